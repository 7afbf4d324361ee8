// main() of every test binary. Sets the suite's environment before any test runs, so a test binary run by
// hand behaves exactly as under ctest: validation on, lavapipe unless LAGOON_DEVICE says otherwise, Lagoon's
// caches inside the build tree. Values already in the environment win (e.g. LAGOON_DEVICE=nvidia ctest).
// Mesa's shader cache is left where Mesa keeps it (~/.cache/mesa_shader_cache): it only holds compiled
// code, keyed by the shader and the driver, so sharing it with `lagoon render` and with other build folders
// (a clean clone, CI) changes no result and spares lavapipe recompiling every pipeline in every new build.
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  setenv("LAGOON_VALIDATION", "1", 1);  // not overridable: every test that touches Vulkan validates
  setenv("LAGOON_DEVICE", LAGOON_TEST_DEVICE, 0);
  setenv("LAGOON_PIPELINE_CACHE", LAGOON_TEST_ARTIFACTS "/pipeline-cache", 0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
