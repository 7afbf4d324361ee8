// render.shading's classic modes (seed 001 §2.1; shaders/render/ocean_surface_classic.*). On still water
// (model springs with nothing to excite it) every mode draws ambient · sky + diffuse · E_sun cos Z, computed
// here from the frame's light (render/sky_light.h) and the display's gamma; on waves, flat shading is
// piecewise constant (one colour per triangle) where per-pixel Blinn-Phong is not, and Gouraud differs from
// both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "render/camera.h"
#include "render/ocean_renderer.h"
#include "render/sky_light.h"
#include "scene/scene_io.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using ClassicShading = GpuTest;

io::Image8 render_with(vk::Context& ctx, std::vector<std::string> sets, scene::Scene* out = nullptr) {
  sets.insert(sets.end(), {"render.width=320", "render.height=180", "render.tone_map=clamp", "objects=[]",
                           "vehicles=[]", "lights=[]"});
  auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json", sets);
  EXPECT_TRUE(s) << s.error().message;
  if (!s) return {};
  if (out) *out = *s;
  auto renderer = render::OceanRenderer::create(ctx, *s);
  EXPECT_TRUE(renderer) << renderer.error().message;
  return renderer ? (*renderer)->render(*s) : io::Image8{};
}

TEST_F(ClassicShading, StillWaterIsAmbientPlusDiffuseInEveryMode) {
  for (const char* mode : {"blinn-phong", "gouraud", "flat"}) {
    scene::Scene scene;
    const io::Image8 image =
        render_with(ctx(),
                    {std::string("render.shading=") + mode, "ocean.model=springs", "ocean.springs.drops=[]",
                     "render.classic.specular=[0,0,0]", "render.classic.ambient=[0.1,0.2,0.3]",
                     "render.classic.diffuse=[0.3,0.2,0.1]"},
                    &scene);
    ASSERT_EQ(image.width, 320u);
    const render::SkyLight light = render::sky_light(scene.sun);
    const glm::vec3 linear = glm::vec3(0.1f, 0.2f, 0.3f) * light.sky_radiance +
                             glm::vec3(0.3f, 0.2f, 0.1f) * light.sun_irradiance * light.sun_direction.y;
    double worst = 0;
    for (uint32_t y = 120; y < 180; y += 7)  // water in front of the camera
      for (uint32_t x = 5; x < 320; x += 11)
        for (int c = 0; c < 3; ++c) {
          const double expected =
              255.0 * std::pow(std::clamp(double(linear[c]) * scene.render.exposure, 0.0, 1.0),
                               1.0 / scene.render.gamma);
          worst = std::max(worst, std::abs(image.pixel(x, y)[c] - expected));
        }
    RecordProperty(std::string("worst_level_error_") + mode, std::to_string(worst));
    EXPECT_LE(worst, 1.5) << mode << ": expected linear " << linear.x << ", " << linear.y << ", " << linear.z;
  }
}

// The share of horizontally adjacent water pixels with exactly the same colour.
double equal_neighbours(const io::Image8& image) {
  int same = 0, pairs = 0;
  for (uint32_t y = 110; y < image.height; ++y)
    for (uint32_t x = 0; x + 1 < image.width; ++x, ++pairs)
      same += std::equal(image.pixel(x, y), image.pixel(x, y) + 3, image.pixel(x + 1, y));
  return double(same) / pairs;
}

TEST_F(ClassicShading, FlatIsOneColourPerTriangleAndGouraudIsNeither) {
  const io::Image8 phong = render_with(ctx(), {"render.shading=blinn-phong"});
  const io::Image8 gouraud = render_with(ctx(), {"render.shading=gouraud"});
  const io::Image8 flat = render_with(ctx(), {"render.shading=flat"});
  const double phong_same = equal_neighbours(phong), flat_same = equal_neighbours(flat);
  RecordProperty("equal_neighbours_blinn_phong", std::to_string(phong_same));
  RecordProperty("equal_neighbours_flat", std::to_string(flat_same));
  EXPECT_GT(flat_same, phong_same + 0.2);
  double gouraud_vs_phong = 0;
  for (size_t i = 0; i < phong.rgba.size(); ++i)
    gouraud_vs_phong += std::abs(int(phong.rgba[i]) - int(gouraud.rgba[i]));
  EXPECT_GT(gouraud_vs_phong / double(phong.rgba.size()), 0.2) << "gouraud drew the per-pixel picture";
}

// Blinn-Phong's defining term (seed 001 §2.1): the highlight (n·h)^s with h the half vector between the
// directions to the sun and to the viewer. On still water, seen towards the sun's reflection 20° below the
// horizon, every pixel is computed here from its ray's point on the water: ambient 0, a dim diffuse part and
// the specular part with s = 400. The rendered highlight must have the formula's peak position (±2 px),
// width (pixels above half the peak, ±10 %) and levels (±2). Phong's (r·v)^s, or another exponent, fails.
TEST_F(ClassicShading, TheHighlightIsTheHalfVectorsPowerWhereAndAsWideAsTheFormulaSays) {
  constexpr uint32_t kW = 320, kH = 180;
  constexpr float kShininess = 400, kDiffuse = 0.02f;
  std::vector<std::string> sets{
      "render.shading=blinn-phong",     "ocean.model=springs",
      "ocean.springs.drops=[]",         "sun.elevation_deg=20",
      "render.classic.ambient=[0,0,0]", "render.classic.shininess=" + std::to_string(kShininess)};
  scene::Scene first;
  render_with(ctx(), sets, &first);
  const render::SkyLight light = render::sky_light(first.sun);
  const glm::vec3 l = light.sun_direction;
  // The peak at 80 % of white after exposure, so nothing clips.
  const float sun = std::max({light.sun_irradiance.r, light.sun_irradiance.g, light.sun_irradiance.b});
  const float specular = 0.8f / (first.render.exposure * sun * l.y) - kDiffuse;
  const glm::vec3 eye(0, 10, 0), glint_dir = glm::normalize(glm::vec3(l.x, -l.y, l.z));
  const glm::vec3 look = eye + 30.0f * glint_dir;
  sets.insert(sets.end(), {"render.classic.diffuse=[" + std::to_string(kDiffuse) + "," +
                               std::to_string(kDiffuse) + "," + std::to_string(kDiffuse) + "]",
                           "render.classic.specular=[" + std::to_string(specular) + "," +
                               std::to_string(specular) + "," + std::to_string(specular) + "]",
                           "camera.position=[0,10,0]",
                           "camera.look_at=[" + std::to_string(look.x) + "," + std::to_string(look.y) + "," +
                               std::to_string(look.z) + "]"});
  scene::Scene scene;
  const io::Image8 image = render_with(ctx(), sets, &scene);
  ASSERT_EQ(image.width, kW);
  // Where the mesh is drawn: this test found two pixel-sized holes at T-junctions between the clipmap's rings
  // (docs/rendering.md, "No T-junctions"), where the sky showed through; they are counted and skipped.
  auto renderer = render::OceanRenderer::create(ctx(), scene);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const render::OceanRenderer::SurfaceAov drawn_water = (*renderer)->render_surface_aov(scene);
  int holes = 0;

  const render::CameraMatrices cam = render::camera_matrices(scene.camera, float(kW) / float(kH));
  const glm::dmat4 inv = glm::inverse(glm::dmat4(cam.view_proj));
  const glm::dvec3 e(scene.camera.position), n(0, 1, 0), to_sun(l);
  const double top = std::pow(0.8, 1.0 / scene.render.gamma) * 255.0;
  double worst = 0;
  int expected_wide = 0, drawn_wide = 0;
  glm::ivec2 expected_peak(0), drawn_peak(0);
  double expected_best = -1, drawn_best = -1;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      const glm::dvec4 far =
          inv * glm::dvec4((x + 0.5) / (kW / 2.0) - 1.0, 1.0 - (y + 0.5) / (kH / 2.0), 1.0, 1.0);
      const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - e);
      if (dir.y > -0.02) continue;  // the sky, and water too far off to be in the mesh
      if (drawn_water.world_at(x, y).w == 0) {
        ++holes;
        continue;
      }
      const glm::dvec3 p = e + dir * (e.y / -dir.y);
      const glm::dvec3 v = glm::normalize(e - p), h = glm::normalize(to_sun + v);
      const double spec = std::pow(std::max(glm::dot(n, h), 0.0), double(kShininess));
      const double linear = sun * glm::dot(n, to_sun) * (kDiffuse + specular * spec);
      const double level =
          255.0 * std::pow(std::clamp(linear * scene.render.exposure, 0.0, 1.0), 1.0 / scene.render.gamma);
      const double drawn = image.pixel(x, y)[1];  // green: sun_irradiance's largest channel is not assumed
      const double expected_green =
          255.0 * std::pow(std::clamp(double(light.sun_irradiance.g) * glm::dot(n, to_sun) *
                                          (kDiffuse + specular * spec) * scene.render.exposure,
                                      0.0, 1.0),
                           1.0 / scene.render.gamma);
      worst = std::max(worst, std::abs(drawn - expected_green));
      if (level > expected_best) expected_best = level, expected_peak = {int(x), int(y)};
      if (drawn > drawn_best) drawn_best = drawn, drawn_peak = {int(x), int(y)};
      expected_wide += expected_green > 0.5 * top * light.sun_irradiance.g / sun ? 1 : 0;
      drawn_wide += drawn > 0.5 * top * light.sun_irradiance.g / sun ? 1 : 0;
    }
  RecordProperty("worst_level_error", std::to_string(worst));
  RecordProperty("mesh_holes", std::to_string(holes));
  EXPECT_LE(holes, 10);
  RecordProperty("highlight_pixels",
                 std::to_string(drawn_wide) + " drawn, " + std::to_string(expected_wide) + " by the formula");
  ASSERT_GT(expected_wide, 100) << "the highlight is not in the frame";
  EXPECT_LE(std::abs(drawn_peak.x - expected_peak.x), 2) << drawn_peak.x << " vs " << expected_peak.x;
  EXPECT_LE(std::abs(drawn_peak.y - expected_peak.y), 2) << drawn_peak.y << " vs " << expected_peak.y;
  EXPECT_NEAR(double(drawn_wide), double(expected_wide), 0.1 * expected_wide);
  EXPECT_LE(worst, 2.0);
}

}  // namespace
}  // namespace lagoon::test
