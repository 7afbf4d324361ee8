// A vehicle is drawn where its path puts it (vehicles[]): a boat crossing the view on a straight path is
// found, in frames at two times, at the projection of the path's point for that time (computed here from the
// waypoints and the speed, not by the renderer), whichever time is rendered first.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class VehicleRender : public GpuTest {};

constexpr uint32_t kBoatWidth = 160, kBoatHeight = 90;

// The default bay seen from (0, 3, -10) toward +z, with a boat on `waypoints` at 5 m/s.
scene::Scene boat_scene(const std::string& waypoints, float time_s) {
  const std::vector<std::string> overrides{
      "render.width=" + std::to_string(kBoatWidth),
      "render.height=" + std::to_string(kBoatHeight),
      "time_s=" + std::to_string(time_s),
      "camera.position=[0,3,-10]",
      "camera.look_at=[0,0,20]",
      "camera.fov_deg=55",
      "objects=[]",
      "wakes.enabled=false",  // the hull alone: its wake would move the changed pixels' centre
      R"(vehicles=[{"name":"boat","file":"assets/boat.gltf","path":{"waypoints":)" + waypoints +
          R"(,"speed_mps":5,"loop":false},"body":{"mass_kg":1100,"centre_of_mass_offset":[0,-0.3,0]}}])"};
  return shipped_scene("default", overrides);
}

// The column where a point on the water at (x, 0, z) appears.
double column_of(glm::dvec3 p) {
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 3, -10), glm::dvec3(0, 0, 20), glm::dvec3(0, 1, 0));
  const glm::dmat4 proj = glm::perspective(glm::radians(55.0), double(kBoatWidth) / kBoatHeight, 0.1, 1000.0);
  const glm::dvec4 clip = proj * view * glm::dvec4(p, 1.0);
  return (0.5 * clip.x / clip.w + 0.5) * kBoatWidth;
}

// Mean column of the pixels that differ from `empty`, and how many there are.
std::pair<double, int> changed_columns(const io::Image8& empty, const io::Image8& frame) {
  double sum = 0;
  int count = 0;
  for (uint32_t y = 0; y < frame.height; ++y)
    for (uint32_t x = 0; x < frame.width; ++x) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d += std::abs(int(empty.pixel(x, y)[c]) - int(frame.pixel(x, y)[c]));
      if (d > 24) {
        sum += x + 0.5;
        ++count;
      }
    }
  return {count ? sum / count : -1.0, count};
}

TEST_F(VehicleRender, TheBoatIsDrawnWhereItsPathPutsItAtEachTime) {
  const std::string crossing = "[[-15,20],[15,20]]", far_away = "[[-500,-500],[-520,-500]]";
  auto renderer = render::OceanRenderer::create(ctx(), boat_scene(crossing, 0));
  auto reference = render::OceanRenderer::create(ctx(), boat_scene(far_away, 0));
  ASSERT_TRUE(renderer && reference);
  for (float t : {4.0f, 2.0f}) {  // later first: the earlier frame is simulated again from time 0
    const io::Image8 empty = (*reference)->render(boat_scene(far_away, t));
    const io::Image8 frame = (*renderer)->render(boat_scene(crossing, t));
    const auto [column, count] = changed_columns(empty, frame);
    const double expected = column_of({-15.0 + 5.0 * t, 0.0, 20.0});
    RecordProperty("t" + std::to_string(int(t)), "boat at column " + std::to_string(column) + ", expected " +
                                                     std::to_string(expected) + ", " + std::to_string(count) +
                                                     " pixels");
    EXPECT_GT(count, 40) << "t = " << t;
    EXPECT_NEAR(column, expected, 5.0) << "t = " << t;
  }
}

}  // namespace
}  // namespace lagoon::test
