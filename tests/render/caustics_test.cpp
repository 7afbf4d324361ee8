// Caustics (issue 13, item 2): the sun's light refracted by the displaced cascades, splatted onto planes at
// four depths. Checked against what physics fixes without computing the pattern: energy is conserved (the
// mean over the window equals a flat sea's), a flat sea focuses nothing, the pattern follows the ocean in
// time and is the same for the same time, and focusing grows with depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/camera.h"
#include "render/frame_uniforms.h"
#include "render/ocean_renderer.h"
#include "render/passes/caustics_pass.h"
#include "scene/scene_io.h"
#include "shared/caustics.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

constexpr size_t kSliceTexels = size_t{LAGOON_CAUSTICS_CELLS} * LAGOON_CAUSTICS_CELLS;

struct SliceStats {
  double mean = 0, stddev = 0, max = 0;
};

SliceStats stats(const std::vector<float>& map, int slice) {
  SliceStats s;
  const float* v = &map[slice * kSliceTexels];
  for (size_t i = 0; i < kSliceTexels; ++i) s.mean += v[i], s.max = std::max(s.max, double(v[i]));
  s.mean /= kSliceTexels;
  for (size_t i = 0; i < kSliceTexels; ++i) s.stddev += (v[i] - s.mean) * (v[i] - s.mean);
  s.stddev = std::sqrt(s.stddev / kSliceTexels);
  return s;
}

class Caustics : public GpuTest {
 protected:
  std::vector<float> caustic_map(std::vector<std::string> overrides) {
    overrides.insert(overrides.begin(), {"render.width=64", "render.height=48"});
    auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/tropical-lagoon.json", overrides);
    EXPECT_TRUE(s) << s.error().message;
    if (!s) return {};
    auto renderer = render::OceanRenderer::create(ctx(), *s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    if (!renderer) return {};
    (*renderer)->render(*s);
    return (*renderer)->caustics().read_map(ctx());
  }
};

TEST_F(Caustics, EnergyIsConservedAtEveryDepth) {
  // A low sun sends the rays far sideways (12.8 m at 15 m depth for 30°): the surface they come from is
  // not the one above the window.
  for (const char* elevation : {"65", "30"}) {
    const std::vector<float> map = caustic_map({std::string("sun.elevation_deg=") + elevation});
    ASSERT_EQ(map.size(), LAGOON_CAUSTICS_SLICES * kSliceTexels);
    for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
      const SliceStats s = stats(map, k);
      RecordProperty(std::string("sun") + elevation + "_slice" + std::to_string(k),
                     std::to_string(s.mean) + " mean, " + std::to_string(s.stddev) + " std, " +
                         std::to_string(s.max) + " max");
      EXPECT_NEAR(s.mean, 1.0, 0.03) << "sun " << elevation << ", slice " << k;
      EXPECT_GT(s.stddev, 0.05) << "sun " << elevation << ", slice " << k << ": no pattern at all";
    }
  }
}

TEST_F(Caustics, AFlatSeaFocusesNothing) {
  // Phillips at a 0.05 m/s breeze (longest wave 2.5e-4 m) with every wave shorter than ~60 m damped away
  // (exp(−k²l²), l = 10 m): a flat sea, WaveQuery gives height 0 and normal (0, 1, 0).
  const std::vector<float> map =
      caustic_map({"ocean.spectrum.type=phillips", "ocean.spectrum.wind_speed_mps=0.05",
                   "ocean.spectrum.small_wave_cutoff_m=10"});
  ASSERT_FALSE(map.empty());
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    const SliceStats s = stats(map, k);
    EXPECT_NEAR(s.mean, 1.0, 0.01) << "slice " << k;
    EXPECT_LT(s.stddev, 0.02) << "slice " << k;
    EXPECT_LT(s.max, 1.05) << "slice " << k;
  }
}

TEST_F(Caustics, ThePatternFollowsTheOceanInTime) {
  const std::vector<float> a = caustic_map({"time_s=4"}), again = caustic_map({"time_s=4"}),
                           later = caustic_map({"time_s=5"});
  ASSERT_EQ(a.size(), later.size());
  EXPECT_EQ(a, again);  // integer accumulation: the same sea gives the same bits
  double difference = 0;
  for (size_t i = 0; i < kSliceTexels; ++i) difference += std::abs(a[i] - later[i]);
  EXPECT_GT(difference / kSliceTexels, 0.05);
}

TEST_F(Caustics, FocusingGrowsWithDepthBeforeTheFocus) {
  // In the linear regime E ≈ 1 − z·(1 − 1/n)·∇²h: the pattern's contrast grows in proportion to depth.
  const std::vector<float> map = caustic_map({});
  ASSERT_FALSE(map.empty());
  const double c1 = stats(map, 0).stddev, c2 = stats(map, 1).stddev;  // 1 m and 2.5 m
  EXPECT_GT(c2, 1.5 * c1) << c1 << " at 1 m, " << c2 << " at 2.5 m";
}

// The map blurred along one axis as common/caustic_blur.glsl should: a Gaussian of standard deviation
// `sigma` cells over 3σ each side, the edge cells standing for what lies beyond, in double.
std::vector<double> gaussian_along(const std::vector<double>& in, int slice, double sigma, bool along_x) {
  const int n = LAGOON_CAUSTICS_CELLS, radius = int(std::ceil(3 * sigma));
  std::vector<double> out(in);
  for (int z = 0; z < n; ++z)
    for (int x = 0; x < n; ++x) {
      double sum = 0, total = 0;
      for (int i = -radius; i <= radius; ++i) {
        const int cx = along_x ? std::clamp(x + i, 0, n - 1) : x,
                  cz = along_x ? z : std::clamp(z + i, 0, n - 1);
        const double w = std::exp(-0.5 * i * i / (sigma * sigma));
        sum += w * in[(size_t(slice) * n + cz) * n + cx], total += w;
      }
      out[(size_t(slice) * n + z) * n + x] = sum / total;
    }
  return out;
}

TEST_F(Caustics, TheBlurIsAGaussianOfTheSharpPatternAsWideAsTheRaysSpread) {
  // The same sea with and without the blur: the same rays, so the blurred map is the sharp one convolved
  // with each slice's Gaussian, computed here in double from the renderer's own spread.
  const std::vector<std::string> sharp_sea{"render.width=64", "render.height=48",
                                           "render.effects.caustics_blur=false"};
  auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/tropical-lagoon.json", sharp_sea);
  ASSERT_TRUE(s) << s.error().message;
  auto renderer = render::OceanRenderer::create(ctx(), *s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  (*renderer)->render(*s);
  const std::vector<float> sharp = (*renderer)->caustics().read_map(ctx());
  s->render.effects.caustics_blur = true;
  (*renderer)->render(*s);
  const std::vector<float> blurred = (*renderer)->caustics().read_map(ctx());
  const render::CausticsWindow w =
      render::caustics_window(*s, render::sun_direction(s->sun), float(s->water.ior),
                              render::ocean_shading((*renderer)->ocean()).caustic_mss);
  ASSERT_GT(w.blur_cells[3], 1.0f) << "the 15 m slice blurred by less than a cell: nothing is checked";
  std::vector<double> expected(sharp.begin(), sharp.end());
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    if (w.blur_cells[k] < 0.05f) continue;  // no blur (common/caustic_blur.glsl)
    expected = gaussian_along(gaussian_along(expected, k, w.blur_cells[k], true), k, w.blur_cells[k], false);
  }
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    double worst = 0;
    for (size_t i = k * kSliceTexels; i < (k + 1) * kSliceTexels; ++i)
      worst = std::max(worst, std::abs(blurred[i] - expected[i]));
    RecordProperty("slice" + std::to_string(k),
                   "sigma " + std::to_string(w.blur_cells[k]) + " cells, worst " + std::to_string(worst) +
                       ", sharp std " + std::to_string(stats(sharp, k).stddev) + ", blurred std " +
                       std::to_string(stats(blurred, k).stddev));
    EXPECT_LT(worst, 1e-4) << "slice " << k << ", sigma " << w.blur_cells[k];
    // The light stays: only the edge cells, standing for what lies beyond the window, are counted twice.
    EXPECT_NEAR(stats(blurred, k).mean, stats(sharp, k).mean, 3e-3) << "the blur moves light in or out";
  }
  EXPECT_LT(stats(blurred, 3).stddev, 0.7 * stats(sharp, 3).stddev);
}

TEST_F(Caustics, ACoarserMapKeepsTheEnergyAndThePattern) {
  // The same sea on the same 32 m window in 128² and 64² cells (a picture drawn small, the demo's dynamic
  // resolution): every plane still conserves the light, and the pattern is the full map's, averaged over the
  // coarser cells, where the blur is wider than a coarse cell (6 and 15 m).
  auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/tropical-lagoon.json",
                             std::vector<std::string>{"render.width=64", "render.height=48"});
  ASSERT_TRUE(s) << s.error().message;
  auto renderer = render::OceanRenderer::create(ctx(), *s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  (*renderer)->render(*s);
  const std::vector<float> full = (*renderer)->caustics().read_map(ctx());
  const int n = LAGOON_CAUSTICS_CELLS;
  for (int coarse : {2, 4}) {
    (*renderer)->set_caustic_cells(uint32_t(n / coarse));
    ASSERT_EQ((*renderer)->caustic_cells(), uint32_t(n / coarse));
    (*renderer)->render(*s);
    const std::vector<float> map = (*renderer)->caustics().read_map(ctx());
    const int m = n / coarse;
    for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
      // The coarse frame's cells are the image's first m x m texels.
      double sum = 0, a2 = 0, b2 = 0, ab = 0, a_sum = 0, b_sum = 0, count = 0;
      for (int z = 0; z < m; ++z)
        for (int x = 0; x < m; ++x) {
          const double a = map[(size_t(k) * n + z) * n + x];
          double b = 0;
          for (int dz = 0; dz < coarse; ++dz)
            for (int dx = 0; dx < coarse; ++dx)
              b += full[(size_t(k) * n + z * coarse + dz) * n + x * coarse + dx];
          b /= coarse * coarse;
          sum += a, a_sum += a, b_sum += b, a2 += a * a, b2 += b * b, ab += a * b, ++count;
        }
      const double mean = sum / count, ma = a_sum / count, mb = b_sum / count;
      const double correlation =
          (ab / count - ma * mb) / std::sqrt((a2 / count - ma * ma) * (b2 / count - mb * mb));
      RecordProperty(
          "cells" + std::to_string(m) + "_slice" + std::to_string(k),
          "mean " + std::to_string(mean) + ", correlation with the full map " + std::to_string(correlation));
      EXPECT_NEAR(mean, 1.0, 0.03) << m << " cells, slice " << k;
      // Measured 0.76-0.99 (the picture below checks the shading's lookup of the coarse cells).
      EXPECT_GT(correlation, k >= 2 ? 0.85 : 0.7) << m << " cells, slice " << k;
    }
  }
  // The floor drawn with the coarse map looks up its own cells: the reef's floor, 8-12 m down where the blur
  // is wider than a coarse cell, is the full map's picture within a little. Each picture from a renderer of
  // its own, so no texel of another frame's map stands in for a lookup in the wrong place.
  auto reef = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/reef-dive.json",
                                std::vector<std::string>{"render.width=160", "render.height=96"});
  ASSERT_TRUE(reef) << reef.error().message;
  auto picture = [&](uint32_t cells, bool caustics) {
    scene::Scene one = *reef;
    one.render.effects.caustics = caustics;
    auto r = render::OceanRenderer::create(ctx(), one);
    EXPECT_TRUE(r) << r.error().message;
    (*r)->set_caustic_cells(cells);
    return (*r)->render(one);
  };
  const io::Image8 fine = picture(uint32_t(n), true), coarse = picture(uint32_t(n / 2), true),
                   off = picture(uint32_t(n), false);
  auto difference = [](const io::Image8& a, const io::Image8& b) {  // mean over the lower half, the floor
    double sum = 0;
    int count = 0;
    for (uint32_t y = a.height / 2; y < a.height; ++y)
      for (uint32_t x = 0; x < a.width; ++x)
        for (int c = 0; c < 3; ++c) sum += std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])), ++count;
    return sum / count;
  };
  const double to_coarse = difference(fine, coarse), to_off = difference(fine, off);
  RecordProperty("picture", "mean difference to the 128-cell map's " + std::to_string(to_coarse) +
                                ", to no caustics " + std::to_string(to_off));
  EXPECT_LT(to_coarse, 0.4 * to_off) << "the coarse map's picture is not the full map's";
  (*renderer)->set_caustic_cells(77);  // rounded down to a power of two of at least 64

  EXPECT_EQ((*renderer)->caustic_cells(), 64u);
  (*renderer)->set_caustic_cells(100000);
  EXPECT_EQ((*renderer)->caustic_cells(), uint32_t(n));
}

// Mean and standard deviation of the luminance over the image's lower half (the floor, in these views).
std::pair<double, double> floor_luminance(const io::Image8& image) {
  double sum = 0, sum2 = 0;
  int n = 0;
  for (uint32_t y = image.height / 2; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      sum += l, sum2 += l * l, ++n;
    }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(sum2 / n - mean * mean, 0.0))};
}

TEST_F(Caustics, VisibleOnTheFloorFromAboveAndFromBelow) {
  // The lagoon's sand about 3.5 m down seen from 3 m above the water, and from 1.5 m down looking along the
  // floor;
  // the floor without its texture, so what varies is the light.
  const std::vector<std::string> above{"camera.position=[0,3,60]", "camera.look_at=[0,-3,66]"},
      below{"camera.position=[0,-1.5,60]", "camera.look_at=[0,-4,70]"};
  for (const auto& view : {above, below}) {
    const bool is_above = view[0] == above[0];
    SCOPED_TRACE(is_above ? "above" : "below");
    std::vector<std::string> on = view;
    on.insert(on.end(), {"render.width=160", "render.height=96", "seafloor.texture=", "render.exposure=0.7"});
    std::vector<std::string> off = on;
    off.push_back("render.effects.caustics=false");
    auto scene_on = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/tropical-lagoon.json", on);
    auto scene_off = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/tropical-lagoon.json", off);
    ASSERT_TRUE(scene_on && scene_off);
    auto renderer = render::OceanRenderer::create(ctx(), *scene_on);
    ASSERT_TRUE(renderer) << renderer.error().message;
    const auto [mean_on, std_on] = floor_luminance((*renderer)->render(*scene_on));
    const auto [mean_off, std_off] = floor_luminance((*renderer)->render(*scene_off));
    RecordProperty(is_above ? "above" : "below",
                   "mean " + std::to_string(mean_on) + " vs " + std::to_string(mean_off) + ", std " +
                       std::to_string(std_on) + " vs " + std::to_string(std_off));
    EXPECT_GT(std_on, 1.5 * std_off + 2.0) << "no caustic pattern on the floor";
    EXPECT_NEAR(mean_on, mean_off, 0.1 * mean_off) << "caustics brighten or darken the floor on average";
  }
}

}  // namespace
}  // namespace lagoon::test
