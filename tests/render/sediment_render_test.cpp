// Sediment in the picture (issue 14, docs/physics.md "Sediment"): the clouds an AUV stirs up near the floor,
// drawn by the frame's shaders, against the concentration integrated along each pixel's ray here on the CPU.
// Under the water, black particles (albedo 0) leave exactly the light the clouds transmit: the frame with
// them is the frame without them times exp(-τ), τ the attenuation integrated through the Gaussians by
// quadrature (not the shaders' closed form). From above, the water over the clouds changes colour and the
// rest does not; white particles brighten it and black ones darken it.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "physics/sediment.h"
#include "render/camera.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"
#include "world/vehicle_sediment.h"

namespace lagoon::test {
namespace {

class SedimentRender : public GpuTest {};

constexpr uint32_t kSedimentWidth = 120, kSedimentHeight = 90;
constexpr double kFloorDepth = 8;

// A flat white floor 8 m down; an AUV, shrunk to a speck, holding still 0.3 m above it at (0, 2) for 30 s.
scene::Scene stirred_bay(std::vector<std::string> more) {
  std::vector<std::string> overrides{"render.width=" + std::to_string(kSedimentWidth),
                                     "render.height=" + std::to_string(kSedimentHeight),
                                     "camera.fov_deg=60",
                                     "seafloor.type=slope",
                                     "seafloor.depth_near_m=8",
                                     "seafloor.depth_far_m=8",
                                     "seafloor.albedo=[1,1,1]",
                                     "seafloor.texture=\"\"",
                                     "objects=[]",
                                     "render.tone_map=clamp",
                                     "render.gamma=1",
                                     "render.exposure=1.5",
                                     "render.effects.particles=false",
                                     "sediment.grains_per_g=0",  // the turbidity alone, unless a test asks
                                     "render.effects.caustics=false",
                                     "wakes.enabled=false",
                                     "time_s=30",
                                     R"(vehicles=[{"name":"auv","file":"assets/auv.gltf","scale":0.01,)"
                                     R"("path":{"waypoints":[[0,2],[0,3]],"speed_mps":0},"depth_m":7.7}])"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return shipped_scene("default", overrides);
}

const physics::FloorDepth kFlat = [](glm::dvec2) { return kFloorDepth; };

// The ray through pixel (x, y)'s centre.
glm::dvec3 pixel_ray(const scene::Scene& s, uint32_t x, uint32_t y) {
  const render::CameraMatrices cam =
      render::camera_matrices(s.camera, float(kSedimentWidth) / float(kSedimentHeight));
  const glm::mat4 inv = glm::inverse(cam.view_proj);
  const glm::vec4 far = inv * glm::vec4((x + 0.5f) / (kSedimentWidth / 2.f) - 1.f,
                                        1.f - (y + 0.5f) / (kSedimentHeight / 2.f), 1.f, 1.f);
  return glm::normalize(glm::dvec3(far) / double(far.w) - glm::dvec3(s.camera.position));
}

// ∫ c* C dt along the ray by the midpoint rule.
double optical_depth(const std::vector<physics::SedimentPuff>& puffs, double attenuation, glm::dvec3 origin,
                     glm::dvec3 dir, double length) {
  const int n = 4000;
  const double dt = length / n;
  double tau = 0;
  for (int i = 0; i < n; ++i)
    tau += attenuation * physics::sediment_concentration(puffs, kFlat, origin + dir * ((i + 0.5) * dt)) * dt;
  return tau;
}

double channel(const io::Image8& image, uint32_t x, uint32_t y, int c) {
  return image.rgba[(size_t{y} * image.width + x) * 4 + c] / 255.0;
}

TEST_F(SedimentRender, UnderTheWaterTheCloudsTransmitExpMinusTheirOpticalDepth) {
  const std::vector<std::string> view{"camera.position=[0,-3,-4]", "camera.look_at=[0,-8,4]"};
  std::vector<std::string> black = view, clear = view;
  black.push_back("sediment.colour=[0,0,0]");
  clear.push_back("sediment.enabled=false");
  const scene::Scene with = stirred_bay(black), without = stirred_bay(clear);
  auto clouds = world::VehicleSediment::create(with);
  ASSERT_TRUE(clouds) << clouds.error().message;
  const std::vector<physics::SedimentPuff> puffs = clouds->puffs(with.time_s);
  ASSERT_GE(puffs.size(), 20u);  // one a second, none settled yet
  auto a = render::OceanRenderer::create(ctx(), with);
  auto b = render::OceanRenderer::create(ctx(), without);
  ASSERT_TRUE(a && b);
  const io::Image8 seen = (*a)->render(with), plain = (*b)->render(without);
  const glm::dvec3 eye(with.camera.position);
  int dense = 0;
  double worst = 0;
  for (uint32_t y = 5; y < kSedimentHeight; y += 6)
    for (uint32_t x = 5; x < kSedimentWidth; x += 6) {
      const glm::dvec3 dir = pixel_ray(with, x, y);
      if (dir.y > -0.15) continue;  // the floor within the tables' reach
      const double tau =
          optical_depth(puffs, clouds->attenuation_m2_per_g(), eye, dir, (kFloorDepth + eye.y) / -dir.y);
      if (tau > 0.5) ++dense;
      for (int c = 0; c < 3; ++c) {
        const double want = channel(plain, x, y, c) * std::exp(-tau);
        const double got = channel(seen, x, y, c);
        worst = std::max(worst, std::abs(got - want));
        EXPECT_NEAR(got, want, 2.5 / 255 + 0.03 * want) << "pixel " << x << "," << y << " τ " << tau;
      }
    }
  RecordProperty("dense_pixels", dense);
  RecordProperty("worst_abs", std::to_string(worst));
  EXPECT_GE(dense, 10);  // the check saw the clouds, not only clear water
}

// Seed 002 §3.4's earth-coloured particles: the grains show where the clouds are. Every pixel they change
// looks through a cloud (its optical depth, computed here from the clouds, is not negligible).
TEST_F(SedimentRender, GrainsAreDrawnWhereTheCloudsAre) {
  const std::vector<std::string> view{"camera.position=[0,-3,-4]", "camera.look_at=[0,-8,4]",
                                      "sediment.colour=[1,0.8,0.5]", "sediment.grain_size_mm=30"};
  std::vector<std::string> grains = view, none = view;
  grains.push_back("sediment.grains_per_g=10");
  const scene::Scene with = stirred_bay(grains), without = stirred_bay(none);
  auto clouds = world::VehicleSediment::create(with);
  ASSERT_TRUE(clouds) << clouds.error().message;
  const std::vector<physics::SedimentPuff> puffs = clouds->puffs(with.time_s);
  auto a = render::OceanRenderer::create(ctx(), with);
  auto b = render::OceanRenderer::create(ctx(), without);
  ASSERT_TRUE(a && b);
  const io::Image8 seen = (*a)->render(with), plain = (*b)->render(without);
  const glm::dvec3 eye(with.camera.position);
  int changed = 0, outside = 0;
  for (uint32_t y = 0; y < kSedimentHeight; ++y)
    for (uint32_t x = 0; x < kSedimentWidth; ++x) {
      double difference = 0;
      for (int c = 0; c < 3; ++c) difference += std::abs(channel(seen, x, y, c) - channel(plain, x, y, c));
      if (difference < 6.0 / 255) continue;
      ++changed;
      const glm::dvec3 dir = pixel_ray(with, x, y);
      const double reach = dir.y < -0.05 ? (kFloorDepth + eye.y) / -dir.y : 40.0;
      if (optical_depth(puffs, clouds->attenuation_m2_per_g(), eye, dir, reach) < 0.01) ++outside;
    }
  RecordProperty("changed_pixels", changed);
  RecordProperty("outside_the_clouds", outside);
  EXPECT_GE(changed, 15) << "no grains drawn";
  EXPECT_LE(outside, changed / 20) << "grains where no cloud is";
}

TEST_F(SedimentRender, FromAboveTheWaterOverTheCloudsChangesColourAndNowhereElse) {
  const std::vector<std::string> view{"camera.position=[0,4,-6]", "camera.look_at=[0,-8,3]",
                                      "ocean.spectrum.wind_speed_mps=2"};
  std::vector<std::string> white = view, black = view, clear = view;
  white.push_back("sediment.colour=[1,1,1]");
  black.push_back("sediment.colour=[0,0,0]");
  clear.push_back("sediment.enabled=false");
  const scene::Scene with = stirred_bay(white), dark = stirred_bay(black), without = stirred_bay(clear);
  auto clouds = world::VehicleSediment::create(with);
  ASSERT_TRUE(clouds);
  const std::vector<physics::SedimentPuff> puffs = clouds->puffs(with.time_s);
  auto a = render::OceanRenderer::create(ctx(), with);
  auto b = render::OceanRenderer::create(ctx(), without);
  auto c = render::OceanRenderer::create(ctx(), dark);
  ASSERT_TRUE(a && b && c);
  const io::Image8 seen = (*a)->render(with), plain = (*b)->render(without), shadowed = (*c)->render(dark);
  const glm::dvec3 eye(with.camera.position);
  int over = 0, brighter = 0, darker = 0, away = 0;
  for (uint32_t y = 0; y < kSedimentHeight; y += 2)
    for (uint32_t x = 0; x < kSedimentWidth; x += 2) {
      // The pixel's ray refracted at a flat surface (the breeze is light), to the floor: how close it passes
      // to a cloud's centre.
      const glm::dvec3 dir = pixel_ray(with, x, y);
      if (dir.y > -0.2) continue;
      const glm::dvec3 at = eye + dir * (eye.y / -dir.y);
      const glm::dvec3 down = glm::refract(dir, glm::dvec3(0, 1, 0), 1.0 / double(with.water.ior));
      const double length = kFloorDepth / -down.y;
      double nearest = 1e9;
      for (const physics::SedimentPuff& p : puffs) {
        const double t = std::clamp(glm::dot(p.centre - at, down), 0.0, length);
        nearest = std::min(nearest, glm::length(at + down * t - p.centre));
      }
      double gain = 0, loss = 0;
      for (int c = 0; c < 3; ++c) {
        gain += channel(seen, x, y, c) - channel(plain, x, y, c);
        loss += channel(plain, x, y, c) - channel(shadowed, x, y, c);
      }
      if (nearest < 0.4) {
        ++over;
        brighter += gain >= 4 / 255.0 ? 1 : 0;
        darker += loss >= 4 / 255.0 ? 1 : 0;
      } else if (nearest > 6) {
        ++away;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(channel(seen, x, y, c), channel(plain, x, y, c), 1.5 / 255)
              << "pixel " << x << "," << y;
      }
    }
  ASSERT_GE(over, 5);
  EXPECT_GE(brighter, over * 9 / 10);
  EXPECT_GE(darker, over * 9 / 10);
  EXPECT_GE(away, 100);
}

// Through the scene: the harbour's AUV, 0.4-1.5 m above the sloping floor, stirs it; raised 2 m it stirs
// nothing, and the frame's buffer is empty.
TEST(SedimentScene, TheHarbourAuvStirsTheFloorAndRaisedItDoesNot) {
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  for (const auto& [depth, stirs] : {std::pair{"4.4", true}, std::pair{"2.4", false}}) {
    const std::vector<std::string> overrides{std::string("vehicles[1].depth_m=") + depth};
    auto s = scene::load_scene(harbour, overrides);
    ASSERT_TRUE(s) << s.error().message;
    auto clouds = world::VehicleSediment::create(*s);
    ASSERT_TRUE(clouds) << clouds.error().message;
    ASSERT_FALSE(clouds->empty());
    EXPECT_EQ(clouds->cloud().released_g(60) > 0, stirs) << "depth " << depth;
    gpu::SedimentHeader header;
    std::vector<gpu::SedimentPuffGpu> puffs(LAGOON_MAX_SEDIMENT_PUFFS);
    const uint32_t written = clouds->write(60, &header, puffs.data());
    EXPECT_EQ(written > 0, stirs);
    EXPECT_EQ(uint32_t(header.colour.w), written);
  }
  // Sediment off, or no floor the CPU knows: nothing to stir.
  for (const char* off : {"sediment.enabled=false", "seafloor.type=none"}) {
    auto s = scene::load_scene(harbour, std::vector<std::string>{off});
    ASSERT_TRUE(s);
    auto clouds = world::VehicleSediment::create(*s);
    ASSERT_TRUE(clouds);
    EXPECT_TRUE(clouds->empty()) << off;
  }
}

}  // namespace
}  // namespace lagoon::test
