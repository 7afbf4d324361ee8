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

// Issue 39: `--set ocean.model=sines` on a scene written for the FFT ocean sets what sines needs
// (choppiness 0, ocean/model_constraints.h), as the demo's selector does, and says so; a choppiness the user
// sets too, or a scene file that picks sines itself with another choppiness, is still refused.
TEST(SceneCli, PickingAModelWithSetAlsoSetsWhatTheModelNeedsAndSaysSo) {
  for (const char* name :
       {"default", "harbour", "open-ocean", "reef-dive", "tropical-lagoon", "waterline", "beach"}) {
    const std::string scene = shell_quote(std::string(LAGOON_SOURCE_DIR) + "/scenes/" + name + ".json");
    const ProcessResult r = lagoon("probe --scene " + scene + " --time 1 --at 0,0 --set ocean.model=sines");
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("note: --set ocean.model=sines also sets ocean.choppiness "), std::string::npos)
        << name << "\n"
        << r.output;
    EXPECT_NE(r.output.find("-> 0: eqs. 1-3 move the surface only up and down"), std::string::npos)
        << r.output;
  }
  const std::string scene = shell_quote(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json");
  TempDir dir;
  const ProcessResult render =
      lagoon("render --scene " + scene + " --set ocean.model=sines --width 32 --height 18" + " --out " +
             shell_quote((dir / "sines.png").string()));
  EXPECT_EQ(render.exit_code, 0) << render.output;
  EXPECT_TRUE(fs::exists(dir / "sines.png"));

  const ProcessResult chosen = lagoon(
      "probe --scene " + scene + " --time 1 --at 0,0 --set ocean.model=sines --set ocean.choppiness=0.5");
  EXPECT_EQ(chosen.exit_code, 1) << chosen.output;
  EXPECT_NE(chosen.output.find("ocean.choppiness: 0.5 must be 0 for model sines"), std::string::npos)
      << chosen.output;
  EXPECT_EQ(chosen.output.find("also sets"), std::string::npos) << chosen.output;

  std::ofstream(dir / "sines.json") << R"({"ocean": {"model": "sines", "choppiness": 0.8}})";
  const ProcessResult written =
      lagoon("probe --scene " + shell_quote((dir / "sines.json").string()) + " --time 1 --at 0,0");
  EXPECT_EQ(written.exit_code, 1) << written.output;
  EXPECT_NE(written.output.find("ocean.choppiness: 0.8 must be 0 for model sines"), std::string::npos)
      << written.output;
}

}  // namespace
}  // namespace lagoon::test
