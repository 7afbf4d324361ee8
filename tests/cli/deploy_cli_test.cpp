// The cluster files (deploy/): their own command lines, run here for 4 shards (the Slurm script itself with a
// pass-through srun; the Kubernetes Job's container command through /bin/sh with JOB_COMPLETION_INDEX), give
// exactly the files of one unsharded run. Their sizes are made small through the variables the files read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>

#include "support/edited_scene.h"
#include "support/run_process.h"
#include "support/shared_output.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = LAGOON_SOURCE_DIR;

std::map<std::string, std::string> output_files(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& item : fs::directory_iterator(dir))
    if (item.path().extension() != ".jsonl") files[item.path().filename().string()] = read_file(item.path());
  return files;
}

// A working folder as a cluster node sees the checkout: scenes/ with the shipped assets and path, and a
// harbour without wakes and with 64² cascades (quick: every frame replays the foam, and the wakes like it),
// a `lagoon` and a pass-through `srun` on PATH.
void make_working_folder(const fs::path& dir) {
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "bin");
  fs::create_directory_symlink(kSource / "scenes/assets", dir / "scenes/assets");
  fs::create_directory_symlink(kSource / "scenes/paths", dir / "scenes/paths");
  nlohmann::json harbour = nlohmann::json::parse(read_file(kSource / "scenes/harbour.json"));
  harbour["wakes"] = {{"enabled", false}};
  use_small_cascades(harbour);
  std::ofstream(dir / "scenes/harbour-quick.json") << harbour.dump(2);
  fs::create_symlink(LAGOON_BINARY, dir / "bin/lagoon");
  std::ofstream(dir / "bin/srun") << "#!/bin/sh\nexec \"$@\"\n";
  fs::permissions(dir / "bin/srun", fs::perms::owner_all);
}

// The variables both files read, for a small set: 8 frames 2 s apart along the evaluation flight (above
// the water, through the surface and below it), run in the working folder `dir`.
std::string env(const fs::path& dir, const std::string& out) {
  return "cd " + shell_quote(dir.string()) + " && PATH=" + shell_quote((dir / "bin").string()) +
         ":$PATH SCENE=scenes/harbour-quick.json FRAMES=8 FPS=0.5 WIDTH=64 HEIGHT=36 OUT=" + out + " ";
}

class DeployCli : public ::testing::Test {
 protected:
  void SetUp() override { make_working_folder(dir_.path()); }

  std::string env(const std::string& out) const { return test::env(dir_.path(), out); }

  // The shards' union in `out` (relative to the working folder) is one process's set, byte for byte, and
  // verifies. One process's set is made once for both tests (support/shared_output.h), in a working folder
  // of its own laid out as this one (every path in the files is relative to it).
  void expect_the_set_of_one_process(const std::string& out) {
    const fs::path one = shared_output("deploy: one process's set", [](const fs::path& dir) {
      make_working_folder(dir);
      const ProcessResult r = run_process(test::env(dir, "one") +
                                          "lagoon render --scene scenes/harbour-quick.json --path "
                                          "scenes/paths/evaluation.json --frames 8 --fps 0.5 --width 64 "
                                          "--height 36 --out one/frame.png");
      EXPECT_EQ(r.exit_code, 0) << r.output;
      return r.exit_code == 0;
    });
    ASSERT_FALSE(one.empty());
    const auto expected = output_files(one / "one"), sharded = output_files(dir_ / out);
    ASSERT_EQ(expected.size(), 16u);  // 8 PNGs and their metadata
    ASSERT_EQ(sharded.size(), expected.size());
    for (const auto& [name, bytes] : expected) EXPECT_TRUE(sharded.at(name) == bytes) << name << " differs";
    const ProcessResult v = run_process(env("") + "lagoon dataset verify " + out);
    EXPECT_EQ(v.exit_code, 0) << v.output;
  }

  TempDir dir_;
};

TEST_F(DeployCli, TheSlurmArrayScriptsFourTasksMakeTheSetOfOneProcess) {
  const std::string script = (kSource / "deploy/slurm/render-array.sbatch").string();
  EXPECT_NE(read_file(script).find("#SBATCH --array=0-3"), std::string::npos);
  for (int task = 0; task < 4; ++task) {
    const ProcessResult r =
        run_process(env("slurm") + "SLURM_ARRAY_TASK_ID=" + std::to_string(task) +
                    " SLURM_ARRAY_TASK_COUNT=4 SLURM_SUBMIT_DIR=. bash " + shell_quote(script));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  expect_the_set_of_one_process("slurm");
}

TEST_F(DeployCli, TheKubernetesIndexedJobsFourPodsMakeTheSetOfOneProcess) {
  const std::string yaml = read_file(kSource / "deploy/k8s/render-indexed-job.yaml");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      yaml, m, std::regex(R"(completionMode: Indexed\s+completions: (\d+)\s+parallelism: (\d+))")));
  const std::string completions = m[1];
  EXPECT_EQ(m[2], completions);
  ASSERT_TRUE(std::regex_search(yaml, m, std::regex(R"re(\{name: SHARDS, value: "(\d+)"\})re")));
  EXPECT_EQ(m[1], completions) << "SHARDS must equal completions";
  ASSERT_TRUE(
      std::regex_search(yaml, m, std::regex(R"re(command: \["/bin/sh", "-c"\]\s+args: \["(.*)"\])re")));
  const std::string command = std::regex_replace(std::string(m[1]), std::regex(R"(\\")"), "\"");
  EXPECT_NE(command.find("$JOB_COMPLETION_INDEX/$SHARDS"), std::string::npos) << command;
  EXPECT_NE(yaml.find("mountPath: /lagoon/out"), std::string::npos);
  EXPECT_NE(yaml.find("workingDir: /lagoon"), std::string::npos);
  for (int index = 0; index < std::stoi(completions); ++index) {
    const ProcessResult r = run_process(
        env("out/k8s") + "SHARDS=" + completions + " JOB_COMPLETION_INDEX=" + std::to_string(index) +
        " CAMERA_PATH=" + "scenes/paths/evaluation.json /bin/sh -c " + shell_quote(command));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  expect_the_set_of_one_process("out/k8s");
}

TEST(DeployFiles, TheDockerfileBuildsTheCliWithTheProjectsOwnSetUp) {
  // Docker is not available to the suite; the image's steps are the README's own set-up (checked by the
  // fresh-Debian run), so this pins the file to them.
  const std::string docker = read_file(kSource / "deploy/Dockerfile");
  EXPECT_NE(docker.find("FROM debian:12"), std::string::npos);
  EXPECT_NE(docker.find("bash tools/install-deps.sh"), std::string::npos);
  EXPECT_NE(docker.find("-DCMAKE_BUILD_TYPE=Release"), std::string::npos);
  EXPECT_NE(docker.find("ENTRYPOINT [\"lagoon\"]"), std::string::npos);
  EXPECT_TRUE(fs::exists(kSource / "tools/install-deps.sh"));
}

}  // namespace
}  // namespace lagoon::test
