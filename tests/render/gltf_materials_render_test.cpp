// glTF materials in the frame (issue 17): a normal map of a known tilt shades like geometry tilted the same
// way, alpha MASK lets through what is behind the cut-out texels, and BLEND planes are drawn farthest first
// whatever order the file lists them in.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/png.h"
#include "render/ocean_renderer.h"
#include "support/gltf_quads.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

class GltfMaterialsRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_gltf_materials_render"};

  // The model `file` 20 m in front of a camera 3 m above a calm sea, at 160 × 90.
  io::Image8 render_model(const std::string& file) {
    std::ifstream in(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json");
    json s = json::parse(in);
    s["camera"] = {{"position", {0, 3, 0}}, {"look_at", {0, 3, 20}}};
    s["render"].update({{"width", 160}, {"height", 90}});
    s["sun"] = {{"elevation_deg", 40}, {"azimuth_deg", 230}};
    s["seafloor"] = {{"type", "none"}};
    s["objects"] = json::array({json{{"file", file}, {"position", {0, 3, 20}}}});
    std::ofstream(dir_ / "scene.json") << s.dump();
    auto scene = scene::load_scene(dir_ / "scene.json");
    EXPECT_TRUE(scene) << scene.error().message;
    auto renderer = render::OceanRenderer::create(ctx(), *scene);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return (*renderer)->render(*scene);
  }

  // An image file next to the models: w × h texels of `rgba`.
  void write_texture(const std::string& name, uint32_t w, uint32_t h, const std::vector<uint8_t>& rgba) {
    ASSERT_TRUE(io::write_png(dir_ / name, io::Image8{.width = w, .height = h, .rgba = rgba}));
  }
};

// Mean of channel c over the 6 × 6 pixels around (x, y).
double mean_at(const io::Image8& img, uint32_t x, uint32_t y, int c) {
  double sum = 0;
  for (uint32_t dy = 0; dy < 6; ++dy)
    for (uint32_t dx = 0; dx < 6; ++dx) sum += img.pixel(x + dx - 3, y + dy - 3)[c];
  return sum / 36;
}

json grey_material() {
  return {{"pbrMetallicRoughness",
           {{"baseColorFactor", {0.6, 0.6, 0.6, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}}}};
}

TEST_F(GltfMaterialsRender, NormalMapShadesLikeGeometryTiltedTheSameWay) {
  // Tilts of 20° towards +x (the tangent) and towards −y (the bitangent, where the tangent's handedness
  // counts), as a constant normal map on a flat quad and as the quad itself rotated.
  const double t = 20.0 * 3.14159265358979 / 180.0;
  struct Tilt {
    const char* name;
    glm::dvec3 tangent_space;
    json rotation;  // the glTF quaternion turning the quad's normal −z to the same world normal
  };
  const std::vector<Tilt> tilts = {
      {"u", {std::sin(t), 0, std::cos(t)}, {0, std::sin(-t / 2), 0, std::cos(-t / 2)}},
      {"v", {0, std::sin(t), std::cos(t)}, {std::sin(-t / 2), 0, 0, std::cos(-t / 2)}},
  };
  for (const Tilt& tilt : tilts) {
    std::vector<uint8_t> texels;
    for (int i = 0; i < 16; ++i) {
      for (int c = 0; c < 3; ++c)
        texels.push_back(uint8_t(std::lround((tilt.tangent_space[c] * 0.5 + 0.5) * 255)));
      texels.push_back(255);
    }
    const std::string png = std::string("normal_") + tilt.name + ".png";
    write_texture(png, 4, 4, texels);
    json mapped = grey_material();
    mapped["normalTexture"] = {{"index", 0}};
    write_quads(dir_ / "mapped.gltf", {Quad{mapped}},
                {{"images", {{{"uri", png}}}}, {"textures", {{{"source", 0}}}}});
    write_quads(dir_ / "tilted.gltf", {Quad{grey_material(), {0, 0, 0}, tilt.rotation}});
    write_quads(dir_ / "flat.gltf", {Quad{grey_material()}});
    const io::Image8 a = render_model("mapped.gltf"), b = render_model("tilted.gltf"),
                     flat = render_model("flat.gltf");
    double worst = 0, tilt_effect = 0;
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(mean_at(a, 80, 45, c) - mean_at(b, 80, 45, c)));
      tilt_effect = std::max(tilt_effect, std::abs(mean_at(flat, 80, 45, c) - mean_at(b, 80, 45, c)));
    }
    RecordProperty(
        std::string("tilt_") + tilt.name,
        std::to_string(worst) + " levels apart; the tilt itself moves " + std::to_string(tilt_effect));
    EXPECT_LE(worst, 1.0) << tilt.name;
    EXPECT_GT(tilt_effect, 4.0) << tilt.name << ": the tilt must show for the comparison to mean anything";
  }
}

TEST_F(GltfMaterialsRender, MaskCutsOutAndBlendIsOrderCorrect) {
  // A red quad whose texture's left half has alpha 0 (nearest filtering), 2 m in front of a blue one.
  write_texture("half.png", 2, 1, {255, 255, 255, 0, 255, 255, 255, 255});
  const json images = {{"images", {{{"uri", "half.png"}}}},
                       {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}},
                       {"textures", {{{"source", 0}, {"sampler", 0}}}}};
  auto red = [](const char* mode) {
    json m = {{"pbrMetallicRoughness",
               {{"baseColorFactor", {0.9, 0.05, 0.05, 1}},
                {"baseColorTexture", {{"index", 0}}},
                {"metallicFactor", 0}}},
              {"alphaMode", mode}};
    return m;
  };
  const json blue = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.05, 0.05, 0.9, 1}}, {"metallicFactor", 0}}}};
  for (const char* mode : {"MASK", "OPAQUE"}) {
    write_quads(dir_ / "mask.gltf", {Quad{blue, {0, 0, 2}, {0, 0, 0, 1}, 3.0f}, Quad{red(mode)}}, images);
    const io::Image8 img = render_model("mask.gltf");
    // The quad spans about 18 pixels. The camera looks along +z, so the quad's −x (u < ½, the cut-out half)
    // is on the image's right.
    const double left_red = mean_at(img, 75, 45, 0), left_blue = mean_at(img, 75, 45, 2);
    const double right_red = mean_at(img, 85, 45, 0), right_blue = mean_at(img, 85, 45, 2);
    RecordProperty(std::string("mask_") + mode,
                   "left r/b " + std::to_string(left_red) + "/" + std::to_string(left_blue) + ", right " +
                       std::to_string(right_red) + "/" + std::to_string(right_blue));
    EXPECT_GT(left_red, left_blue + 40) << mode;
    if (std::string(mode) == "MASK") {
      EXPECT_GT(right_blue, right_red + 40) << "MASK: the cut-out half shows the blue quad behind";
    } else {
      EXPECT_GT(right_red, right_blue + 40) << "OPAQUE ignores alpha";
    }
  }
  // Two half-transparent planes, red 1 m nearer than green, over a white one; listed in both orders.
  auto tint = [](double r, double g) {
    return json{{"pbrMetallicRoughness", {{"baseColorFactor", {r, g, 0.05, 0.5}}, {"metallicFactor", 0}}},
                {"alphaMode", "BLEND"}};
  };
  const json white = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0}}}};
  const Quad back{white, {0, 0, 3}, {0, 0, 0, 1}, 3.0f};
  const Quad near_red{tint(0.9, 0.05), {0, 0, 0}}, far_green{tint(0.05, 0.9), {0, 0, 1}};
  write_quads(dir_ / "blend_a.gltf", {back, near_red, far_green});
  write_quads(dir_ / "blend_b.gltf", {far_green, back, near_red});
  const io::Image8 a = render_model("blend_a.gltf"), b = render_model("blend_b.gltf");
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(mean_at(a, 80, 45, c), mean_at(b, 80, 45, c), 1.0) << "channel " << c;
  // Over the same background, the nearer plane's colour weighs twice the farther one's.
  EXPECT_GT(mean_at(a, 80, 45, 0), mean_at(a, 80, 45, 1) + 15) << "the nearer red plane must dominate";
  const Quad near_green{tint(0.05, 0.9), {0, 0, 0}}, far_red{tint(0.9, 0.05), {0, 0, 1}};
  write_quads(dir_ / "blend_c.gltf", {near_green, back, far_red});
  const io::Image8 c = render_model("blend_c.gltf");
  EXPECT_GT(mean_at(c, 80, 45, 1), mean_at(c, 80, 45, 0) + 15) << "the nearer green plane must dominate";
}

}  // namespace
}  // namespace lagoon::test
