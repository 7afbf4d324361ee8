// tools/convert-compass.py (issue 39): a scene written for the old, mirrored compass (azimuths clockwise
// from +z toward +x) names the same directions after conversion. The old convention is written out here,
// independently of engine/core/compass.h: an azimuth a pointed along (sin a, cos a) in (x, z), and an
// object's yaw was a right-handed turn by a about +y.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/compass.h"
#include "render/camera.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/run_process.h"
#include "support/temp_dir.h"
#include "world/object_pose.h"

namespace lagoon::test {
namespace {

constexpr double kDeg = M_PI / 180;

// A scene in the old convention, laid out by hand (a comment, arrays over several lines) so that the test
// can tell the layout is kept.
constexpr const char* kOldScene = R"({
  "comment": "written for the old compass",
  "camera": {"position": [0, 5, 0], "yaw_deg": 37, "pitch_deg": -10},
  "sun": {"elevation_deg": 20, "azimuth_deg": 250},
  "ocean": {
    "spectrum": {"wind_direction_deg": 20},
    "gerstner": {"waves": [{"direction_deg": 0}, {"direction_deg": -30.5}, {"direction_deg": 300}]},
    "springs": {"gusts": [{"direction_deg": 45}]}
  },
  "objects": [
    {"name": "turned", "file": "boat.glb", "rotation_deg": [
      60,
      10,
      5
    ]},
    {"name": "unturned", "file": "buoy.glb"}
  ]
})";

glm::dvec2 old_toward(double degrees) {
  return {std::sin(degrees * kDeg), std::cos(degrees * kDeg)};
}

void expect_near(glm::dvec2 got, glm::dvec2 expected, const std::string& what) {
  EXPECT_LT(glm::distance(got, expected), 1e-6) << what << ": got (" << got.x << ", " << got.y
                                                << "), expected (" << expected.x << ", " << expected.y << ")";
}

TEST(ConvertCompass, EveryAngleNamesTheSameDirectionAndTheLayoutStays) {
  const TempDir dir;
  const std::filesystem::path path = dir / "old.json";
  std::ofstream(path) << kOldScene;
  const ProcessResult r =
      run_process("python3 " + shell_quote(std::string(LAGOON_SOURCE_DIR) + "/tools/convert-compass.py") +
                  " " + shell_quote(path.string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("objects[1] (unturned) has no rotation_deg: it now faces north"), std::string::npos)
      << r.output;
  const std::string text = read_file(path);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'),
            std::count(kOldScene, kOldScene + strlen(kOldScene), '\n'))
      << text;
  EXPECT_NE(text.find("\"comment\": \"written for the old compass\""), std::string::npos) << text;

  const Result<scene::Scene> scene = scene::load_scene(path);
  ASSERT_TRUE(scene.ok()) << scene.error().message << "\n" << text;
  // The sun: the old (cos e sin a, sin e, cos e cos a).
  const glm::dvec3 sun(render::sun_direction(scene->sun));
  expect_near({sun.x, sun.z}, std::cos(20 * kDeg) * old_toward(250), "sun");
  EXPECT_NEAR(sun.y, std::sin(20 * kDeg), 1e-6);
  // The view: yaw 37 and pitch -10 the old way.
  const glm::dvec3 view = glm::normalize(glm::dvec3(scene->camera.look_at - scene->camera.position));
  expect_near({view.x, view.z}, std::cos(10 * kDeg) * old_toward(37), "camera");
  // The wind, the waves and the gust, through the one compass the physics uses.
  const scene::Scene& s = *scene;
  expect_near(compass::toward_deg(s.ocean.spectrum.wind_direction_deg), old_toward(20), "wind");
  const double waves[] = {0, -30.5, 300};
  for (int i = 0; i < 3; ++i)
    expect_near(compass::toward_deg(s.ocean.gerstner.waves[i].direction_deg), old_toward(waves[i]),
                "wave " + std::to_string(i));
  expect_near(compass::toward_deg(s.ocean.springs.gusts[0].direction_deg), old_toward(45), "gust");
  // The turned object: the old Ry(yaw) · Rx(-pitch) · Rz(roll), compared on each axis.
  const glm::dquat old = glm::angleAxis(60 * kDeg, glm::dvec3(0, 1, 0)) *
                         glm::angleAxis(-10 * kDeg, glm::dvec3(1, 0, 0)) *
                         glm::angleAxis(5 * kDeg, glm::dvec3(0, 0, 1));
  const glm::dquat now = world::object_orientation(s.objects[0]);
  for (const glm::dvec3 axis : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)})
    EXPECT_LT(glm::distance(now * axis, old * axis), 1e-6) << "object axis " << axis.x << axis.y << axis.z;
  // The unturned one keeps yaw 0, which now faces north: the script said so above.
  EXPECT_EQ(s.objects[1].rotation_deg, glm::vec3(0.f));
}

TEST(ConvertCompass, AFileThatIsNotJsonIsLeftAsItWasWithAClearMessage) {
  const TempDir dir;
  const std::filesystem::path path = dir / "broken.json";
  std::ofstream(path) << "{\"sun\": {\"azimuth_deg\": 10";
  const ProcessResult r =
      run_process("python3 " + shell_quote(std::string(LAGOON_SOURCE_DIR) + "/tools/convert-compass.py") +
                  " " + shell_quote(path.string()) + " " + shell_quote((dir / "missing.json").string()));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("broken.json: not converted"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missing.json: not converted"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(path), "{\"sun\": {\"azimuth_deg\": 10");
}

}  // namespace
}  // namespace lagoon::test
