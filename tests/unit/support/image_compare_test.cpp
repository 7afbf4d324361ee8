#include "support/image_compare.h"

#include <gtest/gtest.h>

#include <stdlib.h>
#include <unistd.h>
#include "support/temp_dir.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;
using io::Image8;

Image8 gradient(uint32_t width, uint32_t height) {
  Image8 image{width, height, std::vector<uint8_t>(size_t{width} * height * 4)};
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<uint8_t>(x * 7 + 20);
      p[1] = static_cast<uint8_t>(y * 5 + 20);
      p[2] = static_cast<uint8_t>((x + y) * 3 + 20);
      p[3] = 255;
    }
  }
  return image;
}

struct TempDir : test::TempDir {
  TempDir() : test::TempDir("lagoon_compare_test") {}
};

// Sets an environment variable for one scope and restores the previous state.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// ---- compare_images ---------------------------------------------------------------------------------------

TEST(CompareImages, IdenticalImagesPassWithInfinitePsnr) {
  const Image8 a = gradient(16, 8);
  const CompareResult r = compare_images(a, a, CompareOptions{});
  EXPECT_TRUE(r.passed);
  EXPECT_FALSE(r.size_mismatch);
  EXPECT_EQ(r.differing_pixels, 0u);
  EXPECT_EQ(r.differing_fraction, 0.0);
  EXPECT_EQ(r.max_channel_difference, 0);
  EXPECT_TRUE(std::isinf(r.psnr_db) && r.psnr_db > 0);
  EXPECT_NE(r.summary().find("inf"), std::string::npos) << r.summary();
}

TEST(CompareImages, SinglePixelBeyondToleranceCountsOnePixel) {
  const Image8 expected = gradient(40, 25);  // 1000 pixels
  Image8 actual = expected;
  actual.pixel(13, 7)[1] += 3;  // tolerance 2: differs
  actual.pixel(2, 2)[0] += 2;   // exactly the tolerance: does not differ
  const CompareResult r = compare_images(actual, expected, CompareOptions{});
  EXPECT_EQ(r.differing_pixels, 1u);
  EXPECT_DOUBLE_EQ(r.differing_fraction, 0.001);
  EXPECT_EQ(r.max_channel_difference, 3);
  EXPECT_TRUE(r.passed);  // 1/1000 <= 0.001
  EXPECT_TRUE(std::isfinite(r.psnr_db));
}

TEST(CompareImages, AlphaDifferenceCountsButDoesNotAffectPsnr) {
  const Image8 expected = gradient(4, 4);
  Image8 actual = expected;
  actual.pixel(1, 1)[3] = 0;
  const CompareResult r = compare_images(actual, expected, CompareOptions{});
  EXPECT_EQ(r.differing_pixels, 1u);
  EXPECT_EQ(r.max_channel_difference, 255);
  EXPECT_TRUE(std::isinf(r.psnr_db));
}

TEST(CompareImages, PsnrOfUniformOffsetMatchesClosedForm) {
  const Image8 expected = gradient(10, 10);
  Image8 actual = expected;
  for (size_t i = 0; i < actual.rgba.size(); ++i) {
    if (i % 4 != 3) actual.rgba[i] += 5;  // MSE over RGB = 25
  }
  const CompareResult r = compare_images(actual, expected, CompareOptions{});
  EXPECT_NEAR(r.psnr_db, 10.0 * std::log10(255.0 * 255.0 / 25.0), 1e-9);
  EXPECT_NEAR(r.psnr_db, 34.151, 1e-3);
  EXPECT_EQ(r.differing_pixels, 100u);
  EXPECT_EQ(r.max_channel_difference, 5);
  EXPECT_FALSE(r.passed);

  CompareOptions loose;
  loose.channel_tolerance = 5;
  EXPECT_TRUE(compare_images(actual, expected, loose).passed);
  loose.min_psnr_db = 35.0;  // the PSNR bound alone now fails it
  const CompareResult bounded = compare_images(actual, expected, loose);
  EXPECT_EQ(bounded.differing_pixels, 0u);
  EXPECT_FALSE(bounded.passed);
  EXPECT_NE(bounded.summary().find("min 35"), std::string::npos) << bounded.summary();
}

TEST(CompareImages, SizeMismatchFails) {
  const CompareResult r = compare_images(gradient(10, 10), gradient(10, 11), CompareOptions{});
  EXPECT_FALSE(r.passed);
  EXPECT_TRUE(r.size_mismatch);
  EXPECT_NE(r.summary().find("10x10"), std::string::npos) << r.summary();
  EXPECT_NE(r.summary().find("10x11"), std::string::npos) << r.summary();

  Image8 broken = gradient(10, 10);
  broken.rgba.pop_back();
  EXPECT_TRUE(compare_images(broken, gradient(10, 10), CompareOptions{}).size_mismatch);
}

TEST(CompareImages, FractionThresholdIsInclusive) {
  const Image8 expected = gradient(10, 10);  // 100 pixels
  CompareOptions options;
  options.max_differing_fraction = 0.02;
  Image8 actual = expected;
  actual.pixel(0, 0)[0] += 50;
  actual.pixel(5, 5)[2] += 50;
  const CompareResult at_limit = compare_images(actual, expected, options);
  EXPECT_EQ(at_limit.differing_pixels, 2u);
  EXPECT_TRUE(at_limit.passed) << at_limit.summary();
  actual.pixel(9, 9)[1] += 50;
  const CompareResult over = compare_images(actual, expected, options);
  EXPECT_EQ(over.differing_pixels, 3u);
  EXPECT_FALSE(over.passed) << over.summary();
}

TEST(CompareImages, SummaryHasNumbersAndTolerances) {
  const Image8 expected = gradient(10, 10);
  Image8 actual = expected;
  actual.pixel(3, 3)[0] += 40;
  CompareOptions options;
  options.channel_tolerance = 7;
  options.max_differing_fraction = 0.0;
  const std::string s = compare_images(actual, expected, options).summary();
  for (const char* part :
       {"FAIL", "1 of 100", "1%", "tolerance 7", "max channel difference 40", "PSNR", "dB"}) {
    EXPECT_NE(s.find(part), std::string::npos) << "missing '" << part << "' in: " << s;
  }
  EXPECT_EQ(s.find('\n'), std::string::npos);
}

// ---- make_diff_image --------------------------------------------------------------------------------------

TEST(DiffImage, MarksDifferingPixelsInMagentaOverDarkGrey) {
  const Image8 expected = gradient(8, 8);
  Image8 actual = expected;
  actual.pixel(2, 3)[0] += 10;   // small difference
  actual.pixel(6, 1)[1] += 200;  // large difference
  actual.pixel(4, 4)[2] += 1;    // within tolerance
  const Image8 diff = make_diff_image(actual, expected, 2);
  ASSERT_EQ(diff.width, 8u);
  ASSERT_EQ(diff.height, 8u);
  const uint8_t* small = diff.pixel(2, 3);
  const uint8_t* large = diff.pixel(6, 1);
  EXPECT_EQ(small[1], 0);
  EXPECT_EQ(small[0], small[2]);
  EXPECT_GT(large[0], small[0]);  // brighter for a larger difference
  for (uint32_t y = 0; y < 8; ++y) {
    for (uint32_t x = 0; x < 8; ++x) {
      const uint8_t* p = diff.pixel(x, y);
      EXPECT_EQ(p[3], 255);
      if ((x == 2 && y == 3) || (x == 6 && y == 1)) continue;
      EXPECT_TRUE(p[0] == p[1] && p[1] == p[2]) << x << "," << y;  // grey
      EXPECT_LT(p[0], small[0]) << "background must be darker than the smallest marked difference";
    }
  }
}

// ---- matches_golden ---------------------------------------------------------------------------------------

TEST(MatchesGolden, UpdateModeWritesGoldenAndSucceeds) {
  TempDir dir;
  ScopedEnv env("LAGOON_UPDATE_GOLDEN", "1");
  const Image8 image = gradient(12, 9);
  const fs::path golden = dir / "goldens/scene.png";
  EXPECT_TRUE(matches_golden(image, golden, CompareOptions{}, dir / "artifacts"));
  Result<Image8> written = io::read_png(golden);
  ASSERT_TRUE(written) << written.error().message;
  EXPECT_EQ(written->rgba, image.rgba);
  EXPECT_FALSE(fs::exists(dir / "artifacts/scene.actual.png"));
}

TEST(MatchesGolden, MissingGoldenFailsAndSaysHowToCreateIt) {
  TempDir dir;
  ScopedEnv env("LAGOON_UPDATE_GOLDEN", nullptr);
  const ::testing::AssertionResult r =
      matches_golden(gradient(4, 4), dir / "scene.png", CompareOptions{}, dir / "artifacts");
  EXPECT_FALSE(r);
  const std::string message = r.message();
  EXPECT_NE(message.find("make update-golden"), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "artifacts/scene.actual.png").string()), std::string::npos) << message;
  EXPECT_TRUE(fs::exists(dir / "artifacts/scene.actual.png"));
  EXPECT_FALSE(fs::exists(dir / "scene.png"));
}

TEST(MatchesGolden, MatchPassesAndLeavesNoArtifacts) {
  TempDir dir;
  ScopedEnv env("LAGOON_UPDATE_GOLDEN", "0");  // anything but "1" compares
  const Image8 image = gradient(6, 6);
  ASSERT_TRUE(io::write_png(dir / "scene.png", image));
  EXPECT_TRUE(matches_golden(image, dir / "scene.png", CompareOptions{}, dir / "artifacts"));
  EXPECT_FALSE(fs::exists(dir / "artifacts/scene.actual.png"));
  EXPECT_FALSE(fs::exists(dir / "artifacts/scene.diff.png"));
}

TEST(MatchesGolden, MismatchWritesActualAndDiffAndReportsThem) {
  TempDir dir;
  ScopedEnv env("LAGOON_UPDATE_GOLDEN", nullptr);
  const Image8 golden = gradient(6, 6);
  ASSERT_TRUE(io::write_png(dir / "scene.png", golden));
  Image8 actual = golden;
  actual.pixel(1, 1)[0] += 100;
  const ::testing::AssertionResult r =
      matches_golden(actual, dir / "scene.png", CompareOptions{}, dir / "out");
  EXPECT_FALSE(r);
  const std::string message = r.message();
  EXPECT_NE(message.find("1 of 36"), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "out/scene.actual.png").string()), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "out/scene.diff.png").string()), std::string::npos) << message;
  Result<Image8> saved = io::read_png(dir / "out/scene.actual.png");
  ASSERT_TRUE(saved);
  EXPECT_EQ(saved->rgba, actual.rgba);
  Result<Image8> diff = io::read_png(dir / "out/scene.diff.png");
  ASSERT_TRUE(diff);
  EXPECT_EQ(diff->rgba, make_diff_image(actual, golden, 2).rgba);

  // Once it matches again, the stale artifacts go away.
  EXPECT_TRUE(matches_golden(golden, dir / "scene.png", CompareOptions{}, dir / "out"));
  EXPECT_FALSE(fs::exists(dir / "out/scene.actual.png"));
  EXPECT_FALSE(fs::exists(dir / "out/scene.diff.png"));
}

TEST(MatchesGolden, SizeMismatchWritesActualButNoDiff) {
  TempDir dir;
  ScopedEnv env("LAGOON_UPDATE_GOLDEN", nullptr);
  ASSERT_TRUE(io::write_png(dir / "scene.png", gradient(6, 6)));
  const ::testing::AssertionResult r =
      matches_golden(gradient(7, 6), dir / "scene.png", CompareOptions{}, dir / "out");
  EXPECT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("size mismatch"), std::string::npos) << r.message();
  EXPECT_TRUE(fs::exists(dir / "out/scene.actual.png"));
  EXPECT_FALSE(fs::exists(dir / "out/scene.diff.png"));
}

TEST(MatchesGolden, CorruptGoldenFailsNamingIt) {
  TempDir dir;
  ScopedEnv env("LAGOON_UPDATE_GOLDEN", nullptr);
  { std::ofstream(dir / "scene.png") << "garbage"; }
  const ::testing::AssertionResult r =
      matches_golden(gradient(2, 2), dir / "scene.png", CompareOptions{}, dir / "out");
  EXPECT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find((dir / "scene.png").string()), std::string::npos) << r.message();
}

}  // namespace
}  // namespace lagoon::test
