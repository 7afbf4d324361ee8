// Scene and glTF error paths through `lagoon render`: each distinct error is reported with the file, the
// field and the reason, exits 1, and leaves no output behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

TEST(SceneCli, BrokenOrHostileModelsAreRefusedWithTheReason) {
  TempDir dir;
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string asset = R"({"asset":{"version":"2.0"},)";
  struct Case {
    std::string file, expected;
  } cases[] = {
      {(dir / "nothere.gltf").string(), "does not exist"},
      {write("broken.gltf", "{not json"), "not a valid glTF file"},
      {write("outside.gltf", asset + R"("buffers":[{"uri":"../secret.bin","byteLength":12}]})"),
       "leads outside the model's folder"},
      {write("absolute.gltf", asset + R"("buffers":[{"uri":"/etc/passwd","byteLength":12}]})"),
       "absolute URI"},
      {write("missing.gltf", asset + R"("buffers":[{"uri":"missing.bin","byteLength":12}]})"), "missing.bin"},
      {write(
           "range.gltf",
           asset +
               R"("buffers":[{"byteLength":12,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],)"
               R"("bufferViews":[{"buffer":0,"byteLength":12}],)"
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":1000,"type":"VEC3"}],)"
               R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],)"
               R"("scenes":[{"nodes":[0]}]})"),
       "past the end of bufferViews[0]"},
  };
  const std::string out = (dir / "out" / "x.png").string();
  for (const Case& c : cases) {
    auto r = run_process(shell_quote(LAGOON_BINARY) + " render --scene " + kDefaultScene + " --out " + out +
                         " --width 64 --height 36 --set " +
                         shell_quote("objects=[{\"file\":\"" + c.file + "\"}]"));
    EXPECT_EQ(r.exit_code, 1) << c.file << "\n" << r.output;
    EXPECT_NE(r.output.find("objects[0].file"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(fs::path(c.file).filename().string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out")) << "an output was left behind";
}

TEST(SceneCli, SceneRuleErrorsNameTheField) {
  struct Case {
    std::string set, expected;
  } cases[] = {
      {"seafloor.depth_far_m=0.1", "seafloor.depth_far_m"},
      {"objects=[{\"fil\":\"a.gltf\"}]", "did you mean 'file'"},
      {"lights=[{\"range_m\":-1}]", "lights[0].range_m"},
      {"render.tone_map=aces", "render.tone_map"},
  };
  for (const Case& c : cases) {
    auto r = run_process(shell_quote(LAGOON_BINARY) + " render --scene " + kDefaultScene +
                         " --out /tmp/never.png --set " + shell_quote(c.set));
    EXPECT_EQ(r.exit_code, 1) << c.set << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.set << "\n" << r.output;
  }
}

TEST(SceneCli, FramesWriteOneNumberedPngEach) {
  TempDir dir;
  auto r = run_process(shell_quote(LAGOON_BINARY) + " render --scene " + kDefaultScene + " --out " +
                       (dir / "f.png").string() + " --width 32 --height 18 --frames 3 --fps 10");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name : {"f_0000.png", "f_0001.png", "f_0002.png"})
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  EXPECT_FALSE(fs::exists(dir / "f.png"));
  EXPECT_NE(r.output.find("3/3 frames"), std::string::npos) << r.output;
  EXPECT_EQ(run_process(shell_quote(LAGOON_BINARY) + " render --scene " + kDefaultScene + " --out " +
                        (dir / "g.png").string() + " --frames 0")
                .exit_code,
            2);
}

}  // namespace
}  // namespace lagoon::test
