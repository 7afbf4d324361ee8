// The suspended particles' size on screen (underwater.particles.size_mm): in a frame under clear water, the
// pixels the particles change are the discs a pinhole camera sees of spheres of that diameter, D f / z
// pixels across, at the particles' places (the candidates as the particles' pass places them;
// tests/gpu/render/particles_test.cpp checks those against the scene).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dataset/pinhole.h"
#include "render/ocean_renderer.h"
#include "support/particle_candidates.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

constexpr uint32_t kSizeWidth = 480, kSizeHeight = 270;
using ParticleSize = GpuTest;

TEST_F(ParticleSize, TheyCoverTheDiscsTheirDiameterProjects) {
  for (const double size_mm : {30.0, 60.0}) {
    const std::vector<std::string> common{"render.width=" + std::to_string(kSizeWidth),
                                          "render.height=" + std::to_string(kSizeHeight),
                                          "camera.position=[0,-6,0]",
                                          "camera.look_at=[0,-6,10]",
                                          "camera.fov_deg=60",
                                          "water.type=jerlov-I",
                                          "seafloor.type=none",
                                          "objects=[]",
                                          "vehicles=[]",
                                          "render.effects.caustics=false",
                                          "underwater.particles.density_per_m3=3",
                                          "underwater.particles.albedo=1",
                                          "underwater.particles.size_mm=" + std::to_string(size_mm)};
    std::vector<std::string> off = common;
    off.push_back("render.effects.particles=false");
    const scene::Scene with = shipped_scene("default", common), without = shipped_scene("default", off);
    auto a = render::OceanRenderer::create(ctx(), with);
    auto b = render::OceanRenderer::create(ctx(), without);
    ASSERT_TRUE(a && b);
    const io::Image8 seen = (*a)->render(with), plain = (*b)->render(without);
    // The discs: a sphere of diameter D at depth z along the axis is D f / z pixels across.
    const dataset::Pinhole cam = dataset::pinhole(with.camera, kSizeWidth, kSizeHeight);
    const glm::dmat3 to_camera = glm::transpose(cam.world_from_camera);
    // must: well inside a near particle's disc (its pixels change); may: within any particle's disc or three
    // quarters of a pixel of blending around it. A diameter drawn 1.3 times too large strays 2.5-6 %; 0.7
    // times leaves 14-20 % of the discs unchanged.
    std::vector<char> must(size_t(kSizeWidth) * kSizeHeight, 0), may(must.size(), 0);
    for (const glm::vec4& c : particle_candidates(ctx(), with)) {
      if (c.w == 0.0f) continue;
      const glm::dvec3 q = to_camera * (glm::dvec3(c) - cam.position);
      if (q.z < with.camera.near_m) continue;
      const double u = cam.cx + cam.fx * q.x / q.z, v = cam.cy + cam.fy * q.y / q.z;
      const double r = 0.5 * size_mm * 1e-3 * cam.fx / q.z, reach = std::max(r, 0.75) + 0.75;
      const bool near = q.z < 4.0 && r >= 1.5;
      const int x0 = std::max(int(std::floor(u - reach)), 0),
                x1 = std::min(int(std::ceil(u + reach)), int(kSizeWidth) - 1);
      const int y0 = std::max(int(std::floor(v - reach)), 0),
                y1 = std::min(int(std::ceil(v + reach)), int(kSizeHeight) - 1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double d = std::hypot(x - u, y - v);
          if (d <= reach) may[size_t(y) * kSizeWidth + x] = 1;
          if (near && d <= r - 1.0) must[size_t(y) * kSizeWidth + x] = 1;
        }
    }
    int inside = 0, inside_changed = 0, changed = 0, stray = 0;
    for (uint32_t y = 0; y < kSizeHeight; ++y)
      for (uint32_t x = 0; x < kSizeWidth; ++x) {
        int difference = 0;
        for (int ch = 0; ch < 3; ++ch)
          difference += std::abs(int(seen.pixel(x, y)[ch]) - int(plain.pixel(x, y)[ch]));
        const bool is_changed = difference > 3;
        const size_t i = size_t(y) * kSizeWidth + x;
        if (must[i]) {
          ++inside;
          inside_changed += is_changed ? 1 : 0;
        }
        if (is_changed) {
          ++changed;
          if (!may[i]) ++stray;
        }
      }
    const std::string at = std::to_string(int(size_mm)) + "mm";
    RecordProperty("inside_changed_" + at, std::to_string(inside_changed) + " of " + std::to_string(inside));
    RecordProperty("stray_" + at, std::to_string(stray) + " of " + std::to_string(changed));
    ASSERT_GT(inside, 100) << at << ": the check needs near particles in view";
    EXPECT_GE(inside_changed, 0.95 * inside) << at << ": the discs are drawn smaller than their diameter";
    EXPECT_LE(stray, 0.02 * changed) << at << ": pixels change beyond the discs (drawn larger)";
  }
}

}  // namespace
}  // namespace lagoon::test
