// render.shading's classic modes (seed 001 §2.1; shaders/render/ocean_surface_classic.*). On still water
// (model springs with nothing to excite it) every mode draws ambient · sky + diffuse · E_sun cos Z, computed
// here from the frame's light (render/sky_light.h) and the display's gamma; on waves, flat shading is
// piecewise constant (one colour per triangle) where per-pixel Blinn-Phong is not, and Gouraud differs from
// both.
#include <gtest/gtest.h>

#include <cmath>

#include "render/ocean_renderer.h"
#include "render/sky_light.h"
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

}  // namespace
}  // namespace lagoon::test
