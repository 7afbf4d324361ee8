// main() of every test binary. Sets the suite's environment before any test runs, so a test binary run by
// hand behaves exactly as under ctest: validation on, lavapipe unless LAGOON_DEVICE says otherwise, caches
// inside the build tree. Values already in the environment win (e.g. LAGOON_DEVICE=nvidia ctest).
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  setenv("LAGOON_VALIDATION", "1", 1);  // not overridable: every test that touches Vulkan validates
  setenv("LAGOON_DEVICE", LAGOON_TEST_DEVICE, 0);
  setenv("LAGOON_PIPELINE_CACHE", LAGOON_TEST_ARTIFACTS "/pipeline-cache", 0);
  setenv("MESA_SHADER_CACHE_DIR", LAGOON_TEST_ARTIFACTS "/mesa-shader-cache", 0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
