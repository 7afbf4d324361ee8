#include "io/json_limits.h"

#include <gtest/gtest.h>

#include <string>

namespace lagoon::io {
namespace {

constexpr JsonLimits kSmall{.max_depth = 3, .max_array_length = 4, .max_string_bytes = 8};

std::string exceeded(const std::string& text) {
  return json_limit_exceeded(text, kSmall).value_or("within the limits");
}

TEST(JsonLimits, DepthUpToTheLimitPassesOneMoreFailsWithItsPosition) {
  EXPECT_EQ(exceeded(R"({"a": [{"b": 1}]})"), "within the limits");
  EXPECT_EQ(exceeded("{\"a\": [\n  {\"b\": [1]}]}"),
            "arrays or objects nested more than 3 deep at line 2, column 9");
}

TEST(JsonLimits, BracketsAndQuotesInsideStringsAreText) {
  EXPECT_EQ(exceeded(R"(["[[[[", "{{{{"])"), "within the limits");
  EXPECT_EQ(exceeded(R"(["a\"[[[["])"), "within the limits");  // an escaped quote does not end the string
}

TEST(JsonLimits, ArrayLengthCountsElementsOfEachArrayOnItsOwn) {
  EXPECT_EQ(exceeded("[1, 2, 3, 4]"), "within the limits");
  EXPECT_EQ(exceeded("[[1, 2, 3, 4], [1, 2, 3, 4], [], {}]"), "within the limits");
  EXPECT_EQ(exceeded("[]"), "within the limits");
  EXPECT_EQ(exceeded(R"(["a", {"k": [1]}, [2], 3, null])"),
            "an array of more than 4 elements at line 1, column 27");
  // Object members are not array elements.
  EXPECT_EQ(exceeded(R"({"a": 1, "b": 2, "c": 3, "d": 4, "e": 5})"), "within the limits");
}

TEST(JsonLimits, StringLengthIsBounded) {
  EXPECT_EQ(exceeded(R"(["1234567"])"), "within the limits");
  EXPECT_EQ(exceeded(R"(["12345678"])"), "within the limits");  // exactly the limit
  EXPECT_EQ(exceeded(R"(["123456789"])"), "a string longer than 8 bytes at line 1, column 11");
  EXPECT_EQ(exceeded(R"({"123456789": 1})"),
            "a string longer than 8 bytes at line 1, column 11");  // keys too
}

TEST(JsonLimits, InvalidJsonIsLeftToTheParser) {
  EXPECT_EQ(exceeded("]]]]]]"), "within the limits");
  EXPECT_EQ(exceeded("[1,,,,,,,,2"), "within the limits");
  EXPECT_EQ(exceeded("\"unterm"), "within the limits");
}

}  // namespace
}  // namespace lagoon::io
