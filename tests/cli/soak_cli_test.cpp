// lagoon soak, short: both phases run, report their figures and pass on a healthy build; bad options are
// usage errors.
#include <gtest/gtest.h>

#include <regex>

#include "support/run_process.h"

namespace lagoon::test {
namespace {

TEST(SoakCli, AShortSoakChecksEveryStepAndFrameAndIsHealthy) {
  auto r = lagoon(
      "soak --scene " + kDefaultScene +
      " --steps 30 --frames 4 --width 64 --height 36 --set "
      "'ocean.cascades=[{\"patch_size_m\":300,\"resolution\":64},{\"patch_size_m\":30,\"resolution\":64}]' "
      // lavapipe keeps ~58 KB per object draw and ~0.4 MiB per frame inside the driver
      // (docs/reliability.md); over 4 frames measured from the first that is a few per cent of the process,
      // so this short run allows 25 %. The long soak reports the real figure.
      "--set objects=[] --max-growth 25");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::regex_search(
      r.output, std::regex(R"(steps +30 +non-finite texels 0 +RSS after warm-up [0-9.]+ MiB)")))
      << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(frames +4 +non-finite texels 0 )"))) << r.output;
  EXPECT_NE(r.output.find("validation errors 0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("healthy"), std::string::npos) << r.output;
}

TEST(SoakCli, BadCountsAreUsageErrors) {
  for (const char* args : {"--steps -1", "--frames x", "--width 4", "--max-growth -1"}) {
    auto r = lagoon("soak --scene " + kDefaultScene + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace lagoon::test
