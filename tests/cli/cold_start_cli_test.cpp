// A cold first run of `lagoon render` compiles its frame on a second device too (render/cold_compile.h): only
// until the build has drawn on the device once, and the picture is the one a run without it draws.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/png.h"
#include "support/run_process.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSecondDevice = "a second device compiles the frame too";

TEST(ColdStartCli, OnlyABuildsFirstFrameOnTheDeviceHasASecondDeviceAndThePictureIsTheSame) {
  const fs::path dir = fs::path(LAGOON_TEST_ARTIFACTS) / "cli" / "cold-start";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // An empty result cache is a build that has not drawn here yet (the test processes' own is shared).
  const std::string cache =
      "LAGOON_STAGE_TIMES=1 LAGOON_PIPELINE_CACHE=" + shell_quote((dir / "cache").string());
  const std::string args =
      "render --scene " + shell_quote(kDefaultScene) + " --width 96 --height 64 --time 4";
  auto out = [&](const char* name) { return " --out " + shell_quote((dir / name).string()); };

  const ProcessResult first = lagoon(args + out("first.png"), cache);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  // lavapipe only: a GPU's driver compiles when a pipeline is made, on the thread that makes it.
  const bool cpu_device = first.output.find("(CPU)") != std::string::npos;
  EXPECT_EQ(first.output.find(kSecondDevice) != std::string::npos, cpu_device) << first.output;

  const ProcessResult second = lagoon(args + out("second.png"), cache);
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_EQ(second.output.find(kSecondDevice), std::string::npos) << "the first run left no marker\n"
                                                                  << second.output;

  const ProcessResult without =
      lagoon(args + out("without.png"), "LAGOON_STAGE_TIMES=1 LAGOON_COLD_COMPILE=0 LAGOON_PIPELINE_CACHE=" +
                                            shell_quote((dir / "off").string()));
  ASSERT_EQ(without.exit_code, 0) << without.output;
  EXPECT_EQ(without.output.find(kSecondDevice), std::string::npos) << without.output;

  // The second device draws into nothing the first reads: its own targets, no cached result of its own.
  auto pixels = [&](const char* name) {
    auto image = io::read_png((dir / name).string());
    return image ? image->rgba : std::vector<uint8_t>{};
  };
  const auto reference = pixels("without.png");
  ASSERT_FALSE(reference.empty());
  EXPECT_TRUE(pixels("first.png") == reference) << "a cold start's picture differs";
  EXPECT_TRUE(pixels("second.png") == reference) << "a warm run's picture differs";
}

}  // namespace
}  // namespace lagoon::test
