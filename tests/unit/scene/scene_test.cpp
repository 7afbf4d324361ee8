#include "scene/scene.h"
#include "scene/scene_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <unistd.h>
#include <cstdlib>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef LAGOON_SOURCE_DIR
#define LAGOON_SOURCE_DIR "."  // running by hand from the repository root
#endif

namespace lagoon::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const std::string kSource = "scenes/x.json";

// Fails with the whole message when a part is missing, so a failing test shows what the user would see.
testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "missing \"" << part << "\" in:\n" << text;
}

// The error message of a parse that must fail.
std::string ErrorOf(const Result<Scene>& result) {
  EXPECT_FALSE(result.ok()) << "expected the scene to be rejected";
  return result.ok() ? std::string() : result.error().message;
}

std::string ParseError(const std::string& text) {
  return ErrorOf(parse_scene(json::parse(text), kSource));
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each test gets its own directory for scene files.
class SceneFileTest : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("lagoon_scene_test_" + std::to_string(getpid()) + "_" + std::string(info->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path Write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  fs::path dir_;
};

// ---- Reading ----

TEST(SceneParse, EmptyObjectGivesDefaults) {
  Result<Scene> scene = parse_scene(json::object(), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->source, fs::path());
  EXPECT_EQ(scene->camera.position, glm::vec3(0.f, 6.f, -40.f));
  EXPECT_EQ(scene->camera.look_at, glm::vec3(0.f));
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 55.f);
  EXPECT_FLOAT_EQ(scene->camera.near_m, 0.1f);
  EXPECT_FLOAT_EQ(scene->camera.far_m, 5000.f);
  EXPECT_FLOAT_EQ(scene->sun.elevation_deg, 35.f);
  EXPECT_FLOAT_EQ(scene->sun.azimuth_deg, 330.f);
  EXPECT_FLOAT_EQ(scene->sun.intensity, 1.f);
  EXPECT_EQ(scene->render.width, 1280u);
  EXPECT_EQ(scene->render.height, 720u);
  EXPECT_FLOAT_EQ(scene->render.exposure, 1.f);
  EXPECT_FLOAT_EQ(scene->render.gamma, 2.2f);
  EXPECT_FLOAT_EQ(scene->time_s, 0.f);
}

// Model springs steps its grid from rest to the frame's time; a time beyond what one call may step to is
// refused at load, naming time_s and the limit, while the FFT ocean takes the same time.
TEST(SceneParse, SpringsRefuseATimeTheirGridCannotReach) {
  Result<Scene> late =
      parse_scene(json::parse(R"({"ocean": {"model": "springs"}, "time_s": 60000})"), kSource);
  ASSERT_FALSE(late.ok());
  EXPECT_NE(late.error().message.find("time_s"), std::string::npos) << late.error().message;
  EXPECT_NE(late.error().message.find("52428.8"), std::string::npos) << late.error().message;
  EXPECT_TRUE(parse_scene(json::parse(R"({"ocean": {"model": "springs"}, "time_s": 50000})"), kSource).ok());
  EXPECT_TRUE(parse_scene(json::parse(R"({"time_s": 60000})"), kSource).ok());
}

// A still frame replays history_s / step_s steps of the wake layer: a combination over 100 million
// cell-steps (1.2 times the defaults) is refused with its cost and the fix; the defaults and a borderline one
// load, and a disabled layer costs nothing (issue 36: 1024 / 1024 took 90 s for a 96 x 54 frame).
TEST(SceneParse, WakeSettingsThatWouldTakeMinutesAreRefusedWithTheirCost) {
  const std::string big = ParseError(R"({"wakes": {"resolution": 1024, "bodies_resolution": 1024}})");
  EXPECT_TRUE(Contains(big, "wakes.step_s: must be history_s / step_s x (resolution² + bodies_resolution²)"));
  EXPECT_TRUE(Contains(big, "300 steps of 2097152 cells is 629 million cell-steps a frame"));
  EXPECT_TRUE(Contains(big, "raise step_s to 0.63, shorten history_s to 4"));
  const std::string fine_step = ParseError(R"({"wakes": {"step_s": 0.005}})");
  EXPECT_TRUE(Contains(fine_step, "6000 steps of 278528 cells"));
  EXPECT_TRUE(parse_scene(json::parse("{}"), kSource).ok());
  // 80 steps of 1024² + 128² = 85 million: allowed.
  EXPECT_TRUE(parse_scene(json::parse(R"({"wakes": {"resolution": 1024, "history_s": 8}})"), kSource).ok());
  EXPECT_TRUE(parse_scene(json::parse(R"({"wakes": {"enabled": false, "step_s": 0.005}})"), kSource).ok());
  EXPECT_TRUE(parse_scene(json::parse(R"({"wakes": {"felt_by_bodies": false, "resolution": 1024,
                                                    "bodies_resolution": 1024, "history_s": 9}})"),
                          kSource)
                  .ok());
}

// A frame replays the floating bodies' physics from bodies_start_s (issue 36: the harbour at 600 s took
// minutes): over 300 hull-seconds is refused with its cost and both fixes; a late start, a time within the
// bound, or no floating hulls load.
TEST(SceneParse, ALateFrameWithFloatingBodiesNeedsALateStart) {
  const std::string buoy = R"({"file": "b.gltf", "floating": {"enabled": true}})";
  const std::string boat = R"({"file": "v.gltf", "path": {"waypoints": [[0, 0], [10, 0]]}})";
  const std::string auv = R"({"file": "v.gltf", "depth_m": 3, "path": {"waypoints": [[0, 0], [10, 0]]}})";
  const std::string three =
      R"("objects": [)" + buoy + "," + buoy + R"(], "vehicles": [)" + boat + "," + auv + "]";
  const std::string late = ParseError("{" + three + R"(, "time_s": 600})");
  EXPECT_TRUE(
      Contains(late, "time_s: must be (time_s - bodies_start_s) x floating hulls <= 300 hull-seconds"))
      << late;
  EXPECT_TRUE(Contains(late, "600 s of 3 hulls is 1800 hull-seconds")) << late;
  EXPECT_TRUE(Contains(late, "set bodies_start_s to 500 or later")) << late;
  EXPECT_TRUE(Contains(late, "or choose time_s <= 100")) << late;
  EXPECT_TRUE(
      parse_scene(json::parse("{" + three + R"(, "time_s": 600, "bodies_start_s": 500})"), kSource).ok());
  EXPECT_TRUE(parse_scene(json::parse("{" + three + R"(, "time_s": 100})"), kSource).ok());
  EXPECT_FALSE(parse_scene(json::parse("{" + three + R"(, "time_s": 101})"), kSource).ok());
  // The AUV is submerged: it follows its path and costs nothing; without floating hulls any time loads.
  EXPECT_TRUE(parse_scene(json::parse(R"({"vehicles": [)" + auv + R"(], "time_s": 86400})"), kSource).ok());
}

TEST(SceneParse, EmptyBlocksGiveDefaults) {
  Result<Scene> scene = parse_scene(json::parse(R"({"camera": {}, "sun": {}, "render": {}})"), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 55.f);
}

TEST(SceneParse, ReadsEveryField) {
  Result<Scene> scene = parse_scene(json::parse(R"({
    "comment": "all fields",
    "camera": {"position": [1, 2, 3], "look_at": [4, 5, 6.5], "fov_deg": 40, "near_m": 0.5, "far_m": 900,
               "comment": "c"},
    "sun": {"elevation_deg": -10, "azimuth_deg": 360, "intensity": 2.5},
    "render": {"width": 64, "height": 48.0, "exposure": 0.5, "gamma": 1.8},
    "time_s": 12.5
  })"),
                                    kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->camera.position, glm::vec3(1.f, 2.f, 3.f));
  EXPECT_EQ(scene->camera.look_at, glm::vec3(4.f, 5.f, 6.5f));
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 40.f);
  EXPECT_FLOAT_EQ(scene->camera.near_m, 0.5f);
  EXPECT_FLOAT_EQ(scene->camera.far_m, 900.f);
  EXPECT_FLOAT_EQ(scene->sun.elevation_deg, -10.f);
  EXPECT_FLOAT_EQ(scene->sun.azimuth_deg, 360.f);
  EXPECT_FLOAT_EQ(scene->sun.intensity, 2.5f);
  EXPECT_EQ(scene->render.width, 64u);
  EXPECT_EQ(scene->render.height, 48u);  // 48.0 is a whole number
  EXPECT_FLOAT_EQ(scene->render.exposure, 0.5f);
  EXPECT_FLOAT_EQ(scene->render.gamma, 1.8f);
  EXPECT_FLOAT_EQ(scene->time_s, 12.5f);
}

// ---- Ocean block ----

using ocean::SpectrumType;
using ocean::Spreading;

TEST(SceneOcean, AbsentBlockGivesDefaults) {
  Result<Scene> scene = parse_scene(json::object(), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const ocean::OceanParams& o = scene->ocean;
  EXPECT_EQ(o.seed, 1u);
  EXPECT_EQ(o.depth_m, 1000.0);
  EXPECT_EQ(o.choppiness, 1.0);
  EXPECT_EQ(o.loop_period_s, 0.0);
  EXPECT_EQ(o.spectrum.type, SpectrumType::Jonswap);
  EXPECT_EQ(o.spectrum.wind_speed_mps, 10.0);
  EXPECT_EQ(o.spectrum.wind_direction_deg, 180.0);
  EXPECT_EQ(o.spectrum.fetch_km, 100.0);
  EXPECT_EQ(o.spectrum.gamma, 3.3);
  EXPECT_EQ(o.spectrum.spreading, Spreading::Cos2s);
  EXPECT_EQ(o.spectrum.swell, 0.0);
  EXPECT_EQ(o.spectrum.small_wave_cutoff_m, 0.0);
  ASSERT_EQ(o.cascades.size(), 3u);
  EXPECT_EQ(o.cascades[0].patch_size_m, 1000.0);
  EXPECT_EQ(o.cascades[1].patch_size_m, 100.0);
  EXPECT_EQ(o.cascades[2].patch_size_m, 10.0);
  for (const ocean::CascadeParams& c : o.cascades) EXPECT_EQ(c.resolution, 256u);
  EXPECT_EQ(o.foam.threshold, 0.5);
  EXPECT_EQ(o.foam.decay_per_s, 0.3);
}

TEST(SceneOcean, EmptyBlocksGiveDefaults) {
  Result<Scene> scene =
      parse_scene(json::parse(R"({"ocean": {"spectrum": {}, "foam": {}, "comment": "calm"}})"), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->ocean.spectrum.type, SpectrumType::Jonswap);
  EXPECT_EQ(scene->ocean.cascades.size(), 3u);
  EXPECT_EQ(scene->ocean.foam.threshold, 0.5);
}

TEST(SceneOcean, ReadsEveryField) {
  Result<Scene> scene = parse_scene(json::parse(R"({"ocean": {
    "seed": 4294967295, "depth_m": 11000, "choppiness": 1.5, "loop_period_s": 60,
    "spectrum": {"type": "tma", "wind_speed_mps": 17.5, "wind_direction_deg": 270, "fetch_km": 0.5,
                 "gamma": 1, "spreading": "donelan-banner", "swell": 0.25, "small_wave_cutoff_m": 0.01},
    "cascades": [{"patch_size_m": 2000, "resolution": 1024}, {"patch_size_m": 250, "resolution": 512.0},
                 {"patch_size_m": 17, "resolution": 128}, {"patch_size_m": 0.75, "resolution": 64,
                 "comment": "ripples"}],
    "foam": {"threshold": -0.25, "decay_per_s": 3}
  }})"),
                                    kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const ocean::OceanParams& o = scene->ocean;
  EXPECT_EQ(o.seed, 4294967295u);
  EXPECT_EQ(o.depth_m, 11000.0);
  EXPECT_EQ(o.choppiness, 1.5);
  EXPECT_EQ(o.loop_period_s, 60.0);
  EXPECT_EQ(o.spectrum.type, SpectrumType::Tma);
  EXPECT_EQ(o.spectrum.wind_speed_mps, 17.5);
  EXPECT_EQ(o.spectrum.wind_direction_deg, 270.0);
  EXPECT_EQ(o.spectrum.fetch_km, 0.5);
  EXPECT_EQ(o.spectrum.gamma, 1.0);
  EXPECT_EQ(o.spectrum.spreading, Spreading::DonelanBanner);
  EXPECT_EQ(o.spectrum.swell, 0.25);
  EXPECT_EQ(o.spectrum.small_wave_cutoff_m, 0.01);  // stored as double: no float rounding
  ASSERT_EQ(o.cascades.size(), 4u);
  EXPECT_EQ(o.cascades[0].patch_size_m, 2000.0);
  EXPECT_EQ(o.cascades[0].resolution, 1024u);
  EXPECT_EQ(o.cascades[1].patch_size_m, 250.0);
  EXPECT_EQ(o.cascades[1].resolution, 512u);
  EXPECT_EQ(o.cascades[2].patch_size_m, 17.0);
  EXPECT_EQ(o.cascades[2].resolution, 128u);
  EXPECT_EQ(o.cascades[3].patch_size_m, 0.75);
  EXPECT_EQ(o.cascades[3].resolution, 64u);
  EXPECT_EQ(o.foam.threshold, -0.25);
  EXPECT_EQ(o.foam.decay_per_s, 3.0);
}

TEST(SceneOcean, EveryEnumNameIsAccepted) {
  for (SpectrumType type : {SpectrumType::Phillips, SpectrumType::PiersonMoskowitz, SpectrumType::Jonswap,
                            SpectrumType::Tma, SpectrumType::JonswapEq15, SpectrumType::PhillipsEq18}) {
    const json document = {{"ocean", {{"spectrum", {{"type", ocean::to_string(type)}}}}}};
    Result<Scene> scene = parse_scene(document, kSource);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->ocean.spectrum.type, type);
  }
  for (Spreading spreading : {Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner}) {
    const json document = {{"ocean", {{"spectrum", {{"spreading", ocean::to_string(spreading)}}}}}};
    Result<Scene> scene = parse_scene(document, kSource);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->ocean.spectrum.spreading, spreading);
  }
}

TEST(SceneOcean, CascadesReplaceTheDefaultListAndElementsStartFromDefaults) {
  Result<Scene> scene = parse_scene(json::parse(R"({"ocean": {"cascades": [{"resolution": 64}]}})"), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  ASSERT_EQ(scene->ocean.cascades.size(), 1u);
  EXPECT_EQ(scene->ocean.cascades[0].patch_size_m, 1000.0);
  EXPECT_EQ(scene->ocean.cascades[0].resolution, 64u);
}

TEST(SceneOcean, BadEnumNameSuggestsClosest) {
  std::string message = ParseError(R"({"ocean": {"spectrum": {"type": "jonswop"}}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: ocean.spectrum.type: string \"jonswop\" is not one of the "
                       "allowed names; did you mean 'jonswap'? allowed: \"jonswap\", \"pm\", "
                       "\"phillips\", \"tma\", \"jonswap-eq15\", \"phillips-eq18\" (default \"jonswap\")"));
  EXPECT_TRUE(Contains(ParseError(R"({"ocean": {"spectrum": {"type": "PM"}}})"), "did you mean 'pm'?"));
  message = ParseError(R"({"ocean": {"spectrum": {"spreading": "donelan_banner"}}})");
  EXPECT_TRUE(Contains(message, "ocean.spectrum.spreading: string \"donelan_banner\" is not one of"));
  EXPECT_TRUE(Contains(message,
                       "did you mean 'donelan-banner'? allowed: \"cos2\", \"cos2s\", "
                       "\"donelan-banner\" (default \"cos2s\")"));
  message = ParseError(R"({"ocean": {"spectrum": {"type": "pierson-moskowitz"}}})");
  EXPECT_FALSE(Contains(message, "did you mean"));
  EXPECT_TRUE(Contains(message, "allowed: \"jonswap\", \"pm\""));
}

TEST(SceneOcean, EnumNotAString) {
  EXPECT_TRUE(Contains(ParseError(R"({"ocean": {"spectrum": {"type": 2}}})"),
                       "ocean.spectrum.type: expected a string, got 2; allowed: \"jonswap\""));
}

TEST(SceneOcean, ResolutionMustBeAPowerOfTwoInRange) {
  for (const char* bad : {"100", "2048", "32", "0", "-256", "4096"}) {
    const std::string message =
        ParseError(std::string(R"({"ocean": {"cascades": [{"resolution": )") + bad + "}]}}");
    EXPECT_TRUE(Contains(message, "scenes/x.json: ocean.cascades[0].resolution: " + std::string(bad) +
                                      " is not a power of two between 64 and 1024; allowed: 64, 128, 256, "
                                      "512, 1024 (default 256)"));
  }
  EXPECT_TRUE(Contains(ParseError(R"({"ocean": {"cascades": [{"resolution": 128.5}]}})"),
                       "ocean.cascades[0].resolution: 128.5 is not a whole number"));
  EXPECT_TRUE(Contains(ParseError(R"({"ocean": {"cascades": [{"resolution": "256"}]}})"),
                       "ocean.cascades[0].resolution: expected an integer, got string \"256\""));
}

TEST(SceneOcean, CascadeCountIsOneToFour) {
  std::string message = ParseError(R"({"ocean": {"cascades": []}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: ocean.cascades: has 0 elements; allowed: an array of 1 to 4 "
                       "objects (default [{\"patch_size_m\":1000,\"resolution\":256},"));
  message = ParseError(R"({"ocean": {"cascades": [{"patch_size_m": 5000}, {"patch_size_m": 500},
      {"patch_size_m": 50}, {"patch_size_m": 5}, {"patch_size_m": 0.5}]}})");
  EXPECT_TRUE(
      Contains(message, "scenes/x.json: ocean.cascades: has 5 elements; allowed: an array of 1 to 4"));
}

TEST(SceneOcean, PatchSizesMustStrictlyDecrease) {
  std::string message =
      ParseError(R"({"ocean": {"cascades": [{"patch_size_m": 100}, {"patch_size_m": 100}]}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: ocean.cascades[1].patch_size_m: must be < the previous "
                       "cascade's; got 100 after 100; list cascades from the largest patch"));
  message = ParseError(
      R"({"ocean": {"cascades": [{"patch_size_m": 100}, {"patch_size_m": 10}, {"patch_size_m": 50}]}})");
  EXPECT_FALSE(Contains(message, "cascades[1].patch_size_m"));
  EXPECT_TRUE(Contains(message,
                       "ocean.cascades[2].patch_size_m: must be < the previous cascade's; got 50 "
                       "after 10"));
}

TEST(SceneOcean, OutOfRangeValues) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"spectrum": {"wind_speed_mps": -5}})",
       "ocean.spectrum.wind_speed_mps: -5 is out of range; allowed: number > 0 and <= 60 m/s (default 10)"},
      {R"({"spectrum": {"wind_speed_mps": 0}})", "ocean.spectrum.wind_speed_mps: 0 is out of range"},
      {R"({"spectrum": {"wind_speed_mps": 61}})", "ocean.spectrum.wind_speed_mps: 61 is out of range"},
      {R"({"spectrum": {"fetch_km": 0}})",
       "ocean.spectrum.fetch_km: 0 is out of range; allowed: number > 0 and <= 10000 km (default 100)"},
      {R"({"spectrum": {"wind_direction_deg": 361}})",
       "ocean.spectrum.wind_direction_deg: 361 is out of range; allowed: number 0 to 360 deg (default 180)"},
      {R"({"spectrum": {"gamma": 0.5}})",
       "ocean.spectrum.gamma: 0.5 is out of range; allowed: number 1 to 20"},
      {R"({"spectrum": {"swell": 1.5}})",
       "ocean.spectrum.swell: 1.5 is out of range; allowed: number 0 to 1"},
      {R"({"spectrum": {"small_wave_cutoff_m": 11}})",
       "ocean.spectrum.small_wave_cutoff_m: 11 is out of range"},
      {R"({"seed": -1})",
       "ocean.seed: -1 is out of range; allowed: whole number 0 to 4294967295 (default 1)"},
      {R"({"seed": 4294967296})", "ocean.seed: 4294967296 is out of range"},
      {R"({"depth_m": 0})", "ocean.depth_m: 0 is out of range; allowed: number > 0 and <= 11000 m"},
      {R"({"depth_m": 11001})", "ocean.depth_m: 11001 is out of range"},
      {R"({"choppiness": 5.5})", "ocean.choppiness: 5.5 is out of range; allowed: number 0 to 5 (default 1)"},
      {R"({"loop_period_s": 3601})",
       "ocean.loop_period_s: 3601 is out of range; allowed: number 0 to 3600 s"},
      {R"({"cascades": [{"patch_size_m": 0}]})",
       "ocean.cascades[0].patch_size_m: 0 is out of range; allowed: number > 0 and <= 100000 m (default "
       "1000)"},
      {R"({"foam": {"threshold": -1.5}})",
       "ocean.foam.threshold: -1.5 is out of range; allowed: number -1 to 2"},
      {R"({"foam": {"decay_per_s": 101}})",
       "ocean.foam.decay_per_s: 101 is out of range; allowed: number 0 to 100 1/s (default 0.3)"},
  };
  for (const auto& [ocean_block, expected] : cases) {
    EXPECT_TRUE(Contains(ParseError(R"({"ocean": )" + ocean_block + "}"), "scenes/x.json: " + expected));
  }
}

TEST(SceneOcean, WrongTypes) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"([])", "ocean: expected an object {...}, got array []"},
      {R"({"spectrum": "jonswap"})", "ocean.spectrum: expected an object {...}, got string \"jonswap\""},
      {R"({"seed": "1"})", "ocean.seed: expected an integer, got string \"1\""},
      {R"({"seed": 1.5})", "ocean.seed: 1.5 is not a whole number"},
      {R"({"depth_m": true})", "ocean.depth_m: expected a number, got boolean true"},
      {R"({"spectrum": {"wind_speed_mps": "10"}})",
       "ocean.spectrum.wind_speed_mps: expected a number, got string \"10\""},
      {R"({"cascades": {"patch_size_m": 100}})",
       "ocean.cascades: expected an array of objects [{...}, ...], got object {\"patch_size_m\":100}; "
       "allowed: an array of 1 to 4 objects"},
      {R"({"cascades": 3})",
       "ocean.cascades: expected an array of objects [{...}, ...], got 3; allowed: an array of 1 to 4 "
       "objects "
       "(default [{\"patch_size_m\":1000,\"resolution\":256},{\"patch_size_m\":100,\"resolution\":256},"
       "{\"patch_size_m\":10,\"resolution\":256}]), or leave it out to use the defaults"},
      {R"({"cascades": [{"patch_size_m": 100}, 256]})",
       "ocean.cascades[1]: expected an object {...}, got 256; each element of cascades is an object such as "
       "{\"patch_size_m\":1000,\"resolution\":256}"},
      {R"({"cascades": [{"patch_size_m": 100, "resolution": [256]}]})",
       "ocean.cascades[0].resolution: expected an integer, got array [256]"},
      {R"({"foam": {"threshold": null}})", "ocean.foam.threshold: expected a number, got null"},
  };
  for (const auto& [ocean_block, expected] : cases) {
    EXPECT_TRUE(Contains(ParseError(R"({"ocean": )" + ocean_block + "}"), "scenes/x.json: " + expected));
  }
}

TEST(SceneOcean, UnknownFieldsInBlocksAndElements) {
  std::string message = ParseError(R"({"ocean": {"cascades": [{"patch_size": 100}], "wind": 3}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: ocean.cascades[0].patch_size: unknown field; did you mean "
                       "'patch_size_m'? Fields allowed in ocean.cascades[0]: patch_size_m, "
                       "resolution, comment"));
  EXPECT_TRUE(Contains(message, "scenes/x.json: ocean.wind: unknown field"));
  EXPECT_TRUE(Contains(ParseError(R"({"ocean": {"spectrum": {"windspeed_mps": 3}}})"),
                       "did you mean 'wind_speed_mps'?"));
  EXPECT_TRUE(Contains(ParseError(R"({"ocaen": {}})"), "did you mean 'ocean'?"));
}

TEST(SceneOcean, ReportsProblemsInEveryElement) {
  const std::string message = ParseError(
      R"({"ocean": {"cascades": [{"resolution": 100}, {"patch_size_m": 10, "resolution": 4096}]}})");
  EXPECT_TRUE(Contains(message, "ocean.cascades[0].resolution: 100 is not a power of two"));
  EXPECT_TRUE(Contains(message, "\nscenes/x.json: ocean.cascades[1].resolution: 4096 is not a power of two"));
}

// ---- Validation errors: file name, JSON path, what is wrong, how to fix ----

TEST(SceneErrors, UnknownFieldSuggestsClosest) {
  const std::string message = ParseError(R"({"camera": {"fov_dg": 40}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_dg: unknown field"));
  EXPECT_TRUE(Contains(message, "did you mean 'fov_deg'?"));
}

TEST(SceneErrors, UnknownFieldSuggestsAcrossMissingUnitSuffix) {
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"near": 1}})"), "did you mean 'near_m'?"));
}

TEST(SceneErrors, UnknownFieldWithoutCloseMatchListsAllowedFields) {
  const std::string message = ParseError(R"({"sun": {"colour": [1, 1, 1]}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: sun.colour: unknown field"));
  EXPECT_FALSE(Contains(message, "did you mean"));
  EXPECT_TRUE(Contains(message, "elevation_deg, azimuth_deg, intensity, comment"));
}

TEST(SceneErrors, UnknownTopLevelBlock) {
  const std::string message = ParseError(R"({"camra": {}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camra: unknown field"));
  EXPECT_TRUE(Contains(message, "did you mean 'camera'?"));
}

TEST(SceneErrors, StringForNumber) {
  const std::string message = ParseError(R"({"camera": {"fov_deg": "wide"}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_deg: expected a number, got string \"wide\""));
  EXPECT_TRUE(Contains(message, "allowed: number 1 to 170 deg"));
}

TEST(SceneErrors, BooleanForNumber) {
  EXPECT_TRUE(Contains(ParseError(R"({"sun": {"intensity": true}})"),
                       "sun.intensity: expected a number, got boolean true"));
}

TEST(SceneErrors, OutOfRange) {
  const std::string message = ParseError(R"({"camera": {"fov_deg": 200}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_deg: 200 is out of range"));
  EXPECT_TRUE(Contains(message, "allowed: number 1 to 170 deg (default 55)"));
}

TEST(SceneErrors, AzimuthDoesNotWrap) {
  EXPECT_TRUE(Contains(ParseError(R"({"sun": {"azimuth_deg": 370}})"),
                       "sun.azimuth_deg: 370 is out of range; allowed: number 0 to 360 deg (default 330)"));
  EXPECT_TRUE(
      Contains(ParseError(R"({"sun": {"azimuth_deg": -10}})"), "sun.azimuth_deg: -10 is out of range"));
}

TEST(SceneErrors, OpenLowerBound) {
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"near_m": 0}})"), "camera.near_m: 0 is out of range"));
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"near_m": 0}})"), "allowed: number > 0 m (default 0.1)"));
  // Positive as a double but 0 as a float: must not slip through as near_m = 0.
  EXPECT_TRUE(
      Contains(ParseError(R"({"camera": {"near_m": 1e-50}})"), "camera.near_m: 1e-50 is out of range"));
}

TEST(SceneErrors, FractionalForInteger) {
  const std::string message = ParseError(R"({"render": {"width": 640.5}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: render.width: 640.5 is not a whole number"));
  EXPECT_TRUE(Contains(message, "; allowed: whole number 16 to 8192 px (default 1280)"));
}

TEST(SceneErrors, IntegerOutOfRange) {
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"height": -720}})"), "render.height: -720 is out of range"));
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"height": 8193}})"), "render.height: 8193 is out of range"));
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"height": 18446744073709551615}})"),
                       "render.height: 18446744073709551615 is out of range"));
}

TEST(SceneErrors, StringForInteger) {
  EXPECT_TRUE(Contains(ParseError(R"({"render": {"width": "1280"}})"),
                       "render.width: expected an integer, got string \"1280\""));
}

TEST(SceneErrors, Vec3WithTwoElements) {
  const std::string message = ParseError(R"({"camera": {"position": [1, 2]}})");
  EXPECT_TRUE(Contains(
      message, "scenes/x.json: camera.position: expected [x, y, z], got array [1,2] with 2 elements"));
  EXPECT_TRUE(Contains(message, "allowed: 3 finite numbers [x, y, z] in m (default [0, 6, -40])"));
}

TEST(SceneErrors, Vec3NotAnArray) {
  EXPECT_TRUE(
      Contains(ParseError(R"({"camera": {"look_at": 5}})"), "camera.look_at: expected [x, y, z], got 5"));
}

TEST(SceneErrors, Vec3ElementNotANumber) {
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"position": [1, "2", 3]}})"),
                       "scenes/x.json: camera.position[1]: expected a number, got string \"2\""));
}

TEST(SceneErrors, NonFiniteNumbers) {
  // JSON text cannot spell NaN, but documents built in memory can, and 1e999 parses as infinity.
  json document = {{"camera", {{"fov_deg", std::nan("")}}}};
  EXPECT_TRUE(Contains(ErrorOf(parse_scene(document, kSource)),
                       "camera.fov_deg: NaN is not a finite 32-bit float; allowed: number 1 to 170 deg"));
  document = {{"time_s", std::numeric_limits<double>::infinity()}};
  EXPECT_TRUE(Contains(ErrorOf(parse_scene(document, kSource)), "time_s: infinity is not a finite"));
  document = {{"camera", {{"position", {0.0, -std::numeric_limits<double>::infinity(), 0.0}}}}};
  EXPECT_TRUE(
      Contains(ErrorOf(parse_scene(document, kSource)), "camera.position[1]: -infinity is not a finite"));
  // Finite as a double but not as a float.
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"position": [0, 1e300, 0]}})"),
                       "camera.position[1]: 1e+300 is not a finite 32-bit float"));
}

TEST(SceneErrors, BlockNotAnObject) {
  const std::string message = ParseError(R"({"camera": 5})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera: expected an object {...}, got 5"));
  EXPECT_TRUE(Contains(message, "leave it out to use the defaults"));
}

TEST(SceneErrors, TopLevelNotAnObject) {
  const std::string message = ParseError(R"([1, 2])");
  EXPECT_TRUE(Contains(message, "scenes/x.json: (top level): expected a JSON object {...}, got array"));
}

TEST(SceneErrors, CommentMustBeAString) {
  const std::string message = ParseError(R"({"sun": {"comment": 3}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: sun.comment: expected a string, got 3"));
}

TEST(SceneErrors, FarMustExceedNear) {
  const std::string message = ParseError(R"({"camera": {"near_m": 10, "far_m": 5}})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.far_m: must be > near_m"));
  EXPECT_TRUE(Contains(message, "got far_m 5 and near_m 10; raise far_m or lower near_m"));
}

TEST(SceneErrors, LookAtMustDifferFromPosition) {
  const std::string message = ParseError(R"({"camera": {"position": [1, 2, 3], "look_at": [1, 2, 3]}})");
  EXPECT_TRUE(Contains(message, "camera.look_at: must be different from position"));
}

TEST(SceneErrors, ReportsEveryProblemOnItsOwnLine) {
  const std::string message = ParseError(R"({"camera": {"fov_deg": 0}, "render": {"gamma": 9}, "tme_s": 1})");
  EXPECT_TRUE(Contains(message, "scenes/x.json: camera.fov_deg: 0 is out of range"));
  EXPECT_TRUE(Contains(message, "\nscenes/x.json: render.gamma: 9 is out of range"));
  EXPECT_TRUE(Contains(message, "\nscenes/x.json: tme_s: unknown field; did you mean 'time_s'?"));
}

TEST(SceneErrors, InvalidUtf8DoesNotThrow) {
  json document = {{"camera", {{"fov_deg", "\xff\xfe"}}}, {"\xff", 1}};
  EXPECT_TRUE(Contains(ErrorOf(parse_scene(document, kSource)), "camera.fov_deg: expected a number"));
}

// ---- Files ----

TEST_F(SceneFileTest, LoadsFileAndRecordsSource) {
  const fs::path path = Write("a.json", R"({"camera": {"fov_deg": 30}})");
  Result<Scene> scene = load_scene(path);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->source, path);
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 30.f);
}

TEST_F(SceneFileTest, MissingFile) {
  const fs::path path = dir_ / "nope.json";
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(Contains(message, path.string() + ": file not found; check the path"));
}

TEST_F(SceneFileTest, DirectoryInsteadOfFile) {
  EXPECT_TRUE(Contains(ErrorOf(load_scene(dir_)), dir_.string() + ": is a directory, not a scene file"));
}

TEST_F(SceneFileTest, UnreadableFile) {
  const fs::path path = Write("locked.json", "{}");
  fs::permissions(path, fs::perms::none);
  if (std::ifstream(path).good()) GTEST_SKIP() << "running with permissions that bypass file modes (root)";
  EXPECT_TRUE(Contains(ErrorOf(load_scene(path)), path.string() + ": cannot be opened: Permission denied"));
}

TEST_F(SceneFileTest, MalformedJsonReportsLineAndColumn) {
  const fs::path path = Write("bad.json", "{\n  \"camera\": {\n    \"fov_deg\": 40,\n  }\n}\n");
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(Contains(message, path.string() + ": invalid JSON: parse error at line 4, column 3"));
  EXPECT_TRUE(Contains(message, "no comments or trailing commas"));
}

// The issue 11 report: 100,000 nested arrays overflowed the parser's stack (SIGSEGV).
TEST_F(SceneFileTest, HundredThousandNestedArraysAreRefusedNamingTheLimit) {
  const fs::path path =
      Write("deep.json", "{\"ocean\": " + std::string(100000, '[') + std::string(100000, ']') + "}");
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(
      Contains(message, path.string() + ": JSON: arrays or objects nested more than 32 deep at line 1"))
      << message;
}

TEST_F(SceneFileTest, LongStringsAndArraysAreRefusedNamingTheLimit) {
  const fs::path name =
      Write("name.json", "{\n  \"objects\": [{\"file\": \"" + std::string(5000, 'a') + "\"}]}");
  EXPECT_TRUE(Contains(ErrorOf(load_scene(name)), "a string longer than 4096 bytes at line 2"));
  std::string lights = "{\"lights\": [";
  for (int i = 0; i < 5000; ++i) lights += i ? ",{}" : "{}";
  const fs::path many = Write("lights.json", lights + "]}");
  EXPECT_TRUE(Contains(ErrorOf(load_scene(many)), "an array of more than 4096 elements"));
}

TEST_F(SceneFileTest, HugeFileIsRefusedWithoutReadingIt) {
  const fs::path path = Write("huge.json", "{}");
  fs::resize_file(path, std::uintmax_t{17} << 20);  // sparse: nothing is written
  EXPECT_TRUE(
      Contains(ErrorOf(load_scene(path)), path.string() + ": is 17 MiB; scene files are limited to 16 MiB"));
}

// Issue 36: /dev/zero was read to 4.2 GB before the 16 MiB limit was checked, and a FIFO would block
// until something wrote to it. Both are refused before a byte is read.
TEST_F(SceneFileTest, DevicesAndPipesAreRefusedWithoutReadingThem) {
  const std::string zero = ErrorOf(load_scene("/dev/zero"));
  EXPECT_TRUE(Contains(zero, "/dev/zero: is not a regular file")) << zero;
  EXPECT_TRUE(Contains(zero, "scenes/default.json")) << "the fix names a scene file: " << zero;
  const fs::path fifo = dir_ / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(Contains(ErrorOf(load_scene(fifo)), fifo.string() + ": is not a regular file"));
}

TEST_F(SceneFileTest, DeeplyNestedOverrideIsRefused) {
  const fs::path path = Write("ok.json", "{}");
  const std::vector<std::string> overrides{"ocean.choppiness=" + std::string(50000, '[')};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, "--set ocean.choppiness=[[[")) << message;
  EXPECT_TRUE(Contains(message, "nested more than 32 deep")) << message;
}

TEST_F(SceneFileTest, EmptyFile) {
  const fs::path path = Write("empty.json", "");
  EXPECT_TRUE(Contains(ErrorOf(load_scene(path)), path.string() + ": invalid JSON: parse error at line 1"));
}

TEST_F(SceneFileTest, NumberTooLargeForJsonParser) {
  const fs::path path = Write("huge.json", R"({"time_s": 1e999})");
  EXPECT_TRUE(
      Contains(ErrorOf(load_scene(path)), path.string() + ": invalid JSON: number overflow parsing '1e999'"));
}

TEST_F(SceneFileTest, DuplicateKeyIsAnError) {
  const fs::path path = Write("dup.json", R"({"camera": {"fov_deg": 40, "fov_deg": 50}, "sun": {}})");
  const std::string message = ErrorOf(load_scene(path));
  EXPECT_TRUE(Contains(message, path.string() + ": camera.fov_deg: field appears more than once"));
}

TEST_F(SceneFileTest, ValidationErrorsNameTheFile) {
  const fs::path path = Write("range.json", R"({"render": {"exposure": 0}})");
  EXPECT_TRUE(Contains(ErrorOf(load_scene(path)), path.string() + ": render.exposure: 0 is out of range"));
}

// ---- Overrides ----

TEST(ApplyOverride, SetsParsedJsonValue) {
  json document = json::object();
  ASSERT_TRUE(apply_override(document, "camera.fov_deg=40").ok());
  ASSERT_TRUE(apply_override(document, "camera.position=[1, 2, 3]").ok());
  EXPECT_EQ(document["camera"]["fov_deg"], 40);
  EXPECT_EQ(document["camera"]["position"], json::parse("[1, 2, 3]"));
}

TEST(ApplyOverride, NonJsonValueBecomesString) {
  json document = json::object();
  ASSERT_TRUE(apply_override(document, "comment=hello world").ok());
  ASSERT_TRUE(apply_override(document, "sun.comment=").ok());
  EXPECT_EQ(document["comment"], "hello world");
  EXPECT_EQ(document["sun"]["comment"], "");
}

TEST(ApplyOverride, MissingEquals) {
  json document = json::object();
  const Result<void> result = apply_override(document, "camera.fov_deg");
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(Contains(result.error().message, "--set camera.fov_deg: missing '='"));
  EXPECT_TRUE(Contains(result.error().message, "expected the form --set path=value"));
}

TEST(ApplyOverride, EmptyPathOrSegment) {
  json document = json::object();
  for (const char* bad : {"=40", " =40", "camera..fov_deg=40", ".fov_deg=1", "camera.=1"}) {
    const Result<void> result = apply_override(document, bad);
    ASSERT_FALSE(result.ok()) << bad;
    EXPECT_TRUE(Contains(result.error().message, "expected the form --set path=value")) << bad;
  }
  EXPECT_EQ(document, json::object());
}

TEST(ApplyOverride, ThroughNonObjectIsAnError) {
  json document = {{"camera", {{"fov_deg", 40}}}};
  const Result<void> result = apply_override(document, "camera.fov_deg.x=1");
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(
      Contains(result.error().message,
               "--set camera.fov_deg.x=1: camera.fov_deg is 40, not an object, so it has no field 'x'"));
  EXPECT_TRUE(
      Contains(result.error().message, "set camera.fov_deg as a whole, e.g. --set camera.fov_deg=40"));
}

TEST_F(SceneFileTest, OverrideCreatesMissingBlock) {
  const fs::path path = Write("no_render.json", R"({"camera": {}})");
  const std::vector<std::string> overrides = {"render.width=64"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->render.width, 64u);
  EXPECT_EQ(scene->render.height, 720u);
}

TEST_F(SceneFileTest, OverrideTakesPrecedenceOverFileAndLastOneWins) {
  const fs::path path = Write("fov.json", R"({"camera": {"fov_deg": 30, "near_m": 2}})");
  const std::vector<std::string> overrides = {"camera.fov_deg=40", "camera.fov_deg=45", "time_s=3"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_FLOAT_EQ(scene->camera.fov_deg, 45.f);
  EXPECT_FLOAT_EQ(scene->camera.near_m, 2.f);  // untouched fields keep the file's value
  EXPECT_FLOAT_EQ(scene->time_s, 3.f);
}

TEST_F(SceneFileTest, OverrideOfUnknownFieldIsRejectedLikeTheFile) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_dg=40"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": camera.fov_dg: unknown field; did you mean 'fov_deg'?"));
  EXPECT_TRUE(Contains(message, "(value from --set camera.fov_dg=40)"));
}

TEST_F(SceneFileTest, OverrideValueIsValidated) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_deg=wide", "camera.position=[1,2]"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, "camera.fov_deg: expected a number, got string \"wide\""));
  EXPECT_TRUE(Contains(message, "(value from --set camera.fov_deg=wide)"));
  EXPECT_TRUE(Contains(message, "camera.position: expected [x, y, z], got array [1,2] with 2 elements"));
  EXPECT_TRUE(Contains(message, "(value from --set camera.position=[1,2])"));
}

TEST_F(SceneFileTest, OverrideCreatingObjectInPlaceOfNumberIsRejected) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_deg.x=1"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": camera.fov_deg: expected a number, got object {\"x\":1}"));
  EXPECT_TRUE(Contains(message, "(value from --set camera.fov_deg.x=1)"));
}

TEST_F(SceneFileTest, MalformedOverrideNamesFileAndExpectedForm) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"camera.fov_deg"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": --set camera.fov_deg: missing '='"));
  EXPECT_TRUE(Contains(message, "expected the form --set path=value"));
}

TEST_F(SceneFileTest, OverrideThroughNonObjectFails) {
  const fs::path path = Write("s.json", R"({"camera": {"position": [0, 1, 2]}})");
  const std::vector<std::string> overrides = {"camera.position.x=1"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, "camera.position is array [0,1,2], not an object"));
  EXPECT_TRUE(Contains(message, "e.g. --set camera.position=[0,1,2]"));
}

TEST_F(SceneFileTest, OverridesOceanFields) {
  const fs::path path = Write("ocean.json", R"({"ocean": {"spectrum": {"type": "phillips"}}})");
  const std::vector<std::string> overrides = {"ocean.spectrum.type=pm", "ocean.spectrum.spreading=cos2",
                                              "ocean.seed=7", "ocean.foam.decay_per_s=2",
                                              R"(ocean.cascades=[{"patch_size_m":500,"resolution":128}])"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->ocean.spectrum.type, ocean::SpectrumType::PiersonMoskowitz);
  EXPECT_EQ(scene->ocean.spectrum.spreading, ocean::Spreading::Cos2);
  EXPECT_EQ(scene->ocean.seed, 7u);
  EXPECT_EQ(scene->ocean.foam.decay_per_s, 2.0);
  ASSERT_EQ(scene->ocean.cascades.size(), 1u);
  EXPECT_EQ(scene->ocean.cascades[0].patch_size_m, 500.0);
  EXPECT_EQ(scene->ocean.cascades[0].resolution, 128u);
}

TEST_F(SceneFileTest, OverrideReplacesCascadesFromTheFile) {
  const fs::path path = Write("ocean.json", R"({"ocean": {"cascades": [{"patch_size_m": 800},
      {"patch_size_m": 80}, {"patch_size_m": 8}, {"patch_size_m": 0.8}]}})");
  const std::vector<std::string> overrides = {
      R"(ocean.cascades=[{"patch_size_m":300,"resolution":512},{"patch_size_m":30}])"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  ASSERT_EQ(scene->ocean.cascades.size(), 2u);
  EXPECT_EQ(scene->ocean.cascades[0].resolution, 512u);
  EXPECT_EQ(scene->ocean.cascades[1].patch_size_m, 30.0);
  EXPECT_EQ(scene->ocean.cascades[1].resolution, 256u);
}

TEST_F(SceneFileTest, OceanOverrideValuesAreValidated) {
  const fs::path path = Write("s.json", "{}");
  const std::vector<std::string> overrides = {"ocean.spectrum.type=jonswop", "ocean.cascades=[]",
                                              "ocean.spectrum.wind_speed_mps=-1"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": ocean.spectrum.type: string \"jonswop\" is not one of"));
  EXPECT_TRUE(Contains(message, "did you mean 'jonswap'?"));
  EXPECT_TRUE(Contains(message, "(value from --set ocean.spectrum.type=jonswop)"));
  EXPECT_TRUE(Contains(message, "ocean.cascades: has 0 elements"));
  EXPECT_TRUE(Contains(message, "(value from --set ocean.cascades=[])"));
  EXPECT_TRUE(Contains(message, "(value from --set ocean.spectrum.wind_speed_mps=-1)"));
}

// Paths cannot index into arrays; the error hands back the whole array with the intended change made.
TEST_F(SceneFileTest, OverrideOfArrayElementSuggestsWholeArray) {
  const fs::path path = Write("s.json", "{}");
  std::vector<std::string> overrides = {"ocean.cascades[0].resolution=128"};
  std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": ocean.cascades[0]: unknown field; a field path cannot "
                                                "index into an array; set the whole array instead, e.g. "
                                                "--set 'ocean.cascades=[{\"patch_size_m\":1000,"
                                                "\"resolution\":128},{\"patch_size_m\":100,"
                                                "\"resolution\":256},{\"patch_size_m\":10,"
                                                "\"resolution\":256}]'"));
  EXPECT_TRUE(Contains(message, "(value from --set ocean.cascades[0].resolution=128)"));

  // An array the file has can be indexed: the element is changed and validated like the file.
  const fs::path two =
      Write("two.json", R"({"ocean": {"cascades": [{"patch_size_m": 50}, {"patch_size_m": 5}]}})");
  overrides = {"ocean.cascades[1].patch_size_m=2"};
  auto changed = load_scene(two, overrides);
  ASSERT_TRUE(changed) << changed.error().message;
  EXPECT_EQ(changed->ocean.cascades[1].patch_size_m, 2.0);

  // An index past the end names the array's length.
  overrides = {"ocean.cascades[7].resolution=64"};
  message = ErrorOf(load_scene(two, overrides));
  EXPECT_TRUE(Contains(message, "ocean.cascades has 2 element(s), so [7] does not exist")) << message;
}

TEST_F(SceneFileTest, OverrideIntoArrayWithDotIsAnError) {
  const fs::path path = Write("s.json", R"({"ocean": {"cascades": [{"patch_size_m": 50}]}})");
  const std::vector<std::string> overrides = {"ocean.cascades.0.resolution=128"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, "ocean.cascades is array [{\"patch_size_m\":50}], not an object"));
}

// ---- World blocks: seafloor, objects, lights; render's tone map and effects ----

TEST(SceneWorld, AbsentBlocksGiveDefaults) {
  Result<Scene> scene = parse_scene(json::object(), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const Seafloor& f = scene->seafloor;
  EXPECT_EQ(f.type, SeafloorType::None);
  EXPECT_FLOAT_EQ(f.depth_near_m, 0.5f);
  EXPECT_FLOAT_EQ(f.depth_far_m, 30.f);
  EXPECT_EQ(f.near, glm::vec2(0.f, 0.f));
  EXPECT_EQ(f.far, glm::vec2(0.f, 200.f));
  EXPECT_FLOAT_EQ(f.extent_m, 600.f);
  EXPECT_EQ(f.texture, "");
  EXPECT_FLOAT_EQ(f.texture_scale_m, 2.f);
  EXPECT_EQ(f.albedo, glm::vec3(0.76f, 0.70f, 0.55f));
  EXPECT_EQ(f.file, "");
  EXPECT_TRUE(scene->objects.empty());
  EXPECT_TRUE(scene->lights.empty());
  EXPECT_EQ(scene->render.tone_map, ToneMap::Belyaev);
  EXPECT_TRUE(scene->render.effects.reflection);
  EXPECT_TRUE(scene->render.effects.refraction);
  EXPECT_TRUE(scene->render.effects.foam);
}

TEST(SceneWorld, ReadsEveryField) {
  Result<Scene> scene = parse_scene(json::parse(R"({
    "seafloor": {"type": "slope", "depth_near_m": 0, "depth_far_m": 11000, "near": [-5, 10.5],
                 "far": [300, -20], "extent_m": 100000, "texture": "sand.png", "texture_scale_m": 1000,
                 "albedo": [0, 0.5, 1], "comment": "bay"},
    "objects": [{"name": "buoy", "file": "buoy.glb", "position": [1, -2, 3], "rotation_deg": [-360, 45, 360],
                 "scale": 1000, "comment": "red"},
                {"file": "/abs/boat.gltf", "scale": 0.25}],
    "lights": [{"position": [4, 5, 6], "colour": [0, 50, 100], "intensity": 1000000, "range_m": 100000,
                "comment": "lamp"}],
    "render": {"tone_map": "clamp", "effects": {"reflection": false, "refraction": false, "foam": false}}
  })"),
                                    kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const Seafloor& f = scene->seafloor;
  EXPECT_EQ(f.type, SeafloorType::Slope);
  EXPECT_FLOAT_EQ(f.depth_near_m, 0.f);
  EXPECT_FLOAT_EQ(f.depth_far_m, 11000.f);
  EXPECT_EQ(f.near, glm::vec2(-5.f, 10.5f));
  EXPECT_EQ(f.far, glm::vec2(300.f, -20.f));
  EXPECT_FLOAT_EQ(f.extent_m, 100000.f);
  EXPECT_EQ(f.texture, "sand.png");  // parse_scene has no folder to resolve against; load_scene does
  EXPECT_FLOAT_EQ(f.texture_scale_m, 1000.f);
  EXPECT_EQ(f.albedo, glm::vec3(0.f, 0.5f, 1.f));
  ASSERT_EQ(scene->objects.size(), 2u);
  const Object& buoy = scene->objects[0];
  EXPECT_EQ(buoy.name, "buoy");
  EXPECT_EQ(buoy.file, "buoy.glb");
  EXPECT_EQ(buoy.position, glm::vec3(1.f, -2.f, 3.f));
  EXPECT_EQ(buoy.rotation_deg, glm::vec3(-360.f, 45.f, 360.f));
  EXPECT_FLOAT_EQ(buoy.scale, 1000.f);
  const Object& boat = scene->objects[1];  // absent fields start from a default Object
  EXPECT_EQ(boat.name, "");
  EXPECT_EQ(boat.file, "/abs/boat.gltf");
  EXPECT_EQ(boat.position, glm::vec3(0.f));
  EXPECT_EQ(boat.rotation_deg, glm::vec3(0.f));
  EXPECT_FLOAT_EQ(boat.scale, 0.25f);
  ASSERT_EQ(scene->lights.size(), 1u);
  const PointLight& l = scene->lights[0];
  EXPECT_EQ(l.position, glm::vec3(4.f, 5.f, 6.f));
  EXPECT_EQ(l.colour, glm::vec3(0.f, 50.f, 100.f));
  EXPECT_FLOAT_EQ(l.intensity, 1e6f);
  EXPECT_FLOAT_EQ(l.range_m, 1e5f);
  EXPECT_EQ(scene->render.tone_map, ToneMap::Clamp);
  EXPECT_FALSE(scene->render.effects.reflection);
  EXPECT_FALSE(scene->render.effects.refraction);
  EXPECT_FALSE(scene->render.effects.foam);
}

TEST(SceneWorld, GltfSeafloorAndDefaultElements) {
  Result<Scene> scene = parse_scene(
      json::parse(R"({"seafloor": {"type": "gltf", "file": "bay.glb"}, "objects": [], "lights": [{}, {}]})"),
      kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->seafloor.type, scene::SeafloorType::Gltf);
  EXPECT_EQ(scene->seafloor.file, "bay.glb");
  EXPECT_TRUE(scene->objects.empty());
  ASSERT_EQ(scene->lights.size(), 2u);
  EXPECT_EQ(scene->lights[1].position, glm::vec3(0.f, 5.f, 0.f));
  EXPECT_EQ(scene->lights[1].colour, glm::vec3(1.f, 0.9f, 0.7f));
  EXPECT_FLOAT_EQ(scene->lights[1].intensity, 1.f);
  EXPECT_FLOAT_EQ(scene->lights[1].range_m, 50.f);
}

TEST(SceneWorld, OutOfRangeValues) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"seafloor": {"depth_near_m": -101}})",
       "seafloor.depth_near_m: -101 is out of range; allowed: number -100 to 11000 m (default 0.5)"},
      {R"({"ocean": {"breaker_index": 0.1}})",
       "ocean.breaker_index: 0.1 is out of range; allowed: number 0.3 to 1.5 (default 0.78)"},
      {R"({"seafloor": {"depth_far_m": 11001}})",
       "seafloor.depth_far_m: 11001 is out of range; allowed: number 0 to 11000 m (default 30)"},
      {R"({"seafloor": {"extent_m": 0}})",
       "seafloor.extent_m: 0 is out of range; allowed: number > 0 and <= 100000 m (default 600)"},
      {R"({"seafloor": {"extent_m": 100001}})", "seafloor.extent_m: 100001 is out of range"},
      {R"({"seafloor": {"texture_scale_m": 0}})",
       "seafloor.texture_scale_m: 0 is out of range; allowed: number > 0 and <= 1000 m (default 2)"},
      {R"({"seafloor": {"texture_scale_m": 1000.5}})", "seafloor.texture_scale_m: 1000.5 is out of range"},
      {R"({"seafloor": {"albedo": [0.5, 1.5, 0]}})",
       "seafloor.albedo[1]: 1.5 is out of range; allowed: 3 numbers [r, g, b], each 0 to 1 (default [0.76, "
       "0.7, 0.55])"},
      {R"({"seafloor": {"albedo": [-0.1, 0, 0]}})", "seafloor.albedo[0]: -0.1 is out of range"},
      {R"({"objects": [{"file": "a.glb", "scale": 0}]})",
       "objects[0].scale: 0 is out of range; allowed: number > 0 and <= 1000 (default 1)"},
      {R"({"objects": [{"file": "a.glb", "scale": 1001}]})", "objects[0].scale: 1001 is out of range"},
      {R"({"objects": [{"file": "a.glb"}, {"file": "b.glb", "rotation_deg": [0, 0, 361]}]})",
       "objects[1].rotation_deg[2]: 361 is out of range; allowed: 3 numbers [yaw, pitch, roll], each -360 "
       "to 360 deg (default [0, 0, 0])"},
      {R"({"objects": [{"file": "a.glb", "rotation_deg": [-360.5, 0, 0]}]})",
       "objects[0].rotation_deg[0]: -360.5 is out of range"},
      {R"({"objects": [{"file": "a.glb", "position": [0, 1e300, 0]}]})",
       "objects[0].position[1]: 1e+300 is not a finite 32-bit float; allowed: 3 finite numbers [x, y, z] in "
       "m (default [0, 0, 0])"},
      {R"({"lights": [{"colour": [1, 101, 1]}]})",
       "lights[0].colour[1]: 101 is out of range; allowed: 3 numbers [r, g, b], each 0 to 100 (default [1, "
       "0.9, 0.7])"},
      {R"({"lights": [{"colour": [-1, 1, 1]}]})", "lights[0].colour[0]: -1 is out of range"},
      {R"({"lights": [{"intensity": -1}]})",
       "lights[0].intensity: -1 is out of range; allowed: number 0 to 1000000 (default 1)"},
      {R"({"lights": [{"intensity": 1000001}]})", "lights[0].intensity: 1000001 is out of range"},
      {R"({"lights": [{"range_m": 0}]})",
       "lights[0].range_m: 0 is out of range; allowed: number > 0 and <= 100000 m (default 50)"},
      {R"({"lights": [{"range_m": 100001}]})", "lights[0].range_m: 100001 is out of range"},
      {R"({"camera": {"yaw_deg": 361, "pitch_deg": 0}})",
       "camera.yaw_deg: 361 is out of range; allowed: number -360 to 360 deg"},
      {R"({"camera": {"yaw_deg": 0, "pitch_deg": -91}})",
       "camera.pitch_deg: -91 is out of range; allowed: number -90 to 90 deg"},
  };
  for (const auto& [document, expected] : cases) {
    EXPECT_TRUE(Contains(ParseError(document), "scenes/x.json: " + expected));
  }
}

TEST(SceneWorld, WrongTypesAndNames) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"seafloor": {"type": "slop"}})",
       "seafloor.type: string \"slop\" is not one of the allowed names; did you mean 'slope'? allowed: "
       "\"none\", \"slope\", \"gltf\" (default \"none\")"},
      {R"({"seafloor": {"near": [1, 2, 3]}})",
       "seafloor.near: expected [x, z], got array [1,2,3] with 3 elements; allowed: 2 finite numbers [x, z] "
       "in m (default [0, 0])"},
      {R"({"seafloor": {"far": 5}})", "seafloor.far: expected [x, z], got 5"},
      {R"({"seafloor": {"near": [0, "1"]}})", "seafloor.near[1]: expected a number, got string \"1\""},
      {R"({"seafloor": {"albedo": [1, 1]}})",
       "seafloor.albedo: expected [r, g, b], got array [1,1] with 2 elements"},
      {R"({"seafloor": {"texture": 3}})", "seafloor.texture: expected a string, got 3"},
      {R"({"seafloor": []})", "seafloor: expected an object {...}, got array []"},
      {R"({"objects": {"file": "a.glb"}})",
       "objects: expected an array of objects [{...}, ...], got object {\"file\":\"a.glb\"}; allowed: an "
       "array of 0 to 256 objects (default [])"},
      {R"({"objects": ["a.glb"]})", "objects[0]: expected an object {...}, got string \"a.glb\""},
      {R"({"objects": [{"file": "a.glb", "colour": [1, 0, 0]}]})",
       "objects[0].colour: unknown field; Fields allowed in objects[0]: name, file, position, "
       "rotation_deg, scale, floating, lights_from_gltf, comment"},
      {R"({"lights": [{"range": 5}]})", "lights[0].range: unknown field; did you mean 'range_m'?"},
      {R"({"render": {"tone_map": "reinhard"}})",
       "render.tone_map: string \"reinhard\" is not one of the allowed names; allowed: \"belyaev\", "
       "\"clamp\" (default \"belyaev\")"},
      {R"({"render": {"effects": {"foam": "no"}}})",
       "render.effects.foam: expected true or false, got string \"no\""},
      {R"({"render": {"effects": {"reflections": false}}})",
       "render.effects.reflections: unknown field; did you mean 'reflection'?"},
      {R"({"render": {"effects": true}})", "render.effects: expected an object {...}, got boolean true"},
  };
  for (const auto& [document, expected] : cases) {
    EXPECT_TRUE(Contains(ParseError(document), "scenes/x.json: " + expected));
  }
}

TEST(SceneWorld, ArrayLengths) {
  json objects = json::array(), lights = json::array();
  for (int i = 0; i < 257; ++i) objects.push_back({{"file", "a.glb"}});
  for (int i = 0; i < 65; ++i) lights.push_back(json::object());
  std::string message = ErrorOf(parse_scene({{"objects", objects}}, kSource));
  EXPECT_TRUE(Contains(message, "scenes/x.json: objects: has 257 elements; allowed: an array of 0 to 256"));
  message = ErrorOf(parse_scene({{"lights", lights}}, kSource));
  EXPECT_TRUE(Contains(message, "scenes/x.json: lights: has 65 elements; allowed: an array of 0 to 64"));
  objects.erase(objects.begin());
  lights.erase(lights.begin());
  Result<Scene> full = parse_scene({{"objects", objects}, {"lights", lights}}, kSource);
  ASSERT_TRUE(full.ok()) << full.error().message;
  EXPECT_EQ(full->objects.size(), 256u);
  EXPECT_EQ(full->lights.size(), 64u);
}

TEST(SceneWorld, DepthsMustNotDecreaseTowardFar) {
  const std::string message = ParseError(R"({"seafloor": {"depth_near_m": 10, "depth_far_m": 5}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: seafloor.depth_far_m: must be >= depth_near_m; got depth_far_m 5 and "
                       "depth_near_m 10; the floor deepens from near to far"));
  Result<Scene> flat =
      parse_scene(json::parse(R"({"seafloor": {"depth_near_m": 7, "depth_far_m": 7}})"), kSource);
  ASSERT_TRUE(flat.ok()) << flat.error().message;
}

TEST(SceneWorld, NearMustDifferFromFar) {
  EXPECT_TRUE(Contains(ParseError(R"({"seafloor": {"near": [3, 4], "far": [3, 4]}})"),
                       "scenes/x.json: seafloor.far: must be different from near; near and far set the "
                       "direction of the slope"));
}

TEST(SceneWorld, FileRulesOfSeafloorType) {
  EXPECT_TRUE(
      Contains(ParseError(R"({"seafloor": {"type": "gltf"}})"),
               "scenes/x.json: seafloor.file: must be a file name when type is \"gltf\"; type \"gltf\" "
               "reads the floor from a mesh; give its path"));
  EXPECT_TRUE(Contains(ParseError(R"({"seafloor": {"type": "gltf", "file": ""}})"),
                       "seafloor.file: must be a file name when type is \"gltf\""));
  EXPECT_TRUE(Contains(ParseError(R"({"seafloor": {"type": "slope", "file": "bay.glb"}})"),
                       "scenes/x.json: seafloor.file: must be left out when type is \"slope\"; got string "
                       "\"bay.glb\"; a slope is generated, not loaded"));
  // "none" ignores the floor fields, so a file prepared for later does not make the scene invalid.
  EXPECT_TRUE(parse_scene(json::parse(R"({"seafloor": {"type": "none", "file": "bay.glb"}})"), kSource).ok());
}

TEST(SceneWorld, ObjectNeedsAFile) {
  const std::string message =
      ParseError(R"({"objects": [{"file": "a.glb"}, {"name": "boat"}, {"file": ""}]})");
  EXPECT_FALSE(Contains(message, "objects[0]"));
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: objects[1].file: must be a file name (required); every object is "
                       "loaded from a glTF file"));
  EXPECT_TRUE(Contains(message, "\nscenes/x.json: objects[2].file: must be a file name (required)"));
}

TEST(SceneWorld, ReadsVehicles) {
  const json document = json::parse(R"({"vehicles": [
      {"name": "tender", "file": "boat.gltf", "scale": 0.8,
       "path": {"waypoints": [[0, 0], [50, 10], [20, 40.5]], "speed_mps": 4, "loop": false, "start_m": 7},
       "body": {"density_kg_m3": 300, "centre_of_mass_offset": [0, -0.2, 0]}},
      {"file": "auv.gltf", "depth_m": 6}]})");
  const Result<Scene> scene = parse_scene(document, kSource);
  ASSERT_TRUE(scene) << scene.error().message;
  const Scene& s = *scene;
  ASSERT_EQ(s.vehicles.size(), 2u);
  const Vehicle& v = s.vehicles[0];
  EXPECT_EQ(v.name, "tender");
  EXPECT_EQ(v.file, "boat.gltf");
  EXPECT_FLOAT_EQ(v.scale, 0.8f);
  ASSERT_EQ(v.path.waypoints.size(), 3u);
  EXPECT_EQ(v.path.waypoints[2], glm::vec2(20, 40.5f));
  EXPECT_FLOAT_EQ(v.path.speed_mps, 4);
  EXPECT_FALSE(v.path.loop);
  EXPECT_FLOAT_EQ(v.path.start_m, 7);
  EXPECT_FLOAT_EQ(v.depth_m, 0);
  EXPECT_FLOAT_EQ(v.body.density_kg_m3, 300);
  EXPECT_EQ(v.body.centre_of_mass_offset, glm::vec3(0, -0.2f, 0));
  EXPECT_FLOAT_EQ(s.vehicles[1].depth_m, 6);
  EXPECT_EQ(s.vehicles[1].path.waypoints, Vehicle{}.path.waypoints);  // the default path
  EXPECT_TRUE(s.vehicles[1].path.loop);
}

TEST(SceneWorld, VehicleErrorsNameTheFieldAndTheFix) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"vehicles": [{"path": {}}]})",
       "vehicles[0].file: must be a file name (required); every vehicle is loaded from a glTF file"},
      {R"({"vehicles": [{"file": "b.gltf", "path": {"waypoints": [[0, 0]]}}]})",
       "vehicles[0].path.waypoints: expected 2 to 256 points [[x, z], ...], got array [[0,0]] with 1 "
       "elements; "
       "allowed: an array of 2 to 256 points [x, z] in m, e.g. [[0, 0], [40, 10]]"},
      {R"({"vehicles": [{"file": "b.gltf", "path": {"waypoints": [[0, 0], [1, 2, 3]]}}]})",
       "vehicles[0].path.waypoints[1]: expected [x, z], got array [1,2,3]"},
      {R"({"vehicles": [{"file": "b.gltf", "path": {"waypoints": [[0, 0], [1, "2"]]}}]})",
       "vehicles[0].path.waypoints[1][1]: expected a number, got string \"2\""},
      {R"({"vehicles": [{"file": "b.gltf", "path": {"waypoints": [[0, 0], [1, 1e39]]}}]})",
       "vehicles[0].path.waypoints[1][1]: 1e+39 is not a finite 32-bit float"},
      {R"({"vehicles": [{"file": "b.gltf", "path": {"waypoints": "north"}}]})",
       "vehicles[0].path.waypoints: expected 2 to 256 points [[x, z], ...], got string \"north\""},
      {R"({"vehicles": [{"file": "b.gltf", "path": {"speed_mps": -1}}]})",
       "vehicles[0].path.speed_mps: -1 is out of range"},
      {R"({"vehicles": [{"file": "b.gltf", "depth_m": -2}]})", "vehicles[0].depth_m: -2 is out of range"},
      {R"({"vehicles": [{"file": "b.gltf", "body": {"enabled": true}}]})",
       "vehicles[0].body.enabled: unknown field"},
  };
  for (const auto& [document, expected] : cases) {
    EXPECT_TRUE(Contains(ParseError(document), "scenes/x.json: " + expected));
  }
}

TEST(SceneWorld, FieldReferenceRows) {
  std::map<std::string, FieldInfo> rows;
  for (const FieldInfo& f : scene_fields()) rows[f.path] = f;
  EXPECT_EQ(rows.at("seafloor.near").type, "[x, z]");
  EXPECT_EQ(rows.at("seafloor.far").default_value, "[0, 200]");
  EXPECT_EQ(rows.at("seafloor.far").range, "finite, different from near");
  EXPECT_EQ(rows.at("seafloor.albedo").type, "[r, g, b]");
  EXPECT_EQ(rows.at("seafloor.albedo").range, "each 0 to 1");
  EXPECT_EQ(rows.at("seafloor.file").range,
            "any, a file name when type is \"gltf\", left out when type is \"slope\"");
  EXPECT_EQ(rows.at("objects").default_value, "[]");
  EXPECT_EQ(rows.at("objects").range, "0 to 256 elements");
  EXPECT_EQ(rows.at("objects[].file").range, "any, a file name (required)");
  EXPECT_EQ(rows.at("objects[].rotation_deg").type, "[yaw, pitch, roll]");
  EXPECT_EQ(rows.at("lights").range, "0 to 64 elements");
  EXPECT_EQ(rows.at("lights[].colour").range, "each 0 to 100");
  EXPECT_EQ(rows.at("render.tone_map").default_value, "\"belyaev\"");
  EXPECT_EQ(rows.at("render.effects.foam").default_value, "true");
  EXPECT_EQ(rows.at("camera.yaw_deg").default_value, "");  // no default: look_at aims the camera
  EXPECT_EQ(rows.at("camera.yaw_deg").range, "-360 to 360, given with pitch_deg");
  EXPECT_EQ(rows.at("camera.look_at").range,
            "finite, left out when yaw_deg or pitch_deg is given, different from position");
}

// ---- Camera: yaw_deg / pitch_deg instead of look_at ----

// Unit view direction of a parsed camera.
glm::vec3 ViewOf(const std::string& camera_block) {
  Result<Scene> scene = parse_scene(json::parse(R"({"camera": )" + camera_block + "}"), kSource);
  EXPECT_TRUE(scene.ok()) << scene.error().message;
  if (!scene.ok()) return glm::vec3(0.f);
  return glm::normalize(scene->camera.look_at - scene->camera.position);
}

void ExpectNear(glm::vec3 got, glm::vec3 expected, const std::string& what) {
  EXPECT_NEAR(got.x, expected.x, 1e-6f) << what;
  EXPECT_NEAR(got.y, expected.y, 1e-6f) << what;
  EXPECT_NEAR(got.z, expected.z, 1e-6f) << what;
}

// The compass (core/compass.h): clockwise from north (-z) toward east (+x), seen from above.
TEST(SceneCamera, YawAndPitchSetLookAt) {
  ExpectNear(ViewOf(R"({"yaw_deg": 0, "pitch_deg": 0})"), {0, 0, -1}, "yaw 0 looks north (-z)");
  ExpectNear(ViewOf(R"({"yaw_deg": 90, "pitch_deg": 0})"), {1, 0, 0}, "yaw 90 looks east (+x)");
  ExpectNear(ViewOf(R"({"yaw_deg": 180, "pitch_deg": 0})"), {0, 0, 1}, "yaw 180 looks south (+z)");
  const float h = std::sqrt(0.5f);
  ExpectNear(ViewOf(R"({"yaw_deg": 45, "pitch_deg": 0})"), {h, 0, -h}, "yaw 45 looks north-east");
  ExpectNear(ViewOf(R"({"yaw_deg": -90, "pitch_deg": 0})"), {-1, 0, 0}, "yaw -90 = 270 looks west");
  ExpectNear(ViewOf(R"({"yaw_deg": 270, "pitch_deg": 0})"), {-1, 0, 0}, "yaw 270 looks west");
  ExpectNear(ViewOf(R"({"yaw_deg": 37, "pitch_deg": -90})"), {0, -1, 0}, "pitch -90 looks straight down");
  ExpectNear(ViewOf(R"({"yaw_deg": 0, "pitch_deg": 90})"), {0, 1, 0}, "pitch 90 looks straight up");
  const float c = std::sqrt(0.5f);
  ExpectNear(ViewOf(R"({"yaw_deg": 0, "pitch_deg": 45})"), {0, c, -c}, "pitch up is positive");
  ExpectNear(ViewOf(R"({"yaw_deg": 90, "pitch_deg": -30})"), {std::cos(glm::radians(30.f)), -0.5f, 0},
             "east and 30 degrees down");
}

TEST(SceneCamera, YawAndPitchLookFromThePosition) {
  Result<Scene> scene = parse_scene(
      json::parse(R"({"camera": {"position": [100000, 5, -100000], "yaw_deg": 90, "pitch_deg": 0}})"),
      kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const glm::vec3 offset = scene->camera.look_at - scene->camera.position;
  EXPECT_GT(offset.x, 0.f);
  // Far from the origin the offset grows with the distance, so float rounding keeps the direction.
  ExpectNear(glm::normalize(offset), {1, 0, 0}, "from a distant position");
  scene = parse_scene(json::parse(R"({"camera": {"yaw_deg": 0, "pitch_deg": 0}})"), kSource);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->camera.position, glm::vec3(0.f, 6.f, -40.f));  // the default position is kept
}

TEST(SceneCamera, LookAtAndAnglesTogetherIsAnError) {
  const std::string message =
      ParseError(R"({"camera": {"look_at": [0, 0, 10], "yaw_deg": 90, "pitch_deg": 0}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: camera.look_at: must be left out when yaw_deg or pitch_deg is given; "
                       "both aim the camera; keep either look_at or yaw_deg and pitch_deg"));
  EXPECT_TRUE(Contains(ParseError(R"({"camera": {"look_at": [0, 0, 10], "yaw_deg": 90}})"),
                       "camera.look_at: must be left out when yaw_deg or pitch_deg is given"));
}

TEST(SceneCamera, YawAndPitchComeTogether) {
  std::string message = ParseError(R"({"camera": {"yaw_deg": 90}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: camera.pitch_deg: must be given with yaw_deg; got yaw_deg "
                       "alone; add pitch_deg"));
  message = ParseError(R"({"camera": {"pitch_deg": -10}})");
  EXPECT_TRUE(Contains(message,
                       "scenes/x.json: camera.yaw_deg: must be given with pitch_deg; got pitch_deg "
                       "alone; add yaw_deg"));
  // A given but bad angle is reported as such, not also as missing.
  message = ParseError(R"({"camera": {"yaw_deg": "east", "pitch_deg": 0}})");
  EXPECT_TRUE(Contains(message,
                       "camera.yaw_deg: expected a number, got string \"east\"; allowed: number -360 "
                       "to 360 deg"));
  EXPECT_FALSE(Contains(message, "must be given"));
}

// ---- World blocks in files: paths and overrides ----

TEST_F(SceneFileTest, RelativeFilesAreResolvedAgainstTheSceneFolder) {
  fs::create_directories(dir_ / "bay");
  const fs::path absolute = dir_ / "models" / "rock.glb";
  const fs::path path = Write("bay/bay.json", R"({
    "seafloor": {"type": "gltf", "file": "floor/bay.glb", "texture": "../textures/sand.png"},
    "objects": [{"file": "buoy.gltf"}, {"file": )" +
                                                  json(absolute.string()).dump() + R"(}],
    "water": {"type": "custom", "table": "water.csv"}
  })");
  Result<Scene> scene = load_scene(path);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  // Missing files are not an error here: the renderer reports them with the resolved name.
  EXPECT_EQ(scene->seafloor.file, (dir_ / "bay" / "floor/bay.glb").string());
  EXPECT_EQ(scene->seafloor.texture, (dir_ / "bay" / "../textures/sand.png").string());
  ASSERT_EQ(scene->objects.size(), 2u);
  EXPECT_EQ(scene->objects[0].file, (dir_ / "bay" / "buoy.gltf").string());
  EXPECT_EQ(scene->objects[1].file, absolute.string());  // absolute paths are kept
  EXPECT_EQ(scene->water.table, (dir_ / "bay" / "water.csv").string());

  const fs::path plain = Write("plain.json", "{}");
  scene = load_scene(plain);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->seafloor.texture, "");  // "" means "none", not the scene's folder
  EXPECT_EQ(scene->seafloor.file, "");
}

TEST_F(SceneFileTest, OverridesWorldBlocks) {
  const fs::path path = Write("s.json", R"({"seafloor": {"type": "gltf", "file": "bay.glb"},
      "objects": [{"file": "old.glb"}, {"file": "older.glb"}]})");
  const std::vector<std::string> overrides = {"seafloor.type=slope",
                                              "seafloor.file=",
                                              "seafloor.near=[10,20]",
                                              R"(objects=[{"file":"a.gltf"}])",
                                              R"(lights=[{"position":[0,2,0],"intensity":5}])",
                                              "render.tone_map=clamp",
                                              "render.effects.foam=false",
                                              "camera.look_at=[0,0,100]"};
  Result<Scene> scene = load_scene(path, overrides);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->seafloor.type, scene::SeafloorType::Slope);
  EXPECT_EQ(scene->seafloor.file, "");
  EXPECT_EQ(scene->seafloor.near, glm::vec2(10.f, 20.f));
  ASSERT_EQ(scene->objects.size(), 1u);  // the override replaces the file's list
  EXPECT_EQ(scene->objects[0].file, (dir_ / "a.gltf").string());
  ASSERT_EQ(scene->lights.size(), 1u);
  EXPECT_FLOAT_EQ(scene->lights[0].intensity, 5.f);
  EXPECT_EQ(scene->render.tone_map, ToneMap::Clamp);
  EXPECT_FALSE(scene->render.effects.foam);
  EXPECT_TRUE(scene->render.effects.reflection);
}

TEST_F(SceneFileTest, WorldOverrideValuesAreValidated) {
  const fs::path path = Write("s.json", R"({"camera": {"look_at": [0, 0, 1]}})");
  const std::vector<std::string> overrides = {"seafloor.type=slope", "seafloor.file=bay.glb",
                                              R"(objects=[{"name":"boat"}])", "camera.yaw_deg=90",
                                              "camera.pitch_deg=0"};
  const std::string message = ErrorOf(load_scene(path, overrides));
  EXPECT_TRUE(Contains(message, path.string() + ": seafloor.file: must be left out when type is \"slope\""));
  EXPECT_TRUE(Contains(message, "(value from --set seafloor.file=bay.glb)"));
  EXPECT_TRUE(Contains(message, "objects[0].file: must be a file name (required)"));
  EXPECT_TRUE(Contains(message, R"((value from --set objects=[{"name":"boat"}]))"));
  // The file's look_at still aims the camera; the angles cannot silently override it.
  EXPECT_TRUE(Contains(message, "camera.look_at: must be left out when yaw_deg or pitch_deg is given"));
}

// ---- Helpers ----

TEST(JsonFields, ClosestMatch) {
  const std::vector<std::string> fields = {"position", "look_at", "fov_deg", "near_m", "far_m"};
  EXPECT_EQ(closest_match("fov_dge", fields), "fov_deg");
  EXPECT_EQ(closest_match("FOV_DEG", fields), "fov_deg");
  EXPECT_EQ(closest_match("fov", fields), "fov_deg");
  EXPECT_EQ(closest_match("lookat", fields), "look_at");
  EXPECT_EQ(closest_match("colour", fields), "");
}

TEST(JsonFields, BoundsDescribe) {
  EXPECT_EQ(Bounds::between(1, 170).describe(), "1 to 170");
  EXPECT_EQ(Bounds::above(0).describe(), "> 0");
  EXPECT_EQ(Bounds::at_least(0.5).describe(), ">= 0.5");
  EXPECT_EQ(Bounds::above_up_to(0, 60).describe(), "> 0 and <= 60");
  EXPECT_FALSE(Bounds::above_up_to(0, 60).contains(0));
  EXPECT_TRUE(Bounds::above_up_to(0, 60).contains(60));
  EXPECT_EQ(Bounds::any().describe(), "any");
}

TEST(JsonFields, FormatNumber) {
  EXPECT_EQ(format_number(0.1f), "0.1");
  EXPECT_EQ(format_number(5000), "5000");
  EXPECT_EQ(format_number(4294967295.0), "4294967295");  // not 4.29497e+09
  EXPECT_EQ(format_number(-3), "-3");
  EXPECT_EQ(format_number(1e300), "1e+300");
}

// A generic array of blocks, as later "objects" and "lights" arrays will use it.
struct Item {
  float size = 1.f;
  uint32_t count = 2;
};
struct Shelf {
  std::vector<Item> items;  // the test fills the defaults (an initializer list here trips a GCC 12 warning)
};
void read_item(ObjectReader& r, Item& i) {
  r.number("size", i.size, Bounds::above(0), "m", "Size.");
  r.integer("count", i.count, Bounds::between(1, 9), "", "Count.");
}
void read_shelf(ObjectReader& r, Shelf& s) {
  r.array("items", s.items, 2, 2, read_item, "Exactly two.");
  for (size_t i = 1; i < s.items.size(); ++i) {
    r.rule("items[" + std::to_string(i) + "].count", s.items[i].count != s.items[i - 1].count,
           "different from the previous count", "change one");
  }
}

TEST(JsonFields, ArrayOfBlocks) {
  std::vector<FieldInfo> fields;
  Shelf defaults;
  defaults.items.push_back({3.f, 4});
  defaults.items.push_back({5.f, 6});  // two elements, so the rule loop runs once while describing
  ObjectReader describe("shelf", fields);
  read_shelf(describe, defaults);
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].path, "shelf.items");
  EXPECT_EQ(fields[0].type, "array of objects");
  EXPECT_EQ(fields[0].default_value, R"([{"size":3,"count":4},{"size":5,"count":6}])");
  EXPECT_EQ(fields[0].range, "2 to 2 elements");
  EXPECT_EQ(fields[1].path, "shelf.items[].size");
  EXPECT_EQ(fields[1].default_value, "1");  // an element's fields default to a default-constructed Item
  EXPECT_EQ(fields[2].path, "shelf.items[].count");
  EXPECT_EQ(fields[2].range, "1 to 9, different from the previous count");

  Diagnostics diag(kSource);
  Shelf shelf;
  json document = {{"items", json::parse(R"([{"size": 2}, {"count": 7}])")}};
  ObjectReader reader(document, "shelf", diag);
  read_shelf(reader, shelf);
  reader.finish();
  ASSERT_TRUE(diag.ok()) << diag.to_error().message;
  ASSERT_EQ(shelf.items.size(), 2u);
  EXPECT_EQ(shelf.items[0].size, 2.f);
  EXPECT_EQ(shelf.items[0].count, 2u);
  EXPECT_EQ(shelf.items[1].count, 7u);

  document = {{"items", json::parse(R"([{"count": 3}, {"count": 3}, {"size": 0}])")}};
  ObjectReader bad(document, "shelf", diag);
  read_shelf(bad, shelf);
  bad.finish();
  const std::string message = diag.to_error().message;
  EXPECT_TRUE(Contains(message, "shelf.items: has 3 elements; allowed: an array of 2 to 2 objects"));
  EXPECT_TRUE(Contains(message, "shelf.items[2].size: 0 is out of range"));
  EXPECT_TRUE(Contains(message, "shelf.items[1].count: must be different from the previous count"));
}

// A block using the field kinds the scene does not use yet.
struct Extra {
  bool enabled = false;
  std::string name = "reef";
};
void read_extra(ObjectReader& r, Extra& e) {
  r.flag("enabled", e.enabled, "Switch.");
  r.text("name", e.name, "Label.");
}

TEST(JsonFields, FlagAndText) {
  Diagnostics diag(kSource);
  Extra extra;
  json document = {{"enabled", true}, {"name", "atoll"}};
  ObjectReader reader(document, "extra", diag);
  read_extra(reader, extra);
  reader.finish();
  EXPECT_TRUE(diag.ok());
  EXPECT_TRUE(extra.enabled);
  EXPECT_EQ(extra.name, "atoll");

  document = {{"enabled", "yes"}, {"name", 3}};
  ObjectReader bad(document, "extra", diag);
  read_extra(bad, extra);
  bad.finish();
  const std::string message = diag.to_error().message;
  EXPECT_TRUE(Contains(message, "scenes/x.json: extra.enabled: expected true or false, got string \"yes\""));
  EXPECT_TRUE(Contains(message, "scenes/x.json: extra.name: expected a string, got 3"));

  std::vector<FieldInfo> fields;
  ObjectReader describe("extra", fields);
  read_extra(describe, extra);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[1].path, "extra.name");
  EXPECT_EQ(fields[1].type, "string");
}

// ---- Repository files ----

TEST(SceneRepository, DefaultSceneLoads) {
  const fs::path path = fs::path(LAGOON_SOURCE_DIR) / "scenes" / "default.json";
  Result<Scene> scene = load_scene(path);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_GT(scene->camera.position.y, 1.f);  // above the water, looking out toward the horizon
  EXPECT_GT(scene->camera.far_m, 8000.f);    // horizon from 5 m is ~8 km away
  EXPECT_FALSE(scene->ocean.cascades.empty());
}

// The reference table in the docs is generated from the same declarations the parser uses.
TEST(SceneRepository, DocsFieldReferenceIsUpToDate) {
  const std::string docs = ReadText(fs::path(LAGOON_SOURCE_DIR) / "docs" / "scene-format.md");
  const std::string begin = "<!-- BEGIN FIELD REFERENCE";
  const std::string end = "<!-- END FIELD REFERENCE -->";
  const size_t b = docs.find(begin), e = docs.find(end);
  ASSERT_NE(b, std::string::npos) << "docs/scene-format.md lacks the field reference markers";
  ASSERT_NE(e, std::string::npos);
  const size_t table_start = docs.find('\n', b) + 1;
  const std::string expected = to_markdown_table(scene_fields());
  if (const char* update = std::getenv("LAGOON_UPDATE_DOCS"); update && std::string(update) == "1") {
    std::ofstream(fs::path(LAGOON_SOURCE_DIR) / "docs" / "scene-format.md", std::ios::trunc)
        << docs.substr(0, table_start) << expected << docs.substr(e);
    std::printf("[ DOCS     ] rewrote the field reference in docs/scene-format.md\n");
    return;
  }
  EXPECT_EQ(docs.substr(table_start, e - table_start), expected)
      << "The field reference in docs/scene-format.md is out of date: run `make update-docs`";
}

TEST(SceneRepository, DocsExampleIsValid) {
  const std::string docs = ReadText(fs::path(LAGOON_SOURCE_DIR) / "docs" / "scene-format.md");
  const size_t start = docs.find("```json\n");
  ASSERT_NE(start, std::string::npos);
  const size_t end = docs.find("```", start + 8);
  const std::string example = docs.substr(start + 8, end - start - 8);
  const json document = json::parse(example, nullptr, /*allow_exceptions=*/false);
  ASSERT_FALSE(document.is_discarded()) << example;
  Result<Scene> scene = parse_scene(document, "docs example");
  EXPECT_TRUE(scene.ok()) << scene.error().message;
}

}  // namespace
}  // namespace lagoon::scene

namespace lagoon::scene {
namespace {

TEST(SceneOverrideIndex, SetsAnElementOfAnArrayTheFileHas) {
  nlohmann::json doc = nlohmann::json::parse(
      R"({"ocean": {"cascades": [{"patch_size_m": 1000, "resolution": 256}, {"patch_size_m": 100, "resolution": 256}]}})");
  ASSERT_TRUE(apply_override(doc, "ocean.cascades[1].resolution=128"));
  EXPECT_EQ(doc["ocean"]["cascades"][1]["resolution"], 128);
  EXPECT_EQ(doc["ocean"]["cascades"][0]["resolution"], 256);
  ASSERT_TRUE(apply_override(doc, R"(ocean.cascades[0]={"patch_size_m": 800, "resolution": 64})"));
  EXPECT_EQ(doc["ocean"]["cascades"][0]["patch_size_m"], 800);
  auto past_end = apply_override(doc, "ocean.cascades[2].resolution=64");
  ASSERT_FALSE(past_end);
  EXPECT_NE(past_end.error().message.find("has 2 element(s)"), std::string::npos) << past_end.error().message;
  auto parsed = parse_scene(doc, "x.json");
  ASSERT_TRUE(parsed) << parsed.error().message;
  EXPECT_EQ(parsed->ocean.cascades[1].resolution, 128u);
}

}  // namespace
}  // namespace lagoon::scene
