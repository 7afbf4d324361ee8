// lagoon compare-images end to end: the figures for hand-checkable pairs, which bound fails, the exit codes
// and the --diff picture. The comparison itself is unit-tested in tests/unit/support/image_compare_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "io/png.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;
using io::Image8;

// 100x50 = 5000 pixels with channels in 30..228, so +-20 never clips.
Image8 base_image() {
  Image8 image{100, 50, std::vector<uint8_t>(100 * 50 * 4)};
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      uint8_t* p = image.pixel(x, y);
      p[0] = uint8_t(30 + x);
      p[1] = uint8_t(30 + 3 * y);
      p[2] = uint8_t(30 + (x + y) % 150);
      p[3] = 255;
    }
  return image;
}

// Every 50th pixel (100 of 5000 = 2%) has its green channel raised by 20 levels.
Image8 two_percent_off_by_20() {
  Image8 image = base_image();
  for (uint32_t i = 0; i < image.width * image.height; i += 50) image.rgba[size_t{i} * 4 + 1] += 20;
  return image;
}

class CompareImagesCli : public ::testing::Test {
 protected:
  static ProcessResult compare(const std::string& args) { return lagoon("compare-images " + args); }
  std::string write(const std::string& name, const Image8& image) {
    const fs::path path = dir_ / name;
    EXPECT_TRUE(io::write_png(path, image)) << path;
    return shell_quote(path.string());
  }
  std::string path(const std::string& name) { return (dir_ / name).string(); }
  static nlohmann::json json_of(const ProcessResult& r) { return nlohmann::json::parse(r.output); }

  TempDir dir_{"lagoon_compare_cli"};
};

TEST_F(CompareImagesCli, IdenticalImagesPassWithInfinitePsnr) {
  const std::string a = write("a.png", base_image()), b = write("b.png", base_image());
  auto r = compare(a + " " + b);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("inf dB"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("100x50"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0 of 5000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("PASS"), std::string::npos) << r.output;

  auto j = compare(a + " " + b + " --json");
  ASSERT_EQ(j.exit_code, 0) << j.output;
  const auto doc = json_of(j);
  EXPECT_TRUE(doc["psnr_db"].is_null()) << doc;
  EXPECT_TRUE(doc["rgb_identical"].get<bool>()) << doc;
  EXPECT_TRUE(doc["passed"].get<bool>()) << doc;
}

TEST_F(CompareImagesCli, TwoPercentOffBy20FailsTheFractionBoundOnly) {
  const std::string a = write("a.png", base_image()), b = write("b.png", two_percent_off_by_20());
  auto r = compare(a + " " + b);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(
      r.output.find("FAIL: fraction of differing pixels 0.02 (100 pixels) is above --max-fraction 0.01"),
      std::string::npos)
      << r.output;
  // MSE = 100 * 20^2 / (5000 * 3) = 2.667, PSNR = 43.87 dB: above the default 35, so that bound holds.
  EXPECT_EQ(r.output.find("FAIL: PSNR"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("43.87 dB"), std::string::npos) << r.output;

  auto j = compare(a + " " + b + " --json");
  EXPECT_EQ(j.exit_code, 1) << j.output;
  const auto doc = json_of(j);
  EXPECT_EQ(doc["differing_pixels"], 100);
  EXPECT_DOUBLE_EQ(doc["differing_fraction"].get<double>(), 0.02);
  EXPECT_EQ(doc["max_channel_difference"], 20);
  EXPECT_EQ(doc["failed"].size(), 1u) << doc;
  EXPECT_FALSE(doc["passed"].get<bool>());

  // A difference of exactly the tolerance does not count, and a looser fraction bound admits 2%.
  EXPECT_EQ(compare(a + " " + b + " --tolerance 20").exit_code, 0);
  EXPECT_EQ(compare(a + " " + b + " --max-fraction 0.02").exit_code, 0);
  EXPECT_EQ(compare(a + " " + b + " --max-fraction 0.0199").exit_code, 1);
}

TEST_F(CompareImagesCli, EveryChannelOffByOneLevelIs48Point13Db) {
  Image8 off = base_image();
  for (size_t i = 0; i < off.rgba.size(); ++i)
    if (i % 4 != 3) off.rgba[i] += 1;  // RGB only: MSE = 1, PSNR = 20 log10(255)
  const std::string a = write("a.png", base_image()), b = write("b.png", off);
  auto r = compare(a + " " + b);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("48.13 dB"), std::string::npos) << r.output;

  const auto doc = json_of(compare(a + " " + b + " --json"));
  EXPECT_NEAR(doc["psnr_db"].get<double>(), 20.0 * std::log10(255.0), 1e-9);
  EXPECT_EQ(doc["differing_pixels"], 0);  // 1 level is within the default tolerance of 8
  EXPECT_EQ(doc["max_channel_difference"], 1);

  auto strict = compare(a + " " + b + " --min-psnr 50");
  EXPECT_EQ(strict.exit_code, 1) << strict.output;
  EXPECT_NE(strict.output.find("FAIL: PSNR 48.13 dB is below --min-psnr 50"), std::string::npos)
      << strict.output;
  EXPECT_EQ(strict.output.find("FAIL: fraction"), std::string::npos) << strict.output;
}

TEST_F(CompareImagesCli, DiffMarksTheChangedPixels) {
  const Image8 changed = two_percent_off_by_20();
  const std::string a = write("a.png", base_image()), b = write("b.png", changed);
  auto r = compare(a + " " + b + " --diff " + shell_quote(path("out/diff.png")));
  EXPECT_EQ(r.exit_code, 1) << r.output;  // the diff is written whether or not the images agree
  auto diff = io::read_png(path("out/diff.png"));
  ASSERT_TRUE(diff) << diff.error().message;
  ASSERT_EQ(diff->width, 100u);
  ASSERT_EQ(diff->height, 50u);
  for (uint32_t i = 0; i < 5000; ++i) {
    const uint8_t* p = &diff->rgba[size_t{i} * 4];
    const bool marked = p[1] == 0 && p[0] == p[2] && p[0] >= 96;  // magenta
    EXPECT_EQ(marked, i % 50 == 0) << "pixel " << i;
  }
  for (const auto& e : fs::directory_iterator(dir_ / "out"))
    EXPECT_EQ(e.path().filename(), "diff.png") << "left behind: " << e.path();
}

TEST_F(CompareImagesCli, MissingOrNonPngFileExits1NamingIt) {
  const std::string a = write("a.png", base_image());
  auto missing = compare(a + " " + shell_quote(path("nowhere.png")));
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(missing.output.find(path("nowhere.png")), std::string::npos) << missing.output;

  { std::ofstream(path("text.png")) << "not an image"; }
  auto not_png = compare(shell_quote(path("text.png")) + " " + a + " --diff " + shell_quote(path("d.png")));
  EXPECT_EQ(not_png.exit_code, 1) << not_png.output;
  EXPECT_NE(not_png.output.find(path("text.png")), std::string::npos) << not_png.output;
  EXPECT_NE(not_png.output.find("not a PNG"), std::string::npos) << not_png.output;
  EXPECT_FALSE(fs::exists(path("d.png")));
}

TEST_F(CompareImagesCli, SizeMismatchExits1WithBothSizes) {
  Image8 wide = base_image();
  wide.width = 50;
  wide.height = 100;  // same bytes, other shape
  const std::string a = write("a.png", base_image()), b = write("b.png", wide);
  auto r = compare(a + " " + b + " --diff " + shell_quote(path("d.png")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  for (const char* part : {"size mismatch", "100x50", "50x100"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
  EXPECT_FALSE(fs::exists(path("d.png"))) << "no diff picture for images that cannot be compared";
}

TEST_F(CompareImagesCli, BadCommandLinesExit2NamingTheProblem) {
  const std::string a = write("a.png", base_image()), b = write("b.png", base_image());
  struct Case {
    std::string args, expected;
  } cases[] = {
      {"", "missing A.png"},
      {a, "missing B.png"},
      {a + " " + b + " --tolerance 300", "--tolerance 300 must be a whole number from 0 to 255"},
      {a + " " + b + " --tolerance 2.5", "--tolerance 2.5"},
      {a + " " + b + " --max-fraction 2", "--max-fraction 2 must be a number from 0 to 1"},
      {a + " " + b + " --min-psnr lots", "--min-psnr lots"},
      {a + " " + b + " --diff " + shell_quote(path("d.txt")),
       "--diff " + path("d.txt") + " must name a .png"},
      {a + " " + b + " --json=yes", "--json takes no value"},
      {a + " " + b + " " + a, "unexpected argument"},
  };
  for (const Case& c : cases) {
    auto r = compare(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(path("d.txt")));
}

}  // namespace
}  // namespace lagoon::test
