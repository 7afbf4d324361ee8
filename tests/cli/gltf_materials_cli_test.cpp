// `lagoon render` with glTF models that use every sampler mode, material slot and extension the loader
// reads (issue 17): each renders, exits 0 and is not warned about; broken values exit 1 naming the file and
// the field.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/png.h"
#include "support/edited_scene.h"
#include "support/gltf_quads.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

class GltfMaterialsCli : public ::testing::Test {
 protected:
  TempDir dir_{"lagoon_gltf_materials_cli"};

  void SetUp() override {
    std::vector<uint8_t> rgba;
    for (int i = 0; i < 16; ++i)
      rgba.insert(rgba.end(), {200, uint8_t(40 * (i % 4)), 90, uint8_t(i % 2 ? 255 : 60)});
    ASSERT_TRUE(io::write_png(dir_ / "tex.png", io::Image8{.width = 4, .height = 4, .rgba = rgba}));
  }

  // Renders a scene holding the one-quad model made of `material` and `extra`; returns the result.
  ProcessResult render(const json& material, const json& extra = json::object()) {
    json top = {{"images", {{{"uri", "tex.png"}}}}, {"textures", {{{"source", 0}}}}};
    top.update(extra);
    write_quads(dir_ / "model.gltf", {Quad{material}}, top);
    std::ifstream in(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json");
    json s = json::parse(in);
    s["camera"] = {{"position", {0, 3, 0}}, {"look_at", {0, 3, 20}}};
    s["render"].update({{"width", 64}, {"height", 36}});
    s["seafloor"] = {{"type", "none"}};
    use_small_cascades(s);  // the model's materials are checked, not the sea
    // Yaw 180: the model's front (+z) faces south, away from the camera, which sees its -z side.
    s["objects"] =
        json::array({json{{"file", "model.gltf"}, {"position", {0, 3, 20}}, {"rotation_deg", {180, 0, 0}}}});
    std::ofstream(dir_ / "scene.json") << s.dump();
    return run_process(shell_quote(LAGOON_BINARY) + " render --scene " +
                       shell_quote((dir_ / "scene.json").string()) + " --out " +
                       shell_quote((dir_ / "frame.png").string()));
  }

  void expect_renders_without_warning(const ProcessResult& r, const std::string& what) {
    EXPECT_EQ(r.exit_code, 0) << what << "\n" << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << what << "\n" << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir_ / "frame.png")) << what;
    std::filesystem::remove(dir_ / "frame.png");
  }
};

json textured(const json& texture_info = {{"index", 0}}) {
  return {{"pbrMetallicRoughness", {{"baseColorTexture", texture_info}, {"metallicFactor", 0}}}};
}

TEST_F(GltfMaterialsCli, EverySamplerModeRenders) {
  const std::vector<json> samplers = {
      json::object(),
      {{"magFilter", 9728}, {"minFilter", 9728}},
      {{"magFilter", 9729}, {"minFilter", 9729}},
      {{"minFilter", 9984}},
      {{"minFilter", 9985}},
      {{"minFilter", 9986}},
      {{"minFilter", 9987}},
      {{"wrapS", 33071}, {"wrapT", 33071}},
      {{"wrapS", 33648}, {"wrapT", 10497}},
  };
  for (const json& sampler : samplers) {
    const json extra = {{"samplers", {sampler}}, {"textures", {{{"source", 0}, {"sampler", 0}}}}};
    expect_renders_without_warning(render(textured(), extra), "sampler " + sampler.dump());
  }
}

TEST_F(GltfMaterialsCli, EveryMaterialSlotAndAlphaModeRenders) {
  json all = textured();
  all["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 0}};
  all["normalTexture"] = {{"index", 0}, {"scale", 0.7}, {"texCoord", 1}};
  all["occlusionTexture"] = {{"index", 0}, {"strength", 0.5}};
  all["emissiveTexture"] = {{"index", 0}};
  all["emissiveFactor"] = {0.2, 0.1, 0.0};
  all["doubleSided"] = true;
  expect_renders_without_warning(render(all), "every slot");
  for (const char* mode : {"OPAQUE", "MASK", "BLEND"}) {
    json m = textured();
    m["alphaMode"] = mode;
    m["alphaCutoff"] = 0.4;
    expect_renders_without_warning(render(m), mode);
  }
}

TEST_F(GltfMaterialsCli, EveryReadExtensionRendersEvenWhenRequired) {
  struct Case {
    const char* name;
    json material;
  };
  json transform = textured(
      {{"index", 0},
       {"extensions",
        {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.3}, {"scale", {2, 2}}}}}}});
  json emissive = textured();
  emissive["emissiveFactor"] = {1.0, 0.5, 0.2};
  emissive["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5.0}}}};
  for (const Case& c :
       {Case{"KHR_texture_transform", transform}, Case{"KHR_materials_emissive_strength", emissive},
        Case{"KHR_mesh_quantization", textured()}}) {
    const json extra = {{"extensionsUsed", {c.name}}, {"extensionsRequired", {c.name}}};
    expect_renders_without_warning(render(c.material, extra), c.name);
  }
  // An extension the loader does not read is still named in one warning, and still renders.
  json clearcoat = textured();
  clearcoat["extensions"] = {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}}};
  const ProcessResult r = render(clearcoat, {{"extensionsUsed", {"KHR_materials_clearcoat"}}});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("'KHR_materials_clearcoat' is not supported"), std::string::npos) << r.output;
}

TEST_F(GltfMaterialsCli, BrokenValuesExit1NamingTheFileAndField) {
  struct Case {
    json material, extra;
    const char* field;
  };
  json cutoff = textured();
  cutoff["alphaCutoff"] = -1;
  json rough = textured();
  rough["pbrMetallicRoughness"]["roughnessFactor"] = 7;
  const std::vector<Case> cases = {
      {cutoff, json::object(), "materials[0].alphaCutoff"},
      {rough, json::object(), "materials[0].pbrMetallicRoughness.roughnessFactor"},
      {textured(),
       {{"samplers", {{{"magFilter", 1234}}}}, {"textures", {{{"source", 0}, {"sampler", 0}}}}},
       "samplers[0].magFilter"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = render(c.material, c.extra);
    EXPECT_EQ(r.exit_code, 1) << c.field << "\n" << r.output;
    EXPECT_NE(r.output.find("model.gltf"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.field), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "frame.png"));
  }
}

}  // namespace
}  // namespace lagoon::test
