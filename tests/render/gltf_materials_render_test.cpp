// glTF materials in the frame (issue 17): a normal map of a known tilt shades like geometry tilted the same
// way, alpha MASK lets through what is behind the cut-out texels, and BLEND planes are drawn farthest first
// whatever order the file lists them in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/png.h"
#include "render/ocean_renderer.h"
#include "support/edited_scene.h"
#include "support/gltf_quads.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

class GltfMaterialsRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_gltf_materials_render"};

  io::Image8 render(const scene::Scene& s) {
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return (*renderer)->render(s);
  }

  // The model `file` 20 m in front of a camera 3 m above a calm sea, at 160 × 90.
  io::Image8 render_model(const std::string& file) {
    json s = shipped_scene_json("default");
    s["camera"] = {{"position", {0, 3, 0}}, {"look_at", {0, 3, 20}}};
    s["render"].update({{"width", 160}, {"height", 90}});
    s["sun"] = {{"elevation_deg", 40}, {"azimuth_deg", 310}};
    s["seafloor"] = {{"type", "none"}};
    // Yaw 180: the model's front (+z) faces south, away from the camera, which sees its -z side.
    s["objects"] =
        json::array({json{{"file", file}, {"position", {0, 3, 20}}, {"rotation_deg", {180, 0, 0}}}});
    return render(write_and_load(s, dir_ / "scene.json"));
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

// Spheres of radius 0.5 m in the style of the glTF sample MetalRoughSpheres: one row of dielectrics over
// one row of metals, both red (0.9, 0, 0), roughness growing towards −x; each sphere its own node and
// material.
void write_sphere_grid(const std::filesystem::path& path, const std::vector<float>& roughness) {
  constexpr int kRings = 24, kSegments = 48;
  std::vector<float> pos, nrm;
  std::vector<uint16_t> idx;
  for (int r = 0; r <= kRings; ++r) {
    const double t = 3.14159265358979 * r / kRings;
    for (int k = 0; k <= kSegments; ++k) {
      const double p = 2 * 3.14159265358979 * k / kSegments;
      const double n[3] = {std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p)};
      for (int c = 0; c < 3; ++c) {
        nrm.push_back(float(n[c]));
        pos.push_back(float(0.5 * n[c]));
      }
    }
  }
  for (int r = 0; r < kRings; ++r) {
    for (int k = 0; k < kSegments; ++k) {
      const uint16_t a = uint16_t(r * (kSegments + 1) + k), b = uint16_t(a + kSegments + 1);
      idx.insert(idx.end(), {a, uint16_t(a + 1), b, uint16_t(a + 1), uint16_t(b + 1), b});
    }
  }
  std::vector<uint8_t> bin;
  auto add = [&](const void* data, size_t bytes) {
    const auto* b = static_cast<const uint8_t*>(data);
    bin.insert(bin.end(), b, b + bytes);
  };
  add(pos.data(), pos.size() * 4);
  add(nrm.data(), nrm.size() * 4);
  add(idx.data(), idx.size() * 2);
  const size_t count = pos.size() / 3;
  json doc = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", json::array({json{{"nodes", json::array()}}})},
              {"bufferViews",
               {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", pos.size() * 4}},
                {{"buffer", 0}, {"byteOffset", pos.size() * 4}, {"byteLength", nrm.size() * 4}},
                {{"buffer", 0}, {"byteOffset", 2 * pos.size() * 4}, {"byteLength", idx.size() * 2}}}},
              {"accessors",
               {{{"bufferView", 0},
                 {"componentType", 5126},
                 {"count", count},
                 {"type", "VEC3"},
                 {"min", {-0.5, -0.5, -0.5}},
                 {"max", {0.5, 0.5, 0.5}}},
                {{"bufferView", 1}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}},
                {{"bufferView", 2}, {"componentType", 5123}, {"count", idx.size()}, {"type", "SCALAR"}}}}};
  for (int metal = 0; metal < 2; ++metal) {
    for (size_t i = 0; i < roughness.size(); ++i) {
      const size_t m = doc["materials"].size();
      doc["materials"].push_back({{"pbrMetallicRoughness",
                                   {{"baseColorFactor", {0.9, 0.0, 0.0, 1}},
                                    {"metallicFactor", metal},
                                    {"roughnessFactor", roughness[i]}}}});
      doc["meshes"].push_back(
          {{"primitives",
            json::array(
                {json{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"material", m}}})}});
      doc["nodes"].push_back(
          {{"mesh", m},
           {"translation", {1.3 * (double(i) - 0.5 * double(roughness.size() - 1)), metal ? -0.7 : 0.7, 0}}});
      doc["scenes"][0]["nodes"].push_back(m);
    }
  }
  doc["buffers"] = json::array(
      {json{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
  std::ofstream(path) << doc.dump();
}

TEST_F(GltfMaterialsRender, RougherSpheresSpreadTheirHighlightAndOnlyMetalsTintIt) {
  // Red spheres (base colour 0.9, 0, 0) at night, lit by one lamp beside the camera: a metal reflects only
  // red (f0 = base colour), so its green channel is dark; a dielectric's green channel holds nothing but its
  // highlight (f0 = 0.04 in every channel; its diffuse is red only). The highlight's size is measured in
  // the channel that holds it: the metal's red, the dielectric's green.
  const std::vector<float> roughness = {0.25f, 0.35f, 0.5f, 0.65f, 0.8f};
  write_sphere_grid(dir_ / "spheres.gltf", roughness);
  auto render_at = [&](double lamp, double gamma) {
    json s = shipped_scene_json("default");
    s["camera"] = {{"position", {0, 3, 0}}, {"look_at", {0, 3, 7}}, {"fov_deg", 60}};
    s["render"].update(
        {{"width", 640}, {"height", 360}, {"tone_map", "clamp"}, {"gamma", gamma}, {"exposure", 1}});
    s["sun"] = {{"elevation_deg", -20}, {"azimuth_deg", 355}};
    s["lights"] = json::array(
        {json{{"position", {0.5, 3.5, -1}}, {"colour", {1, 1, 1}}, {"intensity", lamp}, {"range_m", 60}}});
    s["seafloor"] = {{"type", "none"}};
    s["objects"] =
        json::array({json{{"file", "spheres.gltf"}, {"position", {0, 3, 7}}, {"rotation_deg", {180, 0, 0}}}});
    return render(write_and_load(s, dir_ / "spheres.json"));
  };
  // The dielectrics' highlight (f0 = 0.04) under a lamp 48 times brighter than the metals' (f0 = 0.9), and
  // through a gamma of 2.2 so its rough spheres' faint highlights keep enough levels; the measure (pixels
  // above a fixed fraction of the peak) is the same for any monotonic encoding.
  const io::Image8 metals = render_at(2.0, 1.0), dielectrics = render_at(96.0, 2.2);
  // The vertical field of view is 60°: 7 m away, 1 m spans 360 / (2 · 7 · tan 30°) = 44.5 px.
  const double px_per_m = 360.0 / (2 * 7 * std::tan(3.14159265358979 / 6));
  for (int metal = 0; metal < 2; ++metal) {
    const io::Image8& img = metal ? metals : dielectrics;
    const int channel = metal ? 0 : 1;
    double previous_area = 0;
    for (size_t i = 0; i < roughness.size(); ++i) {
      const int cx = int(std::lround(320 - px_per_m * 1.3 * (double(i) - 2.0)));  // +x is on the left
      const int cy = int(std::lround(180 - px_per_m * (metal ? -0.7 : 0.7)));
      const int r = int(0.45 * px_per_m);
      std::vector<const uint8_t*> disc;
      for (int y = cy - r; y <= cy + r; ++y)
        for (int x = cx - r; x <= cx + r; ++x)
          if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r)
            disc.push_back(img.pixel(uint32_t(x), uint32_t(y)));
      const uint8_t* top = *std::max_element(disc.begin(), disc.end(),
                                             [&](auto a, auto b) { return a[channel] < b[channel]; });
      const double peak = top[channel];
      const double area =
          double(std::count_if(disc.begin(), disc.end(), [&](auto p) { return p[channel] > 0.5 * peak; })) /
          double(disc.size());
      RecordProperty((metal ? "metal_" : "dielectric_") + std::to_string(i),
                     "roughness " + std::to_string(roughness[i]) + ": highlight " + std::to_string(area) +
                         " of the disc, peak rgb " + std::to_string(top[0]) + " " + std::to_string(top[1]) +
                         " " + std::to_string(top[2]));
      EXPECT_LT(peak, 254.5) << "clipped: the measure needs an unclipped highlight";
      EXPECT_GT(peak, 9.0) << "no highlight to measure";
      if (i > 0) {
        EXPECT_GT(area, previous_area) << (metal ? "metal" : "dielectric") << " roughness " << roughness[i];
      }
      previous_area = area;
      if (metal) {
        EXPECT_LT(top[1], 0.05 * top[0] + 2) << "a metal's highlight takes its base colour";
      }
    }
  }
}

}  // namespace
}  // namespace lagoon::test
