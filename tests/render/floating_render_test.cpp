// A floating object is drawn where its body rides (objects[].floating): the frame with the buoy floating
// differs from the frame with it fixed at its start, only around the buoy, and the renderer's body is the one
// the frame shows.
#include <gtest/gtest.h>

#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class FloatingRender : public GpuTest {};

scene::Scene buoy_scene(bool floating) {
  const std::vector<std::string> overrides{
      "render.width=160",
      "render.height=90",
      "time_s=6",
      "camera.position=[2,1.5,6]",
      "camera.look_at=[2,0.5,12]",
      std::string(R"(objects=[{"file":"assets/buoy.gltf","position":[2,0,12],"floating":{"enabled":)") +
          (floating ? "true" : "false") + R"(,"density_kg_m3":400,"centre_of_mass_offset":[0,-0.6,0]}}])"};
  return shipped_scene("default", overrides);
}

TEST_F(FloatingRender, TheBuoyIsDrawnWhereItRides) {
  const scene::Scene fixed = buoy_scene(false), floating = buoy_scene(true);
  auto a = render::OceanRenderer::create(ctx(), fixed);
  auto b = render::OceanRenderer::create(ctx(), floating);
  ASSERT_TRUE(a && b);
  const io::Image8 still = (*a)->render(fixed), riding = (*b)->render(floating);
  // The buoy's pixels move; the sea far from it does not change.
  int changed_near = 0, changed_far = 0;
  for (uint32_t y = 0; y < still.height; ++y)
    for (uint32_t x = 0; x < still.width; ++x) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d += std::abs(int(still.pixel(x, y)[c]) - int(riding.pixel(x, y)[c]));
      const bool near = x >= 50 && x < 110;  // the buoy stands in the middle third
      if (d > 24) (near ? changed_near : changed_far)++;
    }
  RecordProperty("changed_pixels", std::to_string(changed_near) + " near the buoy, " +
                                       std::to_string(changed_far) + " elsewhere");
  EXPECT_GT(changed_near, 30);
  EXPECT_LT(changed_far, changed_near / 4);
}

}  // namespace
}  // namespace lagoon::test
