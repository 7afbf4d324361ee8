// FrameUniforms' first word is read by no shader: Debian's lavapipe (Mesa 22.3) inlines a uniform block's
// first word into the variants it compiles at the draw, so a word that a shader reads there makes a variant
// per value (a compile per camera pose when it was the view matrix) or per draw (a leak when it was the
// picture's size). shared/frame.h checks the offset at compile time; this checks that nothing reads it.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "support/run_process.h"

namespace lagoon::test {
namespace {

TEST(FrameUniformsLayout, NoShaderReadsTheBlocksFirstWord) {
  const std::filesystem::path shaders = std::filesystem::path(LAGOON_SOURCE_DIR) / "shaders";
  const std::regex read(R"(\.\s*unread\b)");  // frame.unread, f.unread, ...
  std::vector<std::string> readers;
  size_t scanned = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(shaders)) {
    if (!entry.is_regular_file()) continue;
    ++scanned;
    if (std::regex_search(read_file(entry.path()), read)) readers.push_back(entry.path().string());
  }
  EXPECT_GT(scanned, 50u) << "the shader folder was not found: " << shaders;
  EXPECT_TRUE(readers.empty()) << "FrameUniforms::unread is read in " << ::testing::PrintToString(readers)
                               << "; keep the block's first word unread (shared/frame.h says why)";
}

}  // namespace
}  // namespace lagoon::test
