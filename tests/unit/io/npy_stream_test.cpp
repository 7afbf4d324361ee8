// NpyStreamWriter: a streamed array is byte for byte the file write_npy writes for the same data, and an
// incomplete one never appears.
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>

#include "io/atomic_file.h"
#include "io/npy.h"
#include "io/npy_stream.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

TEST(NpyStream, StreamedSlabsEqualTheWholeArrayWrittenAtOnce) {
  TempDir dir;
  const std::vector<size_t> shape{3, 2, 5};
  std::vector<float> data(30);
  std::iota(data.begin(), data.end(), -7.5f);
  ASSERT_TRUE(io::write_npy(dir / "whole.npy", data, shape));

  auto w = io::NpyStreamWriter::create(dir / "streamed.npy", shape);
  ASSERT_TRUE(w) << w.error().message;
  EXPECT_EQ(w->slab_size(), 10u);
  for (size_t t = 0; t < 3; ++t) ASSERT_TRUE(w->append(std::span(data).subspan(10 * t, 10)));
  ASSERT_TRUE(w->commit());

  auto whole = io::read_file_bytes(dir / "whole.npy");
  auto streamed = io::read_file_bytes(dir / "streamed.npy");
  ASSERT_TRUE(whole && streamed);
  EXPECT_EQ(*streamed, *whole);
  EXPECT_EQ(io::npy_file_bytes(shape).value(), whole->size());
  auto back = io::read_npy(dir / "streamed.npy");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->shape, shape);
  EXPECT_EQ(back->data, data);
}

TEST(NpyStream, AnIncompleteArrayIsRefusedAndLeavesNoFile) {
  TempDir dir;
  {
    auto w = io::NpyStreamWriter::create(dir / "a.npy", std::vector<size_t>{4, 2});
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->append(std::vector<float>{1, 2}));
    auto r = w->commit();
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("1 of 4 slabs"), std::string::npos) << r.error().message;
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));  // neither the target nor the temporary
}

TEST(NpyStream, SlabsOfTheWrongSizeOrTooManyAreErrors) {
  TempDir dir;
  auto w = io::NpyStreamWriter::create(dir / "a.npy", std::vector<size_t>{1, 3});
  ASSERT_TRUE(w);
  auto wrong = w->append(std::vector<float>{1, 2});
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.error().message.find("holds 3 values, not 2"), std::string::npos) << wrong.error().message;
  ASSERT_TRUE(w->append(std::vector<float>{1, 2, 3}));
  EXPECT_FALSE(w->append(std::vector<float>{1, 2, 3}));
  EXPECT_FALSE(io::NpyStreamWriter::create(dir / "b.npy", std::vector<size_t>{}));
  EXPECT_FALSE(io::NpyStreamWriter::create(dir / "c.npy", std::vector<size_t>{SIZE_MAX / 2, 3}));
}

}  // namespace
}  // namespace lagoon::test
