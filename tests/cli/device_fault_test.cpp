// Device faults lavapipe can really produce: with the address space limited, its device memory runs out
// part-way through building the renderer. The command must exit 1 with what ran out and what to change,
// never abort or hang, and write nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

TEST(DeviceFault, OutOfDeviceMemoryExits1WithWhatRanOutAndTheFix) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space, so ulimit -v cannot starve lavapipe";
#endif
  // ulimit -v bounds what a CPU device can allocate, not a GPU's memory: this runs on lavapipe only.
  const std::string lavapipe = "LAGOON_DEVICE=llvmpipe ";
  if (run_process(lavapipe + shell_quote(LAGOON_BINARY) + " info").exit_code != 0)
    GTEST_SKIP() << "lavapipe (mesa-vulkan-drivers) is not installed here";
  TempDir dir;
  const std::string out = (dir / "frame.png").string();
  // 8192² render targets need more than 2 GiB; 3 GB of address space leaves lavapipe a 2 GiB heap, not all
  // of it free.
  auto r = run_process("ulimit -v 3000000; " + lavapipe + "exec timeout 300 " + shell_quote(LAGOON_BINARY) +
                       " render --scene " + kDefaultScene + " --out " + shell_quote(out) +
                       " --width 8192 --height 8192");
  EXPECT_EQ(r.exit_code, 1) << r.output;  // not 134 (abort), 139 (crash) or 124 (hang)
  EXPECT_TRUE(r.output.find("out of device memory allocating") != std::string::npos ||
              r.output.find("out of host memory allocating") != std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(" MiB for "), std::string::npos) << r.output;  // how much, for what
  EXPECT_NE(r.output.find("Lower render.width/render.height"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace lagoon::test
