// Shore foam (issue 14, docs/physics.md "Shore foam"): on a beach, foam covers the water where it is too
// shallow for the waves, by the breaking criterion d < H_s / 0.8, fading out over the band's outer half. The
// coverage is read back from two frames (shore foam on and off: frame = mix(off, white, coverage)) and
// compared with the criterion evaluated here from the floor's depth and the sea's significant height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "ocean/slope_statistics.h"
#include "render/camera.h"
#include "render/ocean_renderer.h"
#include "render/seafloor.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class ShoreFoam : public GpuTest {};

constexpr uint32_t kFoamWidth = 160, kFoamHeight = 120;

// A gentle beach, 1:50, falling from the waterline at z = -80 (just out of view: the floor mesh would round
// the slope's kink there) to 4 m at z = 120, seen from 30 m up, almost straight down; a light breeze (few
// whitecaps), linear display.
scene::Scene beach(bool shore_foam) {
  const std::vector<std::string> overrides{
      "render.width=" + std::to_string(kFoamWidth),
      "render.height=" + std::to_string(kFoamHeight),
      "camera.position=[0,30,-62]",
      "camera.look_at=[0,0,-60]",
      "camera.fov_deg=60",
      "seafloor.type=slope",
      "seafloor.near=[0,-80]",
      "seafloor.far=[0,120]",
      "seafloor.depth_near_m=0",
      "seafloor.depth_far_m=4",
      "seafloor.texture=\"\"",
      "seafloor.albedo=[0.3,0.3,0.3]",
      "objects=[]",
      "vehicles=[]",
      "ocean.spectrum.wind_speed_mps=6",
      "render.tone_map=clamp",
      "render.gamma=1",
      "render.exposure=0.6",
      "render.effects.caustics=false",
      std::string("render.effects.shore_foam=") + (shore_foam ? "true" : "false")};
  return shipped_scene("default", overrides);
}

double relative_luminance(const io::Image8& image, uint32_t x, uint32_t y) {
  const uint8_t* p = &image.rgba[(size_t{y} * image.width + x) * 4];
  return (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
}

double smoothstep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

TEST_F(ShoreFoam, TheBandCoversWaterShallowerThanTheWavesBreakIn) {
  const scene::Scene on = beach(true), off = beach(false);
  auto a = render::OceanRenderer::create(ctx(), on);
  auto b = render::OceanRenderer::create(ctx(), off);
  ASSERT_TRUE(a && b);
  const io::Image8 foamy = (*a)->render(on), plain = (*b)->render(off);
  double variance = 0;
  for (const auto& spectrum : (*a)->ocean().spectra()) variance += ocean::height_variance(spectrum);
  const double hs = 4 * std::sqrt(variance), breaking_depth = hs / 0.8;
  ASSERT_GT(hs, 0.3);
  RecordProperty("significant_height_m", std::to_string(hs));

  // Each pixel's water: where its ray meets the mean level, and the floor's depth there.
  const render::CameraMatrices cam =
      render::camera_matrices(on.camera, float(kFoamWidth) / float(kFoamHeight));
  // In double: in float the far plane's point loses metres (the projection spans 0.1 m to 5 km).
  const glm::dmat4 inv = glm::inverse(glm::dmat4(cam.view_proj));
  const glm::dvec3 eye(on.camera.position);
  struct Pixel {
    uint32_t x, y;
    double depth;
  };
  std::vector<Pixel> pixels;
  for (uint32_t y = 0; y < kFoamHeight; y += 2)
    for (uint32_t x = 0; x < kFoamWidth; x += 2) {
      const glm::dvec4 far = inv * glm::dvec4((x + 0.5) / (kFoamWidth / 2.0) - 1.0,
                                              1.0 - (y + 0.5) / (kFoamHeight / 2.0), 1.0, 1.0);
      const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - eye);
      const glm::dvec3 at = eye + dir * (eye.y / -dir.y);
      pixels.push_back({x, y, double(world::slope_depth(on.seafloor, glm::vec2(at.x, at.z)))});
    }
  // The foam's own brightness: where the water is a few centimetres deep the band is solid.
  double white = 0;
  int solid = 0;
  for (const Pixel& p : pixels)
    if (p.depth < 0.1) white += relative_luminance(foamy, p.x, p.y), ++solid;
  ASSERT_GE(solid, 20);
  white /= solid;

  // Coverage and the criterion's, averaged over bins of depth (the foam's brightness varies with the waves'
  // shading, so single pixels scatter).
  constexpr int kBins = 30;  // of 0.05 d_b, to 1.5 d_b
  std::vector<double> got(kBins, 0), want(kBins, 0);
  std::vector<int> count(kBins, 0);
  for (const Pixel& p : pixels) {
    const double base = relative_luminance(plain, p.x, p.y);
    if (white - base < 0.15) continue;  // too close to the foam's brightness to read a coverage
    const int bin = int(p.depth / breaking_depth / 0.05);
    if (bin >= kBins) continue;
    got[bin] += (relative_luminance(foamy, p.x, p.y) - base) / (white - base);
    want[bin] += 1 - smoothstep(0.5, 1.0, p.depth / breaking_depth);
    ++count[bin];
  }
  int bins = 0, fading = 0;
  double worst = 0;
  for (int b = 0; b < kBins; ++b) {
    if (count[b] < 20) continue;
    const double g = got[b] / count[b], w = want[b] / count[b];
    worst = std::max(worst, std::abs(g - w));
    EXPECT_NEAR(g, w, 0.08) << "depth " << (b + 0.5) * 0.05 << " d_b, " << count[b] << " pixels";
    ++bins;
    if (b >= 10 && b < 20) ++fading;
  }
  RecordProperty("bins", bins);
  RecordProperty("worst_coverage_error", std::to_string(worst));
  EXPECT_GE(fading, 8);  // the band's fading half was seen
  EXPECT_GE(bins, 25);   // and water too deep for breaking
}

}  // namespace
}  // namespace lagoon::test
