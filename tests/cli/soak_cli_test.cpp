// lagoon soak, short: both phases run, report their figures and pass on a healthy build; bad options are
// usage errors.
#include <gtest/gtest.h>

#include <regex>

#include "support/run_process.h"

namespace lagoon::test {
namespace {

// 64x36 frames, memory measured after the first 50 (the least of 10 samples at each end, the free heap
// trimmed before each): Lagoon keeps nothing per frame, but at this size what the driver and the validation
// layer hold from one frame to the next moves the floor by up to 4.4 MiB of 130-170 MiB when the machine is
// busy (measured: -0.6 to +1.9 % with two soaks at once here, +2.67 % once in CI, a driver thread's first
// allocations landing after the warm-up), so the runs here are judged at 5 %. Keeping 0.1 MiB a frame alive
// (--retain-kib 100) over 200 frames after the warm-up, 20 MiB, reads +13.3 % and must fail: it catches a
// leak of that size (issue 36), with room above the noise. Under AddressSanitizer (make test-sanitize) the
// resident set is ASan's quarantine and shadow memory (1.3 GiB here, moving by tens of MiB as freed blocks
// cycle through it), so it says nothing about leaks; LeakSanitizer checks those there instead, and the memory
// verdicts are not asserted.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kResidentSetMeansNothing = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kResidentSetMeansNothing = true;
#else
constexpr bool kResidentSetMeansNothing = false;
#endif
#else
constexpr bool kResidentSetMeansNothing = false;
#endif

std::string short_soak(const std::string& extra) {
  return "soak --scene " + kDefaultScene +
         " --width 64 --height 36 --warmup 50 --set "
         "'ocean.cascades=[{\"patch_size_m\":300,\"resolution\":64},{\"patch_size_m\":30,\"resolution\":64}]'"
         " " +
         extra + (kResidentSetMeansNothing ? " --max-growth 1000" : " --max-growth 5");
}

TEST(SoakCli, AShortSoakChecksEveryStepAndFrameAndIsHealthy) {
  auto r = lagoon(short_soak("--steps 60 --frames 100"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::regex_search(
      r.output, std::regex(R"(steps +60 +non-finite texels 0 +RSS after warm-up [0-9.]+ MiB)")))
      << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(frames +100 +non-finite texels 0 )"))) << r.output;
  EXPECT_NE(r.output.find("validation errors 0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("healthy"), std::string::npos) << r.output;
}

TEST(SoakCli, ALeakOfATenthOfAMiBPerFrameIsCaught) {
  if (kResidentSetMeansNothing)
    GTEST_SKIP() << "AddressSanitizer's quarantine hides a leak in the resident set";
  // What is kept alive is the soak's own, whatever the frame draws: the reflection, refraction and caustics
  // passes are off (10 instead of 15 s here).
  auto r =
      lagoon(short_soak("--steps 0 --frames 250 --retain-kib 100 --set render.effects.reflection=false "
                        "--set render.effects.refraction=false --set render.effects.caustics=false"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("NOT healthy"), std::string::npos) << r.output;
}

// Waves summed where they are drawn, over a floor (the beach: swell over the FFT sea, shoaling), stay flat:
// lavapipe re-inlined the uniforms a vertex shader's loop or branch read at every draw and kept each variant,
// and the frames of any scene with such waves grew by about 0.2 MiB each before the wave count and the
// floor's mode became specialisation constants (this run: +16.9 %; model gerstner on the bay: +17.5 %). The
// random sea under the swell runs on two 64² cascades, as in the short soaks (10 instead of 15 s here).
TEST(SoakCli, WavesSummedOverTheFloorStayFlat) {
  if (kResidentSetMeansNothing)
    GTEST_SKIP() << "AddressSanitizer's quarantine hides a leak in the resident set";
  auto r = lagoon("soak --scene " + shell_quote(std::string(LAGOON_SOURCE_DIR) + "/scenes/beach.json") +
                  " --width 64 --height 36 --warmup 30 --steps 0 --frames 100 --max-growth 5 --set "
                  "'ocean.cascades=[{\"patch_size_m\":300,\"resolution\":64},{\"patch_size_m\":30,"
                  "\"resolution\":64}]'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("healthy"), std::string::npos) << r.output;
}

TEST(SoakCli, BadCountsAreUsageErrors) {
  for (const char* args :
       {"--steps -1", "--frames x", "--width 4", "--max-growth -1", "--warmup -2", "--retain-kib 1e9"}) {
    auto r = lagoon("soak --scene " + kDefaultScene + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace lagoon::test
