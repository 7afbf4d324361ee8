// lagoon sky end to end: the sky image of the seed's Fig. 2, its irradiance against the LUTs' E_sky, the
// fitted tone map, and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/npy.h"
#include "io/png.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

TEST(SkyCli, WritesTheFig2SkyWithTheLutsIrradiance) {
  TempDir dir;
  const fs::path out = dir / "sky";
  auto r = lagoon("sky --sun-elevation 30 --width 360 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto png = io::read_png(out / "sky.png");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->width, 360u);
  EXPECT_EQ(png->height, 90u);
  auto rgb = io::read_npy(out / "sky_rgb.npy");
  auto spectral = io::read_npy(out / "sky_spectral.npy");
  ASSERT_TRUE(rgb && spectral);
  EXPECT_EQ(rgb->shape, (std::vector<size_t>{90, 360, 3}));
  EXPECT_EQ(spectral->shape, (std::vector<size_t>{45, 180, 81}));
  std::ifstream meta_file(out / "sky.json");
  const auto meta = nlohmann::json::parse(meta_file);
  const auto& e = meta["irradiance"];
  // E_sky from the image and from the model the LUTs use agree within 1 %, spectrally and in RGB.
  EXPECT_NEAR(e["e_sky_image_w_m2"].get<double>(), e["e_sky_model_w_m2"].get<double>(),
              0.01 * e["e_sky_model_w_m2"].get<double>());
  EXPECT_LT(e["e_sky_worst_wavelength_relative_error"].get<double>(), 0.01);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e["sky_rgb_from_image"][c].get<double>(), e["sky_rgb_of_e_sky"][c].get<double>(),
                0.01 * e["sky_rgb_of_e_sky"][c].get<double>());
  // The sun's column (the middle) is brighter near the sun's row (60° from the zenith) than overhead.
  const size_t w = 360, middle = w / 2;
  auto green = [&](size_t row, size_t col) { return rgb->data[(row * w + col) * 3 + 1]; };
  EXPECT_GT(green(58, middle), 2 * green(2, middle));
  const auto& fit = meta["tone_map_fit"];
  EXPECT_GT(fit["world_adaptation_luminance"].get<double>(), 0.0);
  EXPECT_GT(fit["white_luminance"].get<double>(), 0.0);
  EXPECT_NE(fit["use"].get<std::string>().find("render.tone_map_white="), std::string::npos);
}

TEST(SkyCli, TheFittedToneMapIsAValidSceneSetting) {
  TempDir dir;
  auto r = lagoon("sky --width 128 --out " + (dir / "sky").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream meta_file(dir / "sky" / "sky.json");
  const std::string use = nlohmann::json::parse(meta_file)["tone_map_fit"]["use"];
  r = lagoon("render --scene " + std::string(LAGOON_SOURCE_DIR) +
             "/scenes/default.json --width 64 --height 36 --out " + (dir / "fitted.png").string() + " " +
             use);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "fitted.png"));
}

TEST(SkyCli, BadInputIsNamed) {
  TempDir dir;
  const std::string out = (dir / "sky").string();
  auto r = lagoon("sky");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--out"), std::string::npos) << r.output;
  r = lagoon("sky --width 102 --out " + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("multiple of 4"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  r = lagoon("sky --sun-elevation -5 --out " + out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("sun.elevation_deg"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace lagoon::test
