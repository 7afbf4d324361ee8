// KHR_lights_punctual in the frame (issue 17, item 1): an object's glTF lamp lights the water exactly as the
// same lamp written into the scene's lights does, once its candela are put in white units, and
// objects[].lights_from_gltf = false switches it off.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/ocean_renderer.h"
#include "render/sky_light.h"
#include "support/edited_scene.h"
#include "support/image_compare.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

constexpr double kCandela = 4.0e6;  // a bright lamp (in white units ~1000 against a 2° sun's light)

class GltfLightsRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_gltf_lights_render"};

  void SetUp() override {
    GpuTest::SetUp();
    // A model with no geometry, only a lamp 1 m above its origin.
    const json lamp = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_lights_punctual"}},
        {"extensions",
         {{"KHR_lights_punctual",
           {{"lights", json::array({json{{"type", "point"},
                                         {"color", {1.0, 0.8, 0.5}},
                                         {"intensity", kCandela},
                                         {"range", 80.0}}})}}}}},
        {"scene", 0},
        {"scenes", json::array({json{{"nodes", {0}}}})},
        {"nodes", json::array({json{{"translation", {0, 1, 0}},
                                    {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}})}};
    std::ofstream(dir_ / "lamp.gltf") << lamp.dump();
  }

  scene::Scene night(const json& objects, const json& lights) {
    json s = shipped_scene_json("default");
    s["sun"]["elevation_deg"] = -8;
    s["render"]["exposure"] = 6;
    s["render"]["width"] = 160;
    s["render"]["height"] = 90;
    s["seafloor"] = {{"type", "none"}};
    s["camera"] = {{"position", {0, 4, 0}}, {"look_at", {0, 0, 30}}};
    s["objects"] = objects;
    s["lights"] = lights;
    return write_and_load(s, dir_ / "night.json");
  }

  io::Image8 render(const scene::Scene& s) {
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return (*renderer)->render(s);
  }
};

int brightest_red(const io::Image8& img) {
  int best = 0;
  for (uint32_t y = 50; y < 90; ++y)
    for (uint32_t x = 0; x < img.width; ++x) best = std::max(best, int(img.pixel(x, y)[0]));
  return best;
}

TEST_F(GltfLightsRender, AnObjectsLampIsTheSceneLampItStandsFor) {
  const json object = {{"file", "lamp.gltf"}, {"position", {0, 3, 25}}};
  const scene::Scene with_gltf = night(json::array({object}), json::array());
  const double intensity = kCandela / render::reference_illuminance_lux(with_gltf.sun);
  const scene::Scene written = night(
      json::array(),
      json::array({json{
          {"position", {0, 4, 25}}, {"colour", {1, 0.8, 0.5}}, {"intensity", intensity}, {"range_m", 80}}}));
  const io::Image8 a = render(with_gltf), b = render(written);
  EXPECT_LE(max_channel_difference(a, b), 1);
  json off = object;
  off["lights_from_gltf"] = false;
  const io::Image8 dark = render(night(json::array({off}), json::array()));
  EXPECT_GT(brightest_red(a), brightest_red(dark) + 60) << "the glTF lamp does not light the water";
}

TEST_F(GltfLightsRender, AVehiclesLampTravelsWithItAndHasTheSameSwitch) {
  // The lamp model as a submerged vehicle whose origin runs 0.5 m down: its lamp 0.5 m above the water,
  // 25 m ahead, lights the water like the object's; lights_from_gltf = false turns it off.
  auto vehicle = [](bool lights) {
    return json{{"file", "lamp.gltf"},
                {"depth_m", 0.5},
                {"path", {{"waypoints", {{0, 25}, {0, 60}}}, {"speed_mps", 0.1}}},
                {"lights_from_gltf", lights}};
  };
  auto with_vehicles = [&](const json& vehicles) {
    std::ifstream in(dir_ / "night.json");
    json s = json::parse(in);
    s["vehicles"] = vehicles;
    s["wakes"]["enabled"] = false;  // the lamp rides with the vehicle either way; replaying a wake costs 15 s
    return write_and_load(s, dir_ / "night_vehicle.json");
  };
  night(json::array(), json::array());  // writes night.json
  const io::Image8 lit = render(with_vehicles(json::array({vehicle(true)})));
  const io::Image8 dark = render(with_vehicles(json::array({vehicle(false)})));
  EXPECT_GT(brightest_red(lit), brightest_red(dark) + 60)
      << "the vehicle's glTF lamp does not light the water";
}

TEST_F(GltfLightsRender, ASpotLightsOnlyItsConeAndAGltfSpotIsTheSceneSpot) {
  // No sun; the camera 4 m above a calm sea looks down at a white floor 3 m down, where a lamp 2 m above the
  // floor shines straight down: as a point light and as a spot of 15°/20°, whose pool on the floor is
  // 2 tan 20° = 0.73 m in radius. Under the lamp they agree; 1.5 m beside it the point light still lights
  // the floor and the spot does not.
  auto floor_view = [&](const json& objects, const json& lights) {
    json s = shipped_scene_json("default");
    s["camera"] = {{"position", {0, 4, 0}}, {"look_at", {0, -3, 0.01}}};
    s["render"].update(
        {{"width", 64}, {"height", 64}, {"tone_map", "clamp"}, {"gamma", 1}, {"exposure", 0.15}});
    s["seafloor"] = {
        {"type", "slope"}, {"depth_near_m", 3}, {"depth_far_m", 3}, {"albedo", {1, 1, 1}}, {"texture", ""}};
    s["sun"]["intensity"] = 0;
    s["ocean"]["spectrum"]["wind_speed_mps"] = 2;
    s["objects"] = objects;
    s["lights"] = lights;
    return render(write_and_load(s, dir_ / "floor.json"));
  };
  auto lamp = [](double outer_deg, double intensity) {
    json l = {{"position", {0, -1, 0}}, {"colour", {1, 1, 1}}, {"intensity", intensity}, {"range_m", 20}};
    if (outer_deg < 180)
      l.update({{"spot_direction", {0, -1, 0}}, {"spot_inner_deg", 15}, {"spot_outer_deg", outer_deg}});
    return l;
  };
  const io::Image8 point = floor_view(json::array(), json::array({lamp(180, 12)}));
  const io::Image8 spot = floor_view(json::array(), json::array({lamp(20, 12)}));
  // The floor is 7 m from the camera, the view 55° high: 64 px span 7.3 m, so 1.5 m is 13 px.
  auto luminance_at = [](const io::Image8& img, uint32_t x, uint32_t y) {
    double sum = 0;
    for (uint32_t dy = 0; dy < 3; ++dy)
      for (uint32_t dx = 0; dx < 3; ++dx)
        for (int c = 0; c < 3; ++c) sum += img.pixel(x + dx - 1, y + dy - 1)[c];
    return sum / 27;
  };
  const double point_centre = luminance_at(point, 32, 32), spot_centre = luminance_at(spot, 32, 32);
  const double point_beside = luminance_at(point, 45, 32), spot_beside = luminance_at(spot, 45, 32);
  RecordProperty("levels", std::to_string(point_centre) + "/" + std::to_string(spot_centre) +
                               " under the lamp, " + std::to_string(point_beside) + "/" +
                               std::to_string(spot_beside) + " beside");
  EXPECT_NEAR(spot_centre, point_centre, 0.1 * point_centre)
      << "inside the inner cone a spot is a point light";
  EXPECT_GT(point_beside, 3 * spot_beside + 5) << "outside its cone the spot lights nothing";
  // The same spot from a glTF file: a lamp node turned −90° about x shines down its −z, i.e. straight down.
  // With the sun's intensity 0 the reference illuminance is still the 35° sun's (white units do not dim).
  const double candela = 12.0 * render::reference_illuminance_lux(scene::Sun{});
  const double s = 0.70710678118654752, pi = 3.14159265358979;
  const json spot_file = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions",
       {{"KHR_lights_punctual",
         {{"lights",
           json::array(
               {json{{"type", "spot"},
                     {"color", {1.0, 1.0, 1.0}},
                     {"intensity", candela},
                     {"range", 20.0},
                     {"spot", {{"innerConeAngle", 15 * pi / 180}, {"outerConeAngle", 20 * pi / 180}}}}})}}}}},
      {"scene", 0},
      {"scenes", json::array({json{{"nodes", {0}}}})},
      {"nodes", json::array({json{{"rotation", {-s, 0, 0, s}},
                                  {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}})}};
  std::ofstream(dir_ / "spot.gltf") << spot_file.dump();
  const io::Image8 a =
      floor_view(json::array({json{{"file", "spot.gltf"}, {"position", {0, -1, 0}}}}), json::array());
  const io::Image8 b = floor_view(json::array(), json::array({lamp(20, 12)}));
  EXPECT_LE(max_channel_difference(a, b), 1);
  EXPECT_GT(luminance_at(a, 32, 32), 20.0) << "the glTF spot does not light the floor";
}

TEST(ReferenceIlluminance, IsDaylightsOrder) {
  // A clear sky with the sun 60° up gives 80-130 klx on a horizontal surface (the optics model's 380-780 nm
  // band holds nearly all of the light the eye sees).
  const double lux = render::reference_illuminance_lux({.elevation_deg = 60.0f});
  EXPECT_GT(lux, 80e3);
  EXPECT_LT(lux, 130e3);
  EXPECT_LT(render::reference_illuminance_lux({.elevation_deg = 10.0f}), 0.4 * lux);
}

}  // namespace
}  // namespace lagoon::test
