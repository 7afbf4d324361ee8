// The normal the surface shader shades with, read back per pixel (OceanRenderer::render_surface_aov),
// against WaveQuery's normal at the same world point: an independent CPU evaluation of the same ocean
// (its own FFT, in double), low-passed to the pixel's footprint the way the texture mips low-pass the GPU's.
// Checked in three distance bands, so it holds whatever the device's filtering, and fails when a cascade is
// lost on the way to the shader (issue 10: on lavapipe the 60 m and 8 m cascades contributed nothing).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "dataset/ground_truth.h"
#include "dataset/pinhole.h"
#include "ocean/wave_query.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

glm::dvec2 slope_of(glm::dvec3 n) {
  return {-n.x / n.y, -n.z / n.y};
}

struct BandError {
  double rms = 0;           // rms |s_shader - s_ref| over the band's blocks
  double relative_rms = 0;  // the same / rms |s_ref|
  double reference_rms = 0;
  int blocks = 0;
};

class SurfaceNormal : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    // 12 m above the water, looking 21° down: water from ~14 m to the horizon.
    std::vector<std::string> o{"render.width=320", "render.height=180", "camera.position=[0,12,0]",
                               "camera.look_at=[8,0,30]", "time_s=6"};
    auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json", o);
    ASSERT_TRUE(s) << s.error().message;
    scene_ = *s;
    auto renderer = render::OceanRenderer::create(ctx(), scene_);
    ASSERT_TRUE(renderer) << renderer.error().message;
    aov_ = (*renderer)->render_surface_aov(scene_);
    query_ = std::make_unique<ocean::WaveQuery>(scene_.ocean);
  }

  // The mean slope over a block of pixels: the shader's, averaged over the pixels, and WaveQuery's,
  // averaged over 3×3 points per pixel spread across each pixel's footprint. Averaging over the block makes
  // the comparison independent of how the device filters one pixel: a device without anisotropic filtering
  // blurs a far pixel across the view by its length along the view, so blocks are as many times wider as
  // that footprint is long (rows × columns cover about a square of water).
  static constexpr uint32_t kBlock = 6;
  bool block_slopes(uint32_t x0, uint32_t y0, uint32_t columns, glm::dvec2& shader, glm::dvec2& reference) {
    std::vector<glm::dvec2> points;
    shader = glm::dvec2(0);
    for (uint32_t y = y0; y < y0 + kBlock; ++y)
      for (uint32_t x = x0; x < x0 + columns; ++x) {
        const glm::vec4 n = aov_.normal_at(x, y);
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))
            << "pixel " << x << ", " << y;
        if (aov_.world_at(x, y).w < 0.5 || aov_.world_at(x + 1, y).w < 0.5 || aov_.world_at(x, y + 1).w < 0.5)
          return false;
        shader += slope_of(glm::dvec3(n));
        const glm::dvec3 p(aov_.world_at(x, y));
        const glm::dvec3 ex = glm::dvec3(aov_.world_at(x + 1, y)) - p,
                         ey = glm::dvec3(aov_.world_at(x, y + 1)) - p;
        for (double u : {-1.0 / 3, 0.0, 1.0 / 3})
          for (double v : {-1.0 / 3, 0.0, 1.0 / 3}) {
            const glm::dvec3 q = p + u * ex + v * ey;
            points.emplace_back(q.x, q.z);
          }
      }
    shader /= double(kBlock * columns);
    reference = glm::dvec2(0);
    for (const ocean::WaveSample& w : query_->sample(scene_.time_s, points)) reference += slope_of(w.normal);
    reference /= double(points.size());
    return true;
  }

  // The blocks whose centre lies between near_m and far_m from the camera.
  BandError band(double near_m, double far_m) {
    BandError e;
    double err2 = 0, ref2 = 0;
    const glm::dvec3 eye = scene_.camera.position;
    for (uint32_t y0 = 0; y0 + kBlock < aov_.height; y0 += kBlock) {
      const uint32_t xc = aov_.width / 2, yc = y0 + kBlock / 2;
      const glm::vec4 centre = aov_.world_at(xc, yc);
      const double d = glm::length(glm::dvec3(centre) - eye);
      if (centre.w < 0.5 || d < near_m || d > far_m) continue;
      const double along = glm::length(aov_.world_at(xc, yc + 1) - aov_.world_at(xc, yc)),
                   across = glm::length(aov_.world_at(xc + 1, yc) - aov_.world_at(xc, yc));
      const uint32_t columns = kBlock * uint32_t(std::clamp(std::round(along / across), 1.0, 8.0));
      for (uint32_t x0 = 0; x0 + columns < aov_.width; x0 += columns) {
        glm::dvec2 shader, ref;
        if (!block_slopes(x0, y0, columns, shader, ref)) continue;
        err2 += glm::dot(shader - ref, shader - ref);
        ref2 += glm::dot(ref, ref);
        ++e.blocks;
      }
    }
    e.reference_rms = std::sqrt(ref2 / std::max(e.blocks, 1));
    e.rms = std::sqrt(err2 / std::max(e.blocks, 1));
    e.relative_rms = std::sqrt(err2 / std::max(ref2, 1e-30));
    return e;
  }

  scene::Scene scene_;
  render::OceanRenderer::SurfaceAov aov_;
  std::unique_ptr<ocean::WaveQuery> query_;
};

TEST_F(SurfaceNormal, WaterCoversTheLowerFrameWithUnitNormals) {
  ASSERT_EQ(aov_.width, 320u);
  EXPECT_GT(aov_.world_at(160, 170).w, 0.5f) << "no water below the camera";
  EXPECT_LT(aov_.world_at(160, 2).w, 0.5f) << "water drawn in the sky";
  // Every covered pixel's normal is a unit vector facing up, and its foam a fraction.
  for (uint32_t y = 0; y < aov_.height; ++y)
    for (uint32_t x = 0; x < aov_.width; ++x) {
      if (aov_.world_at(x, y).w < 0.5) continue;
      const glm::vec4 n = aov_.normal_at(x, y);
      ASSERT_NEAR(glm::length(glm::vec3(n)), 1.0f, 1e-3f) << "pixel " << x << ", " << y;
      ASSERT_GT(n.y, 0.0f) << "pixel " << x << ", " << y;
      ASSERT_TRUE(n.w >= 0.0f && n.w <= 1.0f) << "foam " << n.w << " at pixel " << x << ", " << y;
    }
}

// Near, the pixels resolve all three cascades; mid-distance, the 8 m cascade is filtered away: there the
// shader's slopes follow the reference closely, and losing a cascade, or drawing one shifted, leaves most of
// the slope variance unexplained (relative error 0.4 to 1). Far, the footprint filters away nearly every
// slope (reference rms ~0.005): there the bound is absolute, and catches a shader that aliases (samples the
// finest mip) instead of filtering.
TEST_F(SurfaceNormal, ShaderNormalAgreesWithWaveQueryNearMidFar) {
  struct Band {
    const char* name;
    double near_m, far_m, max_relative, max_rms;
  };
  for (const Band b :
       {Band{"near", 13, 20, 0.25, 1.0}, Band{"mid", 30, 50, 0.3, 1.0}, Band{"far", 80, 160, 1e9, 0.01}}) {
    const BandError e = band(b.near_m, b.far_m);
    ASSERT_GT(e.blocks, 10) << b.name;
    std::printf(
        "%s band %g-%g m: rms slope error %.4f, relative %.3f, over %d blocks (reference rms slope %.4f)\n",
        b.name, b.near_m, b.far_m, e.rms, e.relative_rms, e.blocks, e.reference_rms);
    EXPECT_LT(e.relative_rms, b.max_relative) << b.name << " band: relative rms slope error";
    EXPECT_LT(e.rms, b.max_rms) << b.name << " band: rms slope error";
  }
}

// The dataset's normal AOV (lagoon render --aov normal,depth, through dataset/ground_truth.h) over the water:
// the world points rebuilt from its depth along each pixel's ray, its normals, the same bands.
TEST_F(SurfaceNormal, TheDatasetsNormalAovAgreesWithWaveQuery) {
  auto renderer = render::OceanRenderer::create(ctx(), scene_);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const dataset::GroundTruth gt = dataset::ground_truth((*renderer)->render_surface_aov(scene_, true), scene_,
                                                        world::CameraSide::Above, 0.0);
  const dataset::Pinhole cam = dataset::pinhole(scene_.camera, gt.width, gt.height);
  render::OceanRenderer::SurfaceAov rebuilt{.width = gt.width, .height = gt.height};
  for (uint32_t y = 0; y < gt.height; ++y)
    for (uint32_t x = 0; x < gt.width; ++x) {
      const size_t i = size_t{y} * gt.width + x;
      const glm::dvec3 ray = cam.ray(x, y);
      const bool water = gt.water_mask[i] == 1.0f;
      const glm::dvec3 p =
          water ? cam.position + ray * (double(gt.depth[i]) / glm::dot(ray, cam.forward())) : glm::dvec3(0);
      rebuilt.world.push_back(glm::vec4(glm::vec3(p), water ? 1.0f : 0.0f));
      rebuilt.normal_foam.push_back(
          glm::vec4(gt.normal[3 * i], gt.normal[3 * i + 1], gt.normal[3 * i + 2], 0.0f));
    }
  aov_ = std::move(rebuilt);
  for (const auto& [name, near_m, far_m, max_relative] :
       {std::tuple{"near", 13.0, 20.0, 0.25}, std::tuple{"mid", 30.0, 50.0, 0.3}}) {
    const BandError e = band(near_m, far_m);
    ASSERT_GT(e.blocks, 10) << name;
    std::printf("dataset AOV, %s band: relative rms slope error %.3f over %d blocks\n", name, e.relative_rms,
                e.blocks);
    EXPECT_LT(e.relative_rms, max_relative) << name;
  }
}

}  // namespace
}  // namespace lagoon::test
