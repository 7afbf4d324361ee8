// lagoon compare end to end (apps/lagoon/cmd_compare_models.cpp): the outputs appear together, gerstner's Hs
// is the closed form 4 sqrt(Σ A²/2) of its waves, the FFT ocean's is WaveQuery's (the CPU's own evaluation)
// over the same grid, a one-cascade model tiles at its patch, and a bad model name is a usage error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ocean/wave_query.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;
const std::string kSets =
    " --set render.width=160 --set render.height=90 --rounds 2"
    " --set "
    "'ocean.cascades=[{\"patch_size_m\":200,\"resolution\":64},{\"patch_size_m\":23,\"resolution\":64}]'";

TEST(CompareCli, WritesTheSheetTableAndPlotsWithFiguresFromTheField) {
  TempDir dir;
  const fs::path out = dir / "models";
  auto r = lagoon("compare --scene " + kDefaultScene + " --models fft,gerstner,springs --out " +
                  out.string() + kSets);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"contact_sheet.png", "compare.md", "compare.json", "fft.png", "gerstner.png",
                        "springs.png", "fft_spectrum.png", "gerstner_spectrum.png", "springs_spectrum.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  std::ifstream in(out / "compare.json");
  const nlohmann::json doc = nlohmann::json::parse(in);
  ASSERT_EQ(doc["models"].size(), 3u);
  const nlohmann::json& fft = doc["models"][0];
  const nlohmann::json& gerstner = doc["models"][1];
  const nlohmann::json& springs = doc["models"][2];

  // Gerstner: its lattice waves are orthogonal over the patch; at the rest points each adds A²/2.
  const std::string cascades =
      R"(ocean.cascades=[{"patch_size_m":200,"resolution":64},{"patch_size_m":23,"resolution":64}])";
  const std::vector<std::string> gerstner_sets{"ocean.model=gerstner", cascades}, fft_sets{cascades};
  auto scene = scene::load_scene(kDefaultScene, gerstner_sets);
  ASSERT_TRUE(scene) << scene.error().message;
  double energy = 0;
  for (const ocean::GerstnerWaveSpec& w : scene->ocean.gerstner.waves)
    energy += w.amplitude_m * w.amplitude_m / 2;
  EXPECT_NEAR(gerstner["hs_m"].get<double>(), 4 * std::sqrt(energy), 0.02 * 4 * std::sqrt(energy));
  EXPECT_TRUE(gerstner["spectrum_error"].is_null());

  // FFT: the same statistic over WaveQuery's heights at the rest points of the same grid (no inversion:
  // choppiness 0 would change the sea, so the rest positions are sampled through the height fields directly).
  auto fft_scene = scene::load_scene(kDefaultScene, fft_sets);
  ASSERT_TRUE(fft_scene) << fft_scene.error().message;
  fft_scene->ocean.choppiness = 0;  // heights at fixed points are then the rest points' heights
  ocean::WaveQuery query(fft_scene->ocean);
  std::vector<glm::dvec2> points;
  for (int j = 0; j < 256; ++j)
    for (int i = 0; i < 256; ++i) points.push_back(glm::dvec2(i + 0.5, j + 0.5) * (200.0 / 256));
  double mean = 0, square = 0;
  for (const ocean::WaveSample& s : query.sample(fft_scene->time_s, points))
    mean += s.height, square += s.height * s.height;
  mean /= double(points.size());
  const double hs = 4 * std::sqrt(square / double(points.size()) - mean * mean);
  EXPECT_NEAR(fft["hs_m"].get<double>(), hs, 0.03 * hs);
  EXPECT_TRUE(fft["spectrum_error"].is_number());
  EXPECT_LT(fft["spectrum_error"].get<double>(), 0.5);

  // Springs lives on the first cascade alone: it repeats exactly at its patch.
  EXPECT_NEAR(springs["tiling_correlation"].get<double>(), 1.0, 1e-6);
  EXPECT_GT(springs["step_ms"].get<double>(), 0.0);
}

TEST(CompareCli, AnUnknownModelIsAUsageErrorAndWritesNothing) {
  TempDir dir;
  auto r = lagoon("compare --scene " + kDefaultScene + " --models fft,waves --out " + (dir / "x").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("\"waves\" is no model"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x"));
}

}  // namespace
}  // namespace lagoon::test
