// lagoon bench: usage errors, and the render benchmark's report (figures are not asserted: speed is
// measured, never tested).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

ProcessResult lagoon(const std::string& args) {
  return run_process(shell_quote(LAGOON_BINARY) + " " + args);
}

TEST(BenchCli, UsageErrorsExit2) {
  for (const char* args : {"bench", "bench nope", "bench compute --rounds 0", "bench render --rounds x"})
    EXPECT_EQ(lagoon(args).exit_code, 2) << args;
}

TEST(BenchCli, RenderReportsEveryPassAndTheFrame) {
  TempDir dir;
  const std::string json = (dir / "bench.json").string();
  auto r = lagoon("bench render --rounds 1 --scene " + std::string(LAGOON_SOURCE_DIR) +
                  "/scenes/default.json --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream file(json);
  const auto doc = nlohmann::json::parse(file);
  std::vector<std::string> names;
  for (const auto& b : doc["benchmarks"]) names.push_back(b["name"]);
  for (const char* expected : {"render/pass/refraction", "render/pass/reflection", "render/pass/sky",
                               "render/pass/surface", "render/pass/post", "render/frame"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected << "\n" << r.output;
}

}  // namespace
}  // namespace lagoon::test
