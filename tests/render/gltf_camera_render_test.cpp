// camera.gltf in the frame (issue 17, item 3): a glTF camera sees what the same camera written into the scene
// file sees, and its roll turns the picture.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/ocean_renderer.h"
#include "support/edited_scene.h"
#include "support/image_compare.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

class GltfCameraRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_gltf_camera_render"};

  void SetUp() override {
    GpuTest::SetUp();
    // Two cameras 4 m up at z = -30 looking towards +z (turned 180° about y), 40° lens; "rolled" is also
    // turned 90° about its view axis.
    const double yfov = 40.0 * 3.14159265358979 / 180.0, s = 0.70710678118654752;
    const json file = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", json::array({json{{"nodes", {0, 1}}}})},
        {"nodes",
         json::array({json{{"camera", 0}, {"translation", {0, 4, -30}}, {"rotation", {0, 1, 0, 0}}},
                      json{{"camera", 1}, {"translation", {0, 4, -30}}, {"rotation", {s, s, 0, 0}}}})},
        {"cameras", json::array({json{{"name", "level"},
                                      {"type", "perspective"},
                                      {"perspective", {{"yfov", yfov}, {"znear", 0.1}, {"zfar", 5000}}}},
                                 json{{"name", "rolled"},
                                      {"type", "perspective"},
                                      {"perspective", {{"yfov", yfov}, {"znear", 0.1}, {"zfar", 5000}}}}})}};
    std::ofstream(dir_ / "cams.gltf") << file.dump();
  }

  io::Image8 render_with_camera(const json& camera) {
    json scene = shipped_scene_json("open-ocean");
    scene["camera"] = camera;
    scene["render"]["width"] = 96;
    scene["render"]["height"] = 64;
    const scene::Scene s = write_and_load(scene, dir_ / "scene.json");
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return (*renderer)->render(s);
  }
};

// Mean over the rows (along_rows) or the columns of the variance of the pixels' luminance along each.
double variation(const io::Image8& img, bool along_rows) {
  const uint32_t lines = along_rows ? img.height : img.width, length = along_rows ? img.width : img.height;
  double total = 0;
  for (uint32_t line = 0; line < lines; ++line) {
    double sum = 0, sum2 = 0;
    for (uint32_t k = 0; k < length; ++k) {
      const uint8_t* p = along_rows ? img.pixel(k, line) : img.pixel(line, k);
      const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      sum += y, sum2 += y * y;
    }
    total += sum2 / length - (sum / length) * (sum / length);
  }
  return total / lines;
}

TEST_F(GltfCameraRender, SeesWhatTheSameSceneCameraSeesAndItsRollTurnsThePicture) {
  const io::Image8 from_gltf = render_with_camera({{"gltf", {{"file", "cams.gltf"}, {"name", "level"}}}});
  const io::Image8 written = render_with_camera(
      {{"position", {0, 4, -30}}, {"yaw_deg", 180}, {"pitch_deg", 0}, {"fov_deg", 40}, {"near_m", 0.1}});
  EXPECT_LE(max_channel_difference(from_gltf, written), 2) << "the glTF camera and the scene's own differ";
  // Rolled 90°: the horizon runs down the picture. Level, the picture varies along its columns (sky above,
  // sea below) more than along its rows; rolled, the other way round.
  const io::Image8 rolled = render_with_camera({{"gltf", {{"file", "cams.gltf"}, {"name", "rolled"}}}});
  EXPECT_GT(variation(written, false), 1.5 * variation(written, true))
      << variation(written, false) << " " << variation(written, true);
  EXPECT_GT(variation(rolled, true), 1.5 * variation(rolled, false))
      << variation(rolled, true) << " " << variation(rolled, false);
}

}  // namespace
}  // namespace lagoon::test
