// render.effects.foam (issue 39): "false hides" the whitecaps, the foam the surface shader draws from each
// cascade's foam and the whole sea's Jacobian (common/surface_normal.glsl), not only the shore foam. Read
// back per pixel as the surface pass evaluates it (OceanRenderer::render_surface_aov), on a gale's sea seen
// from above: with the switch on, whitecaps cover part of the water; off, nothing is foam, the normals are
// the same, and the drawn frame is darker.
#include <gtest/gtest.h>

#include <cmath>

#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class WhitecapsSwitch : public GpuTest {};

scene::Scene gale(bool foam) {
  // The open ocean at 18 m/s (Monahan & O'Muircheartaigh: about 7 % whitecap cover), 25 m up, looking down.
  const std::vector<std::string> overrides{"render.width=96",
                                           "render.height=54",
                                           "camera.position=[0,25,0]",
                                           "camera.look_at=[0,0,12]",
                                           "objects=[]",
                                           "vehicles=[]",
                                           std::string("render.effects.foam=") + (foam ? "true" : "false")};
  return shipped_scene("open-ocean", overrides);
}

double mean_luminance(const io::Image8& image) {
  double sum = 0;
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    sum += 0.2126 * image.rgba[i] + 0.7152 * image.rgba[i + 1] + 0.0722 * image.rgba[i + 2];
  return sum / (255.0 * image.width * image.height);
}

TEST_F(WhitecapsSwitch, FoamFalseHidesTheWhitecapsAndChangesNothingElse) {
  const scene::Scene on = gale(true), off = gale(false);
  auto a = render::OceanRenderer::create(ctx(), on);
  auto b = render::OceanRenderer::create(ctx(), off);
  ASSERT_TRUE(a && b);
  const render::OceanRenderer::SurfaceAov foamy = (*a)->render_surface_aov(on);
  const render::OceanRenderer::SurfaceAov plain = (*b)->render_surface_aov(off);
  ASSERT_EQ(foamy.normal_foam.size(), plain.normal_foam.size());
  size_t water = 0, whitecaps = 0, foam_off = 0;
  double normal_difference = 0;
  for (size_t i = 0; i < foamy.normal_foam.size(); ++i) {
    if (foamy.world[i].w == 0) continue;
    ++water;
    whitecaps += foamy.normal_foam[i].w >= 0.5f ? 1 : 0;
    foam_off += plain.normal_foam[i].w > 0.0f ? 1 : 0;
    normal_difference = std::max(normal_difference,
                                 double(glm::length(glm::vec3(foamy.normal_foam[i] - plain.normal_foam[i]))));
  }
  ASSERT_GT(water, foamy.normal_foam.size() / 2);
  const double cover = double(whitecaps) / double(water);
  RecordProperty("whitecap_cover", std::to_string(cover));
  EXPECT_GT(cover, 0.005) << "a gale with the whitecaps on shows none";
  EXPECT_EQ(foam_off, 0u) << "render.effects.foam = false still draws foam";
  EXPECT_LT(normal_difference, 1e-6) << "the switch changes the surface's normals";
  EXPECT_LT(mean_luminance((*b)->render(off)), mean_luminance((*a)->render(on)) - 0.002);
}

}  // namespace
}  // namespace lagoon::test
