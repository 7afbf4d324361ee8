// camera.gltf (issue 17, item 3): a scene's camera from a glTF camera node, and the errors a user meets.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/temp_dir.h"

namespace lagoon::scene {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void write(const fs::path& path, const json& doc) {
  std::ofstream(path) << doc.dump(2);
}

// A glTF file with no meshes, only cameras: "level" at (2, 3, -10) looking along +z (turned 180° about y),
// "rolled" there too but rolled 90° about its view axis, and an orthographic "plan".
json cameras_file() {
  const double s = 0.70710678;
  return {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", json::array({json{{"nodes", {0, 1, 2}}}})},
      {"nodes", json::array({json{{"name", "level node"},
                                  {"camera", 0},
                                  {"translation", {2, 3, -10}},
                                  {"rotation", {0, 1, 0, 0}}},
                             json{{"camera", 1}, {"translation", {2, 3, -10}}, {"rotation", {s, s, 0, 0}}},
                             json{{"camera", 2}}})},
      {"cameras",
       json::array({json{{"name", "level"},
                         {"type", "perspective"},
                         {"perspective", {{"yfov", 0.5}, {"znear", 0.2}, {"zfar", 900}}}},
                    json{{"name", "rolled"},
                         {"type", "perspective"},
                         {"perspective", {{"yfov", 0.5}, {"znear", 0.2}}}},
                    json{{"name", "plan"},
                         {"type", "orthographic"},
                         {"orthographic", {{"xmag", 5}, {"ymag", 5}, {"znear", 0.1}, {"zfar", 50}}}}})}};
}

class GltfCamera : public ::testing::Test {
 protected:
  test::TempDir dir_{"lagoon_scene_gltf_camera"};
  void SetUp() override { write(dir_ / "cams.gltf", cameras_file()); }
  Result<Scene> load(const json& camera) {
    write(dir_ / "scene.json", {{"camera", camera}});
    return load_scene(dir_ / "scene.json");
  }
};

TEST_F(GltfCamera, TheNamedCameraSetsTheViewAndTheLens) {
  auto scene = load({{"gltf", {{"file", "cams.gltf"}, {"name", "level"}}}});
  ASSERT_TRUE(scene) << scene.error().message;
  const Camera& c = scene->camera;
  EXPECT_NEAR(glm::distance(c.position, glm::vec3(2, 3, -10)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(glm::normalize(c.look_at - c.position), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(c.up, glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(c.fov_deg, 0.5f * 180.0f / 3.14159265f, 1e-4f);
  EXPECT_FLOAT_EQ(c.near_m, 0.2f);
  EXPECT_FLOAT_EQ(c.far_m, 900.0f);
  // The node's name finds it too, and no name takes the first camera.
  auto by_node = load({{"gltf", {{"file", "cams.gltf"}, {"name", "level node"}}}});
  ASSERT_TRUE(by_node) << by_node.error().message;
  EXPECT_EQ(by_node->camera.position, c.position);
  auto first = load({{"gltf", {{"file", "cams.gltf"}}}});
  ASSERT_TRUE(first) << first.error().message;
  EXPECT_EQ(first->camera.look_at, c.look_at);
}

TEST_F(GltfCamera, ARolledCameraKeepsItsRollAndAnInfiniteOneTheScenesFarPlane) {
  auto scene = load({{"gltf", {{"file", "cams.gltf"}, {"name", "rolled"}}}});
  ASSERT_TRUE(scene) << scene.error().message;
  // Rotation (s, s, 0, 0), 180° about (1, 1, 0): the view is +z as for "level", and up is +x, a 90° roll.
  const Camera& c = scene->camera;
  EXPECT_NEAR(glm::distance(glm::normalize(c.look_at - c.position), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(c.up, glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(std::abs(glm::dot(c.up, glm::vec3(0, 1, 0))), 0.0f, 1e-5f) << "rolled 90°: up is horizontal";
  EXPECT_NEAR(glm::dot(c.up, glm::normalize(c.look_at - c.position)), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(c.far_m, Camera{}.far_m);
}

TEST_F(GltfCamera, MistakesAreNamedWithTheirFix) {
  auto missing = load({{"gltf", {{"file", "nowhere.gltf"}}}});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("camera.gltf.file"), std::string::npos) << missing.error().message;
  auto unknown = load({{"gltf", {{"file", "cams.gltf"}, {"name", "stern"}}}});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("'stern' is not a camera"), std::string::npos)
      << unknown.error().message;
  EXPECT_NE(unknown.error().message.find("'level', 'rolled', 'plan'"), std::string::npos)
      << unknown.error().message;
  auto ortho = load({{"gltf", {{"file", "cams.gltf"}, {"name", "plan"}}}});
  ASSERT_FALSE(ortho);
  EXPECT_NE(ortho.error().message.find("orthographic"), std::string::npos) << ortho.error().message;
  auto both = load({{"gltf", {{"file", "cams.gltf"}}}, {"position", {0, 5, 0}}});
  ASSERT_FALSE(both);
  EXPECT_NE(both.error().message.find("camera.position"), std::string::npos) << both.error().message;
  EXPECT_NE(both.error().message.find("left out when gltf is given"), std::string::npos)
      << both.error().message;
}

}  // namespace
}  // namespace lagoon::scene
