// lagoon bench: usage errors, and the render, compute and bodies benchmarks' reports (figures are not
// asserted: speed is measured, never tested).
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

TEST(BenchCli, UsageErrorsExit2) {
  for (const char* args : {"bench", "bench nope", "bench compute --rounds 0", "bench render --rounds x"})
    EXPECT_EQ(lagoon(args).exit_code, 2) << args;
  struct Case {
    const char* args;
    const char* expected;
  } cases[] = {
      {"bench render --width 0", "--width 0 must be a whole number from 16 to 8192"},
      {"bench render --height 8193", "--height 8193 must be a whole number from 16 to 8192"},
      {"bench render --width 64.5", "--width 64.5"},
      {"bench compute --width 64", "--width applies to 'bench render' only"},
  };
  for (const Case& c : cases) {
    auto r = lagoon(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
}

// The "context" both reports share: enough to tell which device and driver the figures come from.
void expect_device_context(const nlohmann::json& context) {
  for (const char* key : {"device", "device_type", "driver_name", "driver_info", "driver_version"}) {
    ASSERT_TRUE(context.contains(key) && context[key].is_string()) << key << " in " << context;
    EXPECT_FALSE(context[key].get<std::string>().empty()) << key << " in " << context;
  }
  ASSERT_TRUE(context.contains("vulkan_api_version")) << context;
  EXPECT_TRUE(
      std::regex_match(context["vulkan_api_version"].get<std::string>(), std::regex(R"(1\.\d+\.\d+)")))
      << context;
}

// real_time is the median of `rounds` figures, between their min and max.
void expect_spread(const nlohmann::json& entry, int rounds, const char* measure) {
  EXPECT_EQ(entry["iterations"], rounds) << entry;
  EXPECT_EQ(entry["measure"], measure) << entry;
  EXPECT_EQ(entry["time_unit"], "ms") << entry;
  const double median = entry["real_time"], min = entry["min_time"], max = entry["max_time"];
  EXPECT_LE(min, median) << entry;
  EXPECT_LE(median, max) << entry;
  EXPECT_GE(min, 0.0) << entry;
}

TEST(BenchCli, RenderReportsEveryPassAndTheFrameAtTheGivenSize) {
  TempDir dir;
  const std::string json = (dir / "bench.json").string();
  auto r = lagoon("bench render --rounds 3 --width 64 --height 32 --scene " + std::string(LAGOON_SOURCE_DIR) +
                  "/scenes/default.json --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("at 64x32"), std::string::npos) << r.output;
  std::ifstream file(json);
  const auto doc = nlohmann::json::parse(file);
  expect_device_context(doc["context"]);
  EXPECT_EQ(doc["context"]["width"], 64) << doc["context"];
  EXPECT_EQ(doc["context"]["height"], 32) << doc["context"];
  EXPECT_EQ(doc["context"]["rounds"], 3) << doc["context"];
  EXPECT_NE(doc["context"]["scene"].get<std::string>().find("default.json"), std::string::npos);

  std::vector<std::string> names;
  for (const auto& b : doc["benchmarks"]) {
    names.push_back(b["name"]);
    const std::string name = b["name"];
    const bool wall = name == "render/frame" || name.rfind("render/water_colour/", 0) == 0;
    expect_spread(b, 3, wall ? "wall" : "gpu timestamps");
  }
  // The water colour's share: the physical frame against the same frame shaded blinn-phong (issue 16).
  ASSERT_TRUE(doc["context"]["water_colour_share_of_frame"].is_number()) << doc["context"];
  EXPECT_LT(std::abs(doc["context"]["water_colour_share_of_frame"].get<double>()), 1.0);
  for (const char* expected : {"render/pass/refraction", "render/pass/reflection", "render/pass/sky",
                               "render/pass/surface", "render/frame", "render/water_colour/frame_physical",
                               "render/water_colour/frame_blinn_phong", "render/water_colour/lut_build"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected << "\n" << r.output;
}

// A stand-in for an older build: records the arguments it was given and writes a bench render report with
// known figures (frame 1000 ms, surface 500 ms), so what --baseline prints is checked against numbers the
// test chose, not against another measurement.
std::string fake_baseline(const TempDir& dir, const std::string& body) {
  const std::string path = (dir / "old-lagoon").string();
  std::ofstream(path) << "#!/bin/sh\necho \"$@\" >> " << (dir / "args.txt").string() << "\n" << body;
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path;
}

TEST(BenchCli, BaselineRunsTheOtherBuildSideBySideAndPrintsRatios) {
  TempDir dir;
  const std::string old_build =
      fake_baseline(dir,
                    "while [ $# -gt 0 ]; do [ \"$1\" = --json ] && out=$2; shift; done\n"
                    "printf '{\"context\":{},\"benchmarks\":[{\"name\":\"render/frame\","
                    "\"real_time\":1000},{\"name\":\"render/pass/surface\",\"real_time\":500}]}' "
                    "> \"$out\"\n");
  const std::string json = (dir / "ratios.json").string(),
                    scene = std::string(LAGOON_SOURCE_DIR) + "/scenes/open-ocean.json";
  auto r = lagoon("bench render --baseline " + old_build + " --scene " + scene +
                  " --width 32 --height 18 --rounds 2 --set time_s=2 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream args_file(dir / "args.txt");
  const std::string given((std::istreambuf_iterator<char>(args_file)), std::istreambuf_iterator<char>());
  for (const std::string& expected : {"bench render --scene " + scene + " --width 32 --height 18 --rounds 2",
                                      std::string("--set time_s=2")})
    EXPECT_NE(given.find(expected), std::string::npos) << given;
  const auto doc = nlohmann::json::parse(std::ifstream(json));
  EXPECT_EQ(doc["context"]["baseline"], old_build);
  std::map<std::string, nlohmann::json> rows;
  for (const auto& b : doc["benchmarks"]) rows[b["name"]] = b;
  ASSERT_TRUE(rows.count("baseline/open-ocean/frame") && rows.count("baseline/open-ocean/pass/surface"))
      << doc.dump(1);
  const auto& frame = rows["baseline/open-ocean/frame"];
  const auto& surface = rows["baseline/open-ocean/pass/surface"];
  EXPECT_EQ(frame["baseline_ms"].get<double>(), 1000.0);
  EXPECT_EQ(surface["baseline_ms"].get<double>(), 500.0);
  EXPECT_GT(frame["this_ms"].get<double>(), 0.0);
  EXPECT_NEAR(frame["ratio"].get<double>(), frame["this_ms"].get<double>() / 1000.0, 1e-12);
  EXPECT_NEAR(surface["ratio"].get<double>(), surface["this_ms"].get<double>() / 500.0, 1e-12);
  EXPECT_NEAR(doc["context"]["frame_ratio_geometric_mean"].get<double>(), frame["ratio"].get<double>(),
              1e-12);
  EXPECT_NE(r.output.find("open-ocean frame (wall)"), std::string::npos) << r.output;
  // Only passes both builds report get a row: this build's other passes have no baseline figure.
  EXPECT_FALSE(rows.count("baseline/open-ocean/pass/refraction")) << doc.dump(1);
}

// Without --scene every scenes/*.json is compared; one the older build cannot read (a newer scene) is skipped
// with its message and left out of the mean, while the others still give ratios.
TEST(BenchCli, BaselineSkipsAShippedSceneItCannotRender) {
  TempDir dir;
  const std::filesystem::path scenes = dir / "work" / "scenes";
  std::filesystem::create_directories(scenes);
  for (const char* name : {"a.json", "b.json"})
    std::filesystem::copy_file(std::string(LAGOON_SOURCE_DIR) + "/scenes/open-ocean.json", scenes / name);
  const std::string old_build =
      fake_baseline(dir,
                    "case \"$*\" in *b.json*) echo 'b.json: ocean.new_field: unknown field'; exit 1;; esac\n"
                    "while [ $# -gt 0 ]; do [ \"$1\" = --json ] && out=$2; shift; done\n"
                    "printf '{\"context\":{},\"benchmarks\":[{\"name\":\"render/frame\","
                    "\"real_time\":1000}]}' > \"$out\"\n");
  const std::string json = (dir / "ratios.json").string();
  auto r = run_process("cd " + shell_quote((dir / "work").string()) + " && " + shell_quote(LAGOON_BINARY) +
                       " bench render --baseline " + old_build +
                       " --width 32 --height 18 --rounds 1 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("skipping scenes/b.json, which the baseline cannot render"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("ocean.new_field: unknown field"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 of 2 scenes skipped"), std::string::npos) << r.output;
  const auto doc = nlohmann::json::parse(std::ifstream(json));
  std::map<std::string, nlohmann::json> rows;
  for (const auto& b : doc["benchmarks"]) rows[b["name"]] = b;
  ASSERT_TRUE(rows.count("baseline/a/frame") && rows.count("baseline/b/frame")) << doc.dump(1);
  EXPECT_TRUE(rows["baseline/b/frame"].contains("skipped")) << doc.dump(1);
  EXPECT_FALSE(rows["baseline/b/frame"].contains("ratio")) << doc.dump(1);
  // The mean is a's ratio alone: b has none to count.
  EXPECT_NEAR(doc["context"]["frame_ratio_geometric_mean"].get<double>(),
              rows["baseline/a/frame"]["ratio"].get<double>(), 1e-12);
  EXPECT_EQ(doc["context"]["scenes_skipped"], 1);
}

// --baseline-scenes DIR: the older build renders the scene of the same name there (as its commit had it),
// this build its own; a folder that is not there is a usage error.
TEST(BenchCli, BaselineScenesGiveTheOlderBuildItsOwnScene) {
  TempDir dir;
  std::filesystem::create_directories(dir / "old-scenes");
  const std::string old_build =
      fake_baseline(dir,
                    "while [ $# -gt 0 ]; do [ \"$1\" = --json ] && out=$2; shift; done\n"
                    "printf '{\"context\":{},\"benchmarks\":[{\"name\":\"render/frame\","
                    "\"real_time\":1000}]}' > \"$out\"\n");
  const std::string scene = std::string(LAGOON_SOURCE_DIR) + "/scenes/open-ocean.json";
  const std::string old_scene = (dir / "old-scenes" / "open-ocean.json").string();
  auto r = lagoon("bench render --baseline " + old_build + " --baseline-scenes " +
                  (dir / "old-scenes").string() + " --scene " + scene + " --width 32 --height 18 --rounds 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream args_file(dir / "args.txt");
  const std::string given((std::istreambuf_iterator<char>(args_file)), std::istreambuf_iterator<char>());
  EXPECT_NE(given.find("--scene " + old_scene + " "), std::string::npos) << given;
  EXPECT_EQ(given.find("--scene " + scene), std::string::npos) << given;
  EXPECT_NE(r.output.find("open-ocean frame (wall)"), std::string::npos) << r.output;
  auto missing = lagoon("bench render --baseline " + old_build + " --baseline-scenes " +
                        (dir / "nope").string() + " --scene " + scene);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("--baseline-scenes " + (dir / "nope").string() + ": no such folder"),
            std::string::npos)
      << missing.output;
}

TEST(BenchCli, BaselineThatIsMissingOrFailsIsNamed) {
  TempDir dir;
  const std::string scene = " --scene " + std::string(LAGOON_SOURCE_DIR) + "/scenes/open-ocean.json";
  auto missing = lagoon("bench render --baseline " + (dir / "nope").string() + scene);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("no such program; build the older commit"), std::string::npos)
      << missing.output;
  const std::string failing = fake_baseline(dir, "echo 'boom: no device'\nexit 1\n");
  auto r = lagoon("bench render --baseline " + failing + scene + " --width 32 --height 18 --rounds 1");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("boom: no device"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("failed (exit 1)"), std::string::npos) << r.output;
  auto wrong = lagoon("bench compute --baseline " + failing);
  EXPECT_EQ(wrong.exit_code, 2) << wrong.output;
  EXPECT_NE(wrong.output.find("--baseline applies to 'bench render' only"), std::string::npos)
      << wrong.output;
}

TEST(BenchCli, ComputeReportsWallAndGpuTimeOfTheStep) {
  TempDir dir;
  const std::string json = (dir / "bench.json").string();
  auto r = lagoon("bench compute --rounds 1 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream file(json);
  const auto doc = nlohmann::json::parse(file);
  expect_device_context(doc["context"]);
  EXPECT_EQ(doc["context"]["rounds"], 1) << doc["context"];
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& b : doc["benchmarks"]) by_name[b["name"]] = b;
  for (const char* config : {"/N=128/cascades=1", "/N=512/cascades=3"}) {
    const std::string wall = std::string("ocean_step/gpu") + config,
                      device = std::string("ocean_step/gpu_timestamps") + config;
    ASSERT_TRUE(by_name.count(wall)) << wall << "\n" << r.output;
    ASSERT_TRUE(by_name.count(device)) << device << "\n" << r.output;
    expect_spread(by_name[wall], 1, "wall");
    expect_spread(by_name[device], 1, "gpu timestamps");
    // The step's device time is inside the wall time around its submit and wait.
    EXPECT_LE(by_name[device]["real_time"].get<double>(), by_name[wall]["real_time"].get<double>()) << config;
    EXPECT_GT(by_name[device]["real_time"].get<double>(), 0.0) << config;
  }
}

// bench bodies: the harbour's bodies per 60 Hz frame with and without the wakes felt; a scene with nothing
// that floats is refused with a hint.
TEST(BenchCli, BodiesReportsTheFrameCostWithAndWithoutWakes) {
  TempDir dir;
  const std::string json = (dir / "bodies.json").string();
  const std::string harbour = std::string(LAGOON_SOURCE_DIR) + "/scenes/harbour.json";
  auto r = lagoon("bench bodies --scene " + harbour + " --rounds 1 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream file(json);
  const auto doc = nlohmann::json::parse(file);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& b : doc["benchmarks"]) by_name[b["name"]] = b;
  for (const char* name :
       {"bodies/frame_mean/as_scene", "bodies/frame_worst/as_scene", "bodies/frame_mean/without_wakes",
        "bodies/frame_worst/without_wakes", "bodies/paced_mean/as_scene", "bodies/paced_worst/as_scene",
        "bodies/paced_mean/without_wakes", "bodies/paced_worst/without_wakes"}) {
    ASSERT_TRUE(by_name.count(name)) << name << "\n" << r.output;
    expect_spread(by_name[name], 1, "wall");
  }
  for (const char* pace : {"frame", "paced"})
    EXPECT_LE(by_name[std::string("bodies/") + pace + "_mean/as_scene"]["real_time"].get<double>(),
              by_name[std::string("bodies/") + pace + "_worst/as_scene"]["real_time"].get<double>());
  auto none =
      lagoon("bench bodies --scene " + std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json --rounds 1");
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find("has no floating object or vehicle; try scenes/harbour.json"), std::string::npos)
      << none.output;
  EXPECT_EQ(lagoon("bench bodies --width 64").exit_code, 2);
}

}  // namespace
}  // namespace lagoon::test
