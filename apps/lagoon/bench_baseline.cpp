#include "bench_baseline.h"

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bench_report.h"
#include "child_process.h"
#include "exit_codes.h"

namespace lagoon::cli {
namespace {

namespace fs = std::filesystem;

// A folder for the runs' reports and output, removed with it.
struct WorkDir {
  fs::path path;
  WorkDir() {
    std::error_code ec;
    std::string pattern = (fs::temp_directory_path(ec) / "lagoon-bench-baseline-XXXXXX").string();
    if (mkdtemp(pattern.data())) path = pattern;
  }
  ~WorkDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
};

// A build's medians for one scene: the frame's wall time and each pass's GPU time, in ms.
struct BuildTimes {
  double frame = 0;
  std::map<std::string, double> passes;
};

std::optional<std::string> usable_program(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    return "--baseline " + path +
           ": no such program; build the older commit beside this one (git worktree add ../lagoon-base "
           "<commit>, then cmake --build there with --target lagoon) and pass its bin/lagoon";
  if (access(path.c_str(), X_OK) != 0) return "--baseline " + path + ": not executable (chmod +x it)";
  return std::nullopt;
}

// The scenes to compare: --scene, or every shipped scene (scenes/*.json under the working directory).
std::vector<std::string> scenes_to_compare(const ParsedArgs& args) {
  if (auto scene = args.get("scene")) return {*scene};
  std::vector<std::string> scenes;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("scenes", ec))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

// The file the baseline renders for `scene`: the same, or with --baseline-scenes DIR the file of that name
// there (the scene as the older commit had it, where its fields have changed since).
std::string baseline_scene(const ParsedArgs& args, const std::string& scene) {
  const auto dir = args.get("baseline-scenes");
  return dir ? (fs::path(*dir) / fs::path(scene).filename()).string() : scene;
}

// Runs `program bench render` on one scene; its report's medians, or why not.
Result<BuildTimes> measure(const std::string& program, const std::string& scene, const ParsedArgs& args,
                           int rounds, long long width, long long height, const fs::path& work) {
  const fs::path json = work / "report.json", log = work / "output.txt";
  std::error_code ec;
  fs::remove(json, ec);
  std::vector<std::string> argv{program,
                                "bench",
                                "render",
                                "--scene",
                                scene,
                                "--width",
                                std::to_string(width),
                                "--height",
                                std::to_string(height),
                                "--rounds",
                                std::to_string(rounds),
                                "--json",
                                json.string()};
  for (const std::string& set : args.all("set")) argv.insert(argv.end(), {"--set", set});
  auto status = run_child(argv, log);
  if (!status) return status.error();
  std::ifstream in(json);
  if (*status != 0 || !in) {
    std::ifstream out(log);
    const std::string text((std::istreambuf_iterator<char>(out)), std::istreambuf_iterator<char>());
    return Error{program + " bench render --scene " + scene + " failed (exit " + std::to_string(*status) +
                 "):\n" + text};
  }
  BuildTimes times;
  try {
    const nlohmann::json doc = nlohmann::json::parse(in);
    for (const nlohmann::json& b : doc.at("benchmarks")) {
      const std::string name = b.at("name");
      const double ms = b.at("real_time");
      if (name == "render/frame") times.frame = ms;
      if (name.rfind("render/pass/", 0) == 0) times.passes[name.substr(12)] = ms;
    }
  } catch (const std::exception& e) {
    return Error{program + " wrote a report that is not bench render's (" + e.what() + "): " + json.string()};
  }
  if (times.frame <= 0) return Error{program + "'s report has no render/frame time: " + json.string()};
  return times;
}

void print_row(const std::string& name, double base, double ours) {
  std::printf("  %-26s %12.2f %12.2f %8.2f\n", name.c_str(), base, ours, base > 0 ? ours / base : 0.0);
}

}  // namespace

int run_bench_baseline(const ParsedArgs& args, int rounds, long long width, long long height) {
  const std::string baseline = *args.get("baseline");
  // This build is measured by running its own executable again, which only the `lagoon` command is (the
  // Python module's lagoon.run() runs in the interpreter's process).
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  if (fs::path(self).filename() != "lagoon") {
    std::fprintf(
        stderr,
        "lagoon bench render: --baseline runs this build's `lagoon` executable beside the other one, "
        "and this process is %s, not `lagoon`; run `lagoon bench render --baseline ...` from a shell\n",
        self.c_str());
    return kExitUsage;
  }
  if (auto why = usable_program(baseline)) {
    std::fprintf(stderr, "lagoon bench render: %s\n", why->c_str());
    return kExitUsage;
  }
  if (const auto dir = args.get("baseline-scenes"); dir && !fs::is_directory(*dir)) {
    std::fprintf(stderr,
                 "lagoon bench render: --baseline-scenes %s: no such folder; pass the older checkout's "
                 "scenes folder (e.g. ../lagoon-base/scenes)\n",
                 dir->c_str());
    return kExitUsage;
  }
  const std::vector<std::string> scenes = scenes_to_compare(args);
  if (scenes.empty()) {
    std::fprintf(stderr,
                 "lagoon bench render: --baseline without --scene compares every scenes/*.json, and there "
                 "is no scenes folder here; run it from Lagoon's source folder or pass --scene FILE\n");
    return kExitUsage;
  }
  const WorkDir work;
  if (work.path.empty()) {
    std::fprintf(stderr, "lagoon bench render: cannot make a folder under %s for the runs' reports\n",
                 fs::temp_directory_path().c_str());
    return kExitFailure;
  }
  std::printf(
      "this build %s against --baseline %s; %lldx%lld, %d frames a scene and build, medians; ratio = "
      "this / baseline (each build in its own process, their order alternating by scene)\n",
      self.c_str(), baseline.c_str(), width, height, rounds);
  if (const auto dir = args.get("baseline-scenes"))
    std::printf("the baseline renders the scenes of the same name in %s\n", dir->c_str());
  std::printf("  %-26s %12s %12s %8s\n", "scene / pass", "baseline ms", "this ms", "ratio");
  nlohmann::json rows = nlohmann::json::array();
  double log_ratio_sum = 0;
  const bool every_scene = !args.get("scene");
  size_t skipped = 0;
  for (size_t i = 0; i < scenes.size(); ++i) {
    std::fprintf(stderr, "lagoon bench render: [%zu/%zu] %s\n", i + 1, scenes.size(), scenes[i].c_str());
    // ABAB... would favour whichever build runs second on a machine that warms up or throttles.
    const bool base_first = i % 2 == 0;
    const std::string base_scene = baseline_scene(args, scenes[i]);
    auto run = [&](bool base) {
      return measure(base ? baseline : self, base ? base_scene : scenes[i], args, rounds, width, height,
                     work.path);
    };
    Result<BuildTimes> first = run(base_first);
    Result<BuildTimes> second = first ? run(!base_first) : first;
    const std::string name = fs::path(scenes[i]).stem().string();
    const Result<BuildTimes>& base_run = base_first ? first : second;
    // (When this build ran first, its own failure is copied into `second`: that one ends the run below.)
    if (!base_run && every_scene && (base_first || first)) {
      // A scene newer than the older build (a field it does not know): the other scenes still compare.
      std::fprintf(stderr, "lagoon bench render: skipping %s, which the baseline cannot render: %s\n",
                   scenes[i].c_str(), base_run.error().message.c_str());
      std::printf("  %-26s %12s\n", (name + " frame (wall)").c_str(), "skipped: the baseline failed on it");
      rows.push_back({{"name", "baseline/" + name + "/frame"}, {"skipped", base_run.error().message}});
      ++skipped;
      continue;
    }
    if (!first || !second) {
      std::fprintf(stderr, "lagoon bench render: %s\n", (!first ? first : second).error().message.c_str());
      return kExitFailure;
    }
    const BuildTimes& base = base_first ? *first : *second;
    const BuildTimes& ours = base_first ? *second : *first;
    print_row(name + " frame (wall)", base.frame, ours.frame);
    log_ratio_sum += std::log(ours.frame / base.frame);
    rows.push_back({{"name", "baseline/" + name + "/frame"},
                    {"baseline_ms", base.frame},
                    {"this_ms", ours.frame},
                    {"ratio", ours.frame / base.frame}});
    for (const auto& [pass, ms] : ours.passes) {
      const auto other = base.passes.find(pass);
      if (other == base.passes.end() || other->second <= 0) continue;  // a pass the older build lacks
      print_row("  " + pass, other->second, ms);
      rows.push_back({{"name", "baseline/" + name + "/pass/" + pass},
                      {"baseline_ms", other->second},
                      {"this_ms", ms},
                      {"ratio", ms / other->second}});
    }
  }
  const size_t compared = scenes.size() - skipped;
  if (compared == 0) {
    std::fprintf(stderr, "lagoon bench render: the baseline rendered none of the %zu scenes\n",
                 scenes.size());
    return kExitFailure;
  }
  const double mean_ratio = std::exp(log_ratio_sum / double(compared));
  std::printf("  %-26s %12s %12s %8.2f\n", "frames, geometric mean", "", "", mean_ratio);
  if (skipped > 0)
    std::printf("  (%zu of %zu scenes skipped: the baseline could not render them)\n", skipped,
                scenes.size());
  if (auto path = args.get("json")) {
    const nlohmann::json context = {{"baseline", baseline},
                                    {"this", self},
                                    {"width", width},
                                    {"height", height},
                                    {"rounds", rounds},
                                    {"frame_ratio_geometric_mean", mean_ratio},
                                    {"scenes_compared", compared},
                                    {"scenes_skipped", skipped},
                                    {"baseline_scenes", args.get("baseline-scenes").value_or("")}};
    if (!write_report(*path, {{"context", context}, {"benchmarks", rows}})) return kExitFailure;
    std::printf("wrote %s\n", path->c_str());
  }
  return kExitOk;
}

}  // namespace lagoon::cli
