// glTF loader: small models written by the tests themselves (as .gltf with data: URIs, .gltf with a
// separate .bin, and .glb), every error path a hostile or broken file can take, and a deterministic fuzz.
#include <gtest/gtest.h>

#include <stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>
#include <webp/encode.h>
#include <nlohmann/json.hpp>
#include "support/temp_dir.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "gltf/gltf_loader.h"

namespace lagoon::gltf {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kByte = 5120, kShort = 5122, kUnsignedByte = 5121, kUnsignedShort = 5123, kInt = 5124,
              kUnsignedInt = 5125, kFloat = 5126;

struct TempDir : test::TempDir {
  TempDir() : test::TempDir("lagoon_gltf_test") {}
};

// ---- Writing test models ---------------------------------------------------------------------------------

std::string base64(const std::vector<uint8_t>& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = uint32_t{bytes[i]} << 16 | (i + 1 < bytes.size() ? uint32_t{bytes[i + 1]} << 8 : 0) |
                       (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += kDigits[n >> 18 & 63];
    out += kDigits[n >> 12 & 63];
    out += i + 1 < bytes.size() ? kDigits[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

void write_bytes(const fs::path& path, const void* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}
void write_bytes(const fs::path& path, const std::vector<uint8_t>& bytes) {
  write_bytes(path, bytes.data(), bytes.size());
}
void write_text(const fs::path& path, const std::string& text) {
  write_bytes(path, text.data(), text.size());
}

std::vector<uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void put_u32(std::vector<uint8_t>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

std::vector<uint8_t> make_glb(std::string json_text, std::vector<uint8_t> bin) {
  while (json_text.size() % 4) json_text += ' ';
  while (bin.size() % 4) bin.push_back(0);
  std::vector<uint8_t> out;
  put_u32(out, 0x46546C67);  // "glTF"
  put_u32(out, 2);
  put_u32(out, static_cast<uint32_t>(12 + 8 + json_text.size() + (bin.empty() ? 0 : 8 + bin.size())));
  put_u32(out, static_cast<uint32_t>(json_text.size()));
  put_u32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), json_text.begin(), json_text.end());
  if (!bin.empty()) {
    put_u32(out, static_cast<uint32_t>(bin.size()));
    put_u32(out, 0x004E4942);  // "BIN"
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

void append_to_vector(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}

// 2x2 RGBA: red, green / blue, half-transparent white (top row first).
const std::vector<uint8_t> kPixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

std::vector<uint8_t> png_2x2() {
  std::vector<uint8_t> png;
  stbi_write_png_to_func(append_to_vector, &png, 2, 2, 4, kPixels.data(), 8);
  return png;
}

enum class Layout { kDataUri, kSeparateBin, kGlb };
enum class ImageAt { kBufferView, kDataUri, kFile };

// A glTF document plus one binary buffer, written in any of the three layouts.
struct Builder {
  json doc = {{"asset", {{"version", "2.0"}}}};
  std::vector<uint8_t> bin;
  std::map<std::string, std::vector<uint8_t>> files;  // written next to the model

  int push(const char* array, json value) {
    doc[array].push_back(std::move(value));
    return static_cast<int>(doc[array].size()) - 1;
  }
  int view(const void* data, size_t size, std::optional<int> stride = std::nullopt) {
    while (bin.size() % 4) bin.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (stride) v["byteStride"] = *stride;
    const auto* p = static_cast<const uint8_t*>(data);
    bin.insert(bin.end(), p, p + size);
    return push("bufferViews", std::move(v));
  }
  template <typename T>
  int view(const std::vector<T>& values, std::optional<int> stride = std::nullopt) {
    return view(values.data(), values.size() * sizeof(T), stride);
  }
  int accessor(int view_index, int component_type, size_t count, const std::string& type,
               const json& extra = json::object()) {
    json a = {
        {"bufferView", view_index}, {"componentType", component_type}, {"count", count}, {"type", type}};
    a.update(extra);
    return push("accessors", std::move(a));
  }
  json& primitive(int mesh = 0, int prim = 0) { return doc["meshes"][mesh]["primitives"][prim]; }

  std::string buffer_uri(const fs::path& dir, const std::string& stem, Layout layout) const {
    if (layout == Layout::kDataUri) return "data:application/octet-stream;base64," + base64(bin);
    write_bytes(dir / (stem + ".bin"), bin);
    return stem + ".bin";
  }
  fs::path write(const fs::path& dir, const std::string& stem, Layout layout) const {
    json d = doc;
    if (!bin.empty() && !d.contains("buffers")) {
      d["buffers"] = json::array({json{{"byteLength", bin.size()}}});
      if (layout != Layout::kGlb) d["buffers"][0]["uri"] = buffer_uri(dir, stem, layout);
    }
    for (const auto& [name, bytes] : files) write_bytes(dir / name, bytes);
    const fs::path path = dir / (stem + (layout == Layout::kGlb ? ".glb" : ".gltf"));
    if (layout == Layout::kGlb) {
      write_bytes(path, make_glb(d.dump(), bin));
    } else {
      write_text(path, d.dump(1));
    }
    return path;
  }
};

// A triangle (0,0,0) (1,0,0) (0,1,0): no normals, UVs, indices or material.
Builder triangle() {
  Builder b;
  const int v = b.view(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int a = b.accessor(v, kFloat, 3, "VEC3", {{"min", {0, 0, 0}}, {"max", {1, 1, 0}}});
  b.push("meshes", {{"name", "tri"}, {"primitives", json::array({json{{"attributes", {{"POSITION", a}}}}})}});
  b.push("nodes", {{"mesh", 0}});
  b.doc["scenes"] = json::array({json{{"nodes", {0}}}});
  b.doc["scene"] = 0;
  return b;
}

// The unit quad in z = 0 with normals, UVs, 16-bit indices and a material with a 2x2 PNG base colour.
Builder textured_quad(ImageAt image_at) {
  Builder b;
  const int pos =
      b.accessor(b.view(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}), kFloat, 4, "VEC3");
  const int nrm =
      b.accessor(b.view(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}), kFloat, 4, "VEC3");
  const int uv = b.accessor(b.view(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}), kFloat, 4, "VEC2");
  const int idx = b.accessor(b.view(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}), kUnsignedShort, 6, "SCALAR");
  const json prim = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}},
                     {"indices", idx},
                     {"material", 0},
                     {"mode", 4}};
  b.push("meshes", {{"name", "quad"}, {"primitives", json::array({prim})}});
  const std::vector<uint8_t> png = png_2x2();
  if (image_at == ImageAt::kBufferView) {
    b.push("images", {{"bufferView", b.view(png)}, {"mimeType", "image/png"}, {"name", "checker"}});
  } else if (image_at == ImageAt::kDataUri) {
    b.push("images", {{"uri", "data:image/png;base64," + base64(png)}});
  } else {
    b.files["quad texture.png"] = png;
    b.push("images", {{"uri", "quad%20texture.png"}});  // percent-encoded, as URIs must be
  }
  b.push("textures", {{"source", 0}});
  b.push("materials", {{"name", "painted"},
                       {"pbrMetallicRoughness",
                        {{"baseColorFactor", {0.5, 1.0, 1.0, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}});
  b.push("nodes", {{"mesh", 0}});
  b.doc["scenes"] = json::array({json{{"nodes", {0}}}});
  return b;
}

// ---- Checking results ------------------------------------------------------------------------------------

// The error message of loading `file`, which must fail and name the file.
std::string load_error(const fs::path& file, const Limits& limits = {}) {
  Result<Model> model = load_gltf(file, limits);
  if (model.ok()) {
    ADD_FAILURE() << file << " loaded, but should have failed";
    return {};
  }
  const std::string& message = model.error().message;
  EXPECT_EQ(message.rfind(file.string(), 0), 0u) << "the message does not start with the file: " << message;
  return message;
}

::testing::AssertionResult has_all(const std::string& message,
                                   std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) {
    if (message.find(part) == std::string::npos) {
      return ::testing::AssertionFailure() << "'" << part << "' is missing from: " << message;
    }
  }
  return ::testing::AssertionSuccess();
}

Model load_ok(const fs::path& file, const Limits& limits = {}) {
  Result<Model> model = load_gltf(file, limits);
  if (!model.ok()) {
    ADD_FAILURE() << model.error().message;
    return {};
  }
  return std::move(*model);
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

int count_of(const std::vector<std::string>& warnings, std::string_view part) {
  int n = 0;
  for (const std::string& w : warnings) n += w.find(part) != std::string::npos;
  return n;
}

// ---- Valid files -----------------------------------------------------------------------------------------

// The bare triangle gets generated normals, zero UVs and 0..n-1 indices.
void check_triangle(Layout layout) {
  TempDir dir;
  const Model m = load_ok(triangle().write(dir.path(), "tri", layout));
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_EQ(m.meshes[0].name, "tri");
  ASSERT_EQ(m.meshes[0].primitives.size(), 1u);
  const Primitive& p = m.meshes[0].primitives[0];
  ASSERT_EQ(p.positions.size(), 3u);
  expect_near(p.positions[1], {1, 0, 0});
  expect_near(p.positions[2], {0, 1, 0});
  ASSERT_EQ(p.normals.size(), 3u);
  for (const glm::vec3& n : p.normals) expect_near(n, {0, 0, 1});  // counter-clockwise seen from +Z
  EXPECT_EQ(p.uvs, std::vector<glm::vec2>(3, glm::vec2(0)));
  EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(p.material, -1);
  EXPECT_TRUE(m.materials.empty());
  ASSERT_EQ(m.instances.size(), 1u);
  EXPECT_EQ(m.instances[0].world, glm::mat4(1.0f));
  expect_near(m.bounds_min, {0, 0, 0});
  expect_near(m.bounds_max, {1, 1, 0});
  EXPECT_TRUE(m.warnings.empty());
}

// The quad keeps its attributes, material and pixels, with the image in each of the places it can be.
void check_textured_quad(Layout layout) {
  TempDir dir;
  for (ImageAt image_at : {ImageAt::kBufferView, ImageAt::kDataUri, ImageAt::kFile}) {
    SCOPED_TRACE(static_cast<int>(image_at));
    const Model m = load_ok(textured_quad(image_at).write(dir.path(), "quad", layout));
    ASSERT_EQ(m.meshes.size(), 1u);
    ASSERT_EQ(m.meshes[0].primitives.size(), 1u);
    const Primitive& p = m.meshes[0].primitives[0];
    ASSERT_EQ(p.positions.size(), 4u);
    expect_near(p.positions[2], {1, 1, 0});
    ASSERT_EQ(p.normals.size(), 4u);
    expect_near(p.normals[3], {0, 0, 1});
    ASSERT_EQ(p.uvs.size(), 4u);
    EXPECT_EQ(p.uvs[1], glm::vec2(1, 1));
    EXPECT_EQ(p.uvs[3], glm::vec2(0, 0));
    EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(p.material, 0);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].name, "painted");
    EXPECT_EQ(m.materials[0].base_color_factor, glm::vec4(0.5f, 1, 1, 1));
    EXPECT_EQ(m.materials[0].base_color.image, 0);
    ASSERT_EQ(m.textures.size(), 1u);
    EXPECT_EQ(m.textures[0].width, 2u);
    EXPECT_EQ(m.textures[0].height, 2u);
    EXPECT_EQ(m.textures[0].rgba, kPixels);
    expect_near(m.bounds_min, {0, 0, 0});
    expect_near(m.bounds_max, {1, 1, 0});
  }
}

TEST(GltfTriangle, DataUri) {
  check_triangle(Layout::kDataUri);
}
TEST(GltfTriangle, SeparateBin) {
  check_triangle(Layout::kSeparateBin);
}
TEST(GltfTriangle, Glb) {
  check_triangle(Layout::kGlb);
}
TEST(GltfTexturedQuad, DataUri) {
  check_textured_quad(Layout::kDataUri);
}
TEST(GltfTexturedQuad, SeparateBin) {
  check_textured_quad(Layout::kSeparateBin);
}
TEST(GltfTexturedQuad, Glb) {
  check_textured_quad(Layout::kGlb);
}

TEST(GltfLoad, ChildOfTransformedParentGetsComposedWorldMatrixAndBounds) {
  TempDir dir;
  Builder b = triangle();
  const double s = std::sqrt(0.5);  // 90 degrees about +Y: x goes to -z
  b.doc["nodes"] = json::array(
      {json{{"children", {1}}, {"translation", {1, 2, 3}}, {"rotation", {0, s, 0, s}}, {"scale", {2, 2, 2}}},
       json{{"mesh", 0}, {"translation", {1, 0, 0}}},
       // A second root given as a column-major matrix: translation (10, 0, 0).
       json{{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}}});
  b.doc["scenes"][0]["nodes"] = {0, 2};
  const Model m = load_ok(b.write(dir.path(), "tree", Layout::kGlb));
  ASSERT_EQ(m.instances.size(), 2u);
  const glm::mat4 expected =
      glm::translate(glm::mat4(1), glm::vec3(1, 2, 3)) * glm::mat4_cast(glm::quat(float(s), 0, float(s), 0)) *
      glm::scale(glm::mat4(1), glm::vec3(2)) * glm::translate(glm::mat4(1), glm::vec3(1, 0, 0));
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(m.instances[0].world[c][r], expected[c][r], 1e-5f);
  }
  // Worked by hand: child origin -> (1,0,0) -> scaled (2,0,0) -> rotated (0,0,-2) -> moved (1,2,1).
  expect_near(glm::vec3(m.instances[0].world * glm::vec4(0, 0, 0, 1)), {1, 2, 1});
  expect_near(glm::vec3(m.instances[1].world * glm::vec4(0, 1, 0, 1)), {10, 1, 0});
  // Triangle corners in world space: (1,2,1), (1,2,-1), (1,4,1) and (10,0,0), (11,0,0), (10,1,0).
  expect_near(m.bounds_min, {1, 0, -1});
  expect_near(m.bounds_max, {11, 4, 1});
}

TEST(GltfLoad, FileWithoutScenesDrawsEveryRootNode) {
  TempDir dir;
  Builder b = triangle();
  b.doc.erase("scenes");
  b.doc.erase("scene");
  b.doc["nodes"] = json::array({json{{"mesh", 0}, {"children", {1}}}, json{{"mesh", 0}}, json{{"mesh", 0}}});
  EXPECT_EQ(load_ok(b.write(dir.path(), "m", Layout::kDataUri)).instances.size(), 3u);
}

TEST(GltfLoad, RelativeUriIntoSubfolderIsRead) {
  TempDir dir;
  Builder b = triangle();
  fs::create_directories(dir / "data");
  write_bytes(dir / "data" / "tri.bin", b.bin);
  b.doc["buffers"] = json::array({json{{"byteLength", b.bin.size()}, {"uri", "./data/../data/tri.bin"}}});
  EXPECT_EQ(load_ok(b.write(dir.path(), "m", Layout::kSeparateBin)).meshes.size(), 1u);
}

TEST(GltfLoad, NormalizedByteTexcoordsAreScaled) {
  TempDir dir;
  Builder b = triangle();
  const int uv = b.accessor(b.view(std::vector<uint8_t>{0, 255, 255, 0, 51, 102}), kUnsignedByte, 3, "VEC2",
                            {{"normalized", true}});
  b.primitive()["attributes"]["TEXCOORD_0"] = uv;
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  const std::vector<glm::vec2>& uvs = m.meshes[0].primitives[0].uvs;
  ASSERT_EQ(uvs.size(), 3u);
  EXPECT_EQ(uvs[0], glm::vec2(0, 1));
  EXPECT_NEAR(uvs[2].x, 0.2f, 1e-6f);
  EXPECT_NEAR(uvs[2].y, 0.4f, 1e-6f);
}

TEST(GltfLoad, InterleavedAttributesUseTheStride) {
  TempDir dir;
  Builder b;
  // position xyz + uv per vertex: 20 bytes of stride.
  const std::vector<float> data = {0, 0, 0, 0.1f, 0.2f, 1, 0, 0, 0.3f, 0.4f, 0, 1, 0, 0.5f, 0.6f};
  const int v = b.view(data, 20);
  const int pos = b.accessor(v, kFloat, 3, "VEC3");
  const int uv = b.accessor(v, kFloat, 3, "VEC2", {{"byteOffset", 12}});
  b.push("meshes",
         {{"primitives", json::array({json{{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}}})}});
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  const Primitive& p = m.meshes[0].primitives[0];
  expect_near(p.positions[2], {0, 1, 0});
  EXPECT_EQ(p.uvs[1], glm::vec2(0.3f, 0.4f));
}

TEST(GltfLoad, SparseAccessorReplacesListedElements) {
  TempDir dir;
  Builder b = triangle();
  const int idx = b.view(std::vector<uint16_t>{2, 0});
  const int val = b.view(std::vector<float>{5, 5, 5});
  b.doc["accessors"][0]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", idx}, {"componentType", kUnsignedShort}}},
                                     {"values", {{"bufferView", val}}}};
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  expect_near(m.meshes[0].primitives[0].positions[2], {5, 5, 5});
  expect_near(m.meshes[0].primitives[0].positions[1], {1, 0, 0});
}

TEST(GltfLoad, StripsAndFansBecomeTriangleLists) {
  TempDir dir;
  Builder b = triangle();
  const int pos =
      b.accessor(b.view(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}), kFloat, 4, "VEC3");
  b.doc["meshes"][0]["primitives"] = json::array({json{{"attributes", {{"POSITION", pos}}}, {"mode", 5}},
                                                  json{{"attributes", {{"POSITION", pos}}}, {"mode", 6}}});
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  ASSERT_EQ(m.meshes[0].primitives.size(), 2u);
  EXPECT_EQ(m.meshes[0].primitives[0].indices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
  EXPECT_EQ(m.meshes[0].primitives[1].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  for (const glm::vec3& n : m.meshes[0].primitives[0].normals) expect_near(n, {0, 0, 1});
}

TEST(GltfLoad, JpegTextureIsDecoded) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  const std::vector<uint8_t> solid(8 * 8 * 3, 200);
  std::vector<uint8_t> jpeg;
  stbi_write_jpg_to_func(append_to_vector, &jpeg, 8, 8, 3, solid.data(), 95);
  b.doc["images"][0] = {{"bufferView", b.view(jpeg)}, {"mimeType", "image/jpeg"}};
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].width, 8u);
  EXPECT_NEAR(m.textures[0].rgba[0], 200, 3);
  EXPECT_EQ(m.textures[0].rgba[3], 255);
}

// EXT_texture_webp: the texture shows the WebP its extension names, not the PNG given as a fallback for
// viewers without WebP; the extension may be required. A missing or wrong index is named with its field.
TEST(GltfLoad, WebpTextureOfExtTextureWebpIsDecodedInsteadOfTheFallback) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  // 2x2 of other colours than kPixels, so which image was taken shows.
  const std::vector<uint8_t> webp_pixels = {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 200, 1, 2, 3, 4};
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(webp_pixels.data(), 2, 2, 8, &encoded);
  ASSERT_GT(size, 0u);
  const std::vector<uint8_t> webp(encoded, encoded + size);
  WebPFree(encoded);
  b.push("images", {{"bufferView", b.view(webp)}, {"mimeType", "image/webp"}});
  b.doc["textures"][0]["extensions"] = {{"EXT_texture_webp", {{"source", 1}}}};
  b.doc["extensionsUsed"] = {"EXT_texture_webp"};
  b.doc["extensionsRequired"] = {"EXT_texture_webp"};
  Result<Model> m = load_gltf(b.write(dir.path(), "w", Layout::kGlb), {});
  ASSERT_TRUE(m.ok()) << m.error().message;
  ASSERT_EQ(m->textures.size(), 1u);
  EXPECT_EQ(m->textures[0].rgba, webp_pixels);
  EXPECT_EQ(count_of(m->warnings, "EXT_texture_webp"), 0);

  b.doc["textures"][0]["extensions"]["EXT_texture_webp"]["source"] = 7;
  EXPECT_TRUE(has_all(load_error(b.write(dir.path(), "w7", Layout::kGlb)),
                      {"textures[0].extensions.EXT_texture_webp.source: images[7] does not exist"}));
  b.doc["textures"][0]["extensions"]["EXT_texture_webp"] = json::object();
  EXPECT_TRUE(has_all(load_error(b.write(dir.path(), "wnone", Layout::kGlb)),
                      {"textures[0].extensions.EXT_texture_webp.source: missing or not an image index"}));
}

TEST(GltfLoad, SharedImageIsDecodedOnce) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  b.push("textures", {{"source", 0}});
  b.push("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}});
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  EXPECT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.materials[1].base_color.image, 0);
}

// ---- Warnings --------------------------------------------------------------------------------------------

TEST(GltfWarnings, UnsupportedFeaturesWarnOncePerKind) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  b.doc["skins"] = json::array({json{{"joints", {0}}}});
  b.doc["nodes"] =
      json::array({json{{"mesh", 0}, {"skin", 0}, {"camera", 0}}, json{{"mesh", 0}, {"skin", 0}}});
  b.doc["scenes"][0]["nodes"] = {0, 1};
  b.doc["cameras"] =
      json::array({json{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}});
  b.doc["animations"] = json::array();
  b.doc["animations"].push_back({{"channels", json::array()}, {"samplers", json::array()}});
  b.doc["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_lights_punctual"};
  b.doc["materials"][0]["extensions"] = {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}}};
  b.push("materials", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.5}}}}}});
  b.primitive()["targets"] = json::array({json{{"POSITION", 0}}});
  json lines = b.primitive();
  lines["mode"] = 1;
  b.doc["meshes"][0]["primitives"].push_back(lines);
  b.doc["meshes"][0]["primitives"].push_back(lines);
  const Model m = load_ok(b.write(dir.path(), "m", Layout::kGlb));
  for (std::string_view kind :
       {"skins", "animations", "morph targets", "point and line", "'KHR_materials_clearcoat'"}) {
    EXPECT_EQ(count_of(m.warnings, kind), 1) << kind;
  }
  // Cameras (Model::cameras) and KHR_lights_punctual (Model::lights) are read, not warned about.
  EXPECT_EQ(count_of(m.warnings, "KHR_lights_punctual"), 0);
  EXPECT_EQ(m.warnings.size(), 5u);
  EXPECT_EQ(m.cameras.size(), 1u);
  EXPECT_EQ(m.meshes[0].primitives.size(), 1u);  // the line primitives were skipped
  EXPECT_EQ(m.instances.size(), 2u);
}

// ---- Cameras ---------------------------------------------------------------------------------------------

TEST(GltfCameras, ACameraNodeGivesItsWorldTransformAndLens) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  // The camera node is a child of a translated parent and turned 90° about +y: its −Z (the view) is world −x.
  b.doc["nodes"] =
      json::array({json{{"mesh", 0}}, json{{"translation", {1, 2, 3}}, {"children", {2}}},
                   json{{"name", "deck"}, {"camera", 0}, {"rotation", {0, 0.70710678, 0, 0.70710678}}}});
  b.doc["scenes"][0]["nodes"] = {0, 1};
  b.doc["cameras"] = json::array(
      {json{{"name", "bridge"},
            {"type", "perspective"},
            {"perspective", {{"yfov", 0.6}, {"znear", 0.5}, {"zfar", 200.0}, {"aspectRatio", 1.5}}}}});
  const Model m = load_ok(b.write(dir.path(), "cam", Layout::kDataUri));
  ASSERT_EQ(m.cameras.size(), 1u);
  const Camera& c = m.cameras[0];
  EXPECT_EQ(c.name, "bridge");
  EXPECT_EQ(c.node_name, "deck");
  EXPECT_TRUE(c.perspective);
  EXPECT_FLOAT_EQ(c.yfov_rad, 0.6f);
  EXPECT_FLOAT_EQ(c.znear, 0.5f);
  EXPECT_FLOAT_EQ(c.zfar, 200.0f);
  const glm::vec3 position(c.world[3]), view = -glm::vec3(c.world[2]), up(c.world[1]);
  EXPECT_NEAR(glm::distance(position, glm::vec3(1, 2, 3)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(view, glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(up, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
}

TEST(GltfCameras, BrokenCamerasAreRefusedAndOrthographicOnesMarked) {
  TempDir dir;
  auto with_camera = [](json camera, int node_camera = 0) {
    Builder b = textured_quad(ImageAt::kBufferView);
    b.doc["nodes"].push_back(json{{"camera", node_camera}});
    b.doc["scenes"][0]["nodes"].push_back(int(b.doc["nodes"].size()) - 1);
    b.doc["cameras"] = json::array({std::move(camera)});
    return b;
  };
  const json lens = {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}};
  json zero_fov = lens;
  zero_fov["perspective"]["yfov"] = 0.0;
  EXPECT_NE(load_error(with_camera(zero_fov).write(dir.path(), "a", Layout::kDataUri))
                .find("cameras[0].perspective.yfov"),
            std::string::npos);
  json far_before_near = lens;
  far_before_near["perspective"]["zfar"] = 0.05;
  EXPECT_NE(load_error(with_camera(far_before_near).write(dir.path(), "b", Layout::kDataUri))
                .find("cameras[0].perspective.zfar"),
            std::string::npos);
  EXPECT_NE(
      load_error(with_camera(lens, 3).write(dir.path(), "c", Layout::kDataUri)).find(".camera: cameras[3]"),
      std::string::npos);
  const json ortho = {{"type", "orthographic"},
                      {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}};
  const Model m = load_ok(with_camera(ortho).write(dir.path(), "d", Layout::kDataUri));
  ASSERT_EQ(m.cameras.size(), 1u);
  EXPECT_FALSE(m.cameras[0].perspective);
  EXPECT_EQ(m.cameras[0].name, "cameras[0]");  // neither the camera nor its node has a name
}

TEST(GltfLights, PunctualLightsComeWithTheirNodesWorldTransform) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensionsRequired"] = {"KHR_lights_punctual"};  // read, so requiring it is fine
  b.doc["extensions"] = {
      {"KHR_lights_punctual",
       {{"lights", json::array({json{{"name", "lamp"},
                                     {"type", "point"},
                                     {"color", {1.0, 0.5, 0.25}},
                                     {"intensity", 40.0},
                                     {"range", 12.0}},
                                json{{"type", "spot"},
                                     {"intensity", 5.0},
                                     {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
                                json{{"type", "directional"}, {"intensity", 3.0}}})}}}};
  b.doc["nodes"] = json::array({json{{"mesh", 0}, {"translation", {0, 1, 0}}, {"children", {1, 2}}},
                                json{{"name", "mast"},
                                     {"translation", {0, 2, 0}},
                                     {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                                json{{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}});
  b.doc["scenes"][0]["nodes"] = {0};
  const Model m = load_ok(b.write(dir.path(), "lamp", Layout::kDataUri));
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
  ASSERT_EQ(m.lights.size(), 2u);  // the directional light's node is not in the scene
  const Light& lamp = m.lights[0];
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_EQ(lamp.type, Light::Type::Point);
  EXPECT_EQ(lamp.colour, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(lamp.intensity, 40.0f);
  EXPECT_FLOAT_EQ(lamp.range_m, 12.0f);
  EXPECT_NEAR(glm::distance(glm::vec3(lamp.world[3]), glm::vec3(0, 3, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(m.lights[1].type, Light::Type::Spot);
  EXPECT_FLOAT_EQ(m.lights[1].outer_cone_rad, 0.5f);
  EXPECT_EQ(m.lights[1].name, "lights[1]");
  // Broken references and numbers are refused, naming them.
  b.doc["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 7;
  EXPECT_NE(
      load_error(b.write(dir.path(), "bad1", Layout::kDataUri)).find("KHR_lights_punctual.light: lights[7]"),
      std::string::npos);
  b.doc["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  b.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -1.0;
  EXPECT_NE(load_error(b.write(dir.path(), "bad2", Layout::kDataUri)).find("lights[0].intensity"),
            std::string::npos);
}

// ---- Files that are not glTF -----------------------------------------------------------------------------

TEST(GltfFile, MissingFileIsNamed) {
  TempDir dir;
  EXPECT_TRUE(has_all(load_error(dir / "nope.gltf"), {"nope.gltf", "does not exist"}));
}

TEST(GltfFile, FolderAndFifoAreRefusedWithoutBlocking) {
  TempDir dir;
  fs::create_directories(dir / "folder.gltf");
  EXPECT_TRUE(has_all(load_error(dir / "folder.gltf"), {"is a folder"}));
  ASSERT_EQ(::mkfifo((dir / "pipe.glb").c_str(), 0600), 0);
  EXPECT_TRUE(has_all(load_error(dir / "pipe.glb"), {"not a regular file"}));
}

TEST(GltfFile, UnreadableFileSaysWhy) {
  TempDir dir;
  const fs::path path = triangle().write(dir.path(), "m", Layout::kDataUri);
  fs::permissions(path, fs::perms::none);
  if (std::ifstream(path).good()) GTEST_SKIP() << "running with permission to read anything (root)";
  EXPECT_TRUE(has_all(load_error(path), {"cannot be opened", "Permission denied"}));
}

TEST(GltfFile, TextIsNotGltfAndTinygltfSaysWhy) {
  TempDir dir;
  write_text(dir / "a.gltf", "hello, I am not JSON");
  EXPECT_TRUE(has_all(load_error(dir / "a.gltf"), {"not a valid glTF file", "parse error"}));
  write_text(dir / "b.gltf", R"({"meshes": []})");
  EXPECT_TRUE(has_all(load_error(dir / "b.gltf"), {"not a valid glTF file", "asset"}));
  write_text(dir / "c.gltf", "");
  EXPECT_TRUE(has_all(load_error(dir / "c.gltf"), {"not a valid glTF file", "too short"}));
  write_text(dir / "d.gltf", R"({"asset": {"version": "1.0"}})");
  EXPECT_TRUE(has_all(load_error(dir / "d.gltf"), {"asset.version", "only glTF 2.0"}));
}

TEST(GltfFile, FileLargerThanTheLimitIsRefused) {
  TempDir dir;
  Limits limits;
  limits.max_file_bytes = 100;
  EXPECT_TRUE(has_all(load_error(triangle().write(dir.path(), "m", Layout::kGlb), limits),
                      {"more than the limit of 100"}));
  // The same limit holds for the .bin the .gltf names.
  Builder b = triangle();
  std::vector<float> big(1000, 0.0f);
  b.view(big);
  limits.max_file_bytes = 2000;
  EXPECT_TRUE(has_all(load_error(b.write(dir.path(), "sep", Layout::kSeparateBin), limits),
                      {"buffers[0]", "sep.bin", "more than the limit of 2000"}));
}

TEST(GltfFile, BrokenGlbContainerIsRefused) {
  TempDir dir;
  std::vector<uint8_t> glb = read_bytes(triangle().write(dir.path(), "m", Layout::kGlb));
  std::vector<uint8_t> cut(glb.begin(), glb.begin() + 12);
  write_bytes(dir / "cut.glb", cut);
  EXPECT_TRUE(has_all(load_error(dir / "cut.glb"), {"binary glTF", "header"}));
  // The BIN chunk claims 4 bytes more than the file has: tinygltf alone would read past the end.
  const uint32_t json_length = glb[12] | glb[13] << 8;
  const size_t bin_header = 20 + json_length;
  glb[bin_header] = static_cast<uint8_t>(glb[bin_header] + 4);
  write_bytes(dir / "long.glb", glb);
  EXPECT_TRUE(has_all(load_error(dir / "long.glb"), {"binary glTF", "runs past the end"}));
  glb[4] = 1;
  write_bytes(dir / "v1.glb", glb);
  EXPECT_TRUE(has_all(load_error(dir / "v1.glb"), {"version 1"}));
}

TEST(GltfFile, DeeplyNestedJsonIsRefusedBeforeTinygltfRecursesIntoIt) {
  TempDir dir;
  const std::string deep = R"({"asset": {"version": "2.0"}, "extras": )" + std::string(100000, '[') +
                           std::string(100000, ']') + "}";
  write_text(dir / "deep.gltf", deep);
  EXPECT_TRUE(has_all(load_error(dir / "deep.gltf"), {"JSON", "nested more than 64 deep", "column"}));
}

TEST(GltfFile, RequiredExtensionIsAnErrorUsedOneAWarning) {
  TempDir dir;
  Builder b = triangle();
  b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression", "EXT_mesh_gpu_instancing"};
  b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  EXPECT_TRUE(has_all(load_error(b.write(dir.path(), "req", Layout::kGlb)),
                      {"extensionsRequired", "KHR_draco_mesh_compression", "not supported"}));
  b.doc.erase("extensionsRequired");
  const Model m = load_ok(b.write(dir.path(), "used", Layout::kGlb));
  EXPECT_EQ(count_of(m.warnings, "'KHR_draco_mesh_compression' is not supported"), 1);
  EXPECT_EQ(count_of(m.warnings, "'EXT_mesh_gpu_instancing' is not supported"), 1);
}

// ---- URIs ------------------------------------------------------------------------------------------------

// The triangle with its buffer at `uri`; the loader must refuse it before reading anything.
std::string uri_error(const TempDir& dir, const std::string& uri) {
  Builder b = triangle();
  b.doc["buffers"] = json::array({json{{"byteLength", b.bin.size()}, {"uri", uri}}});
  return load_error(b.write(dir / "model", "m", Layout::kSeparateBin));
}

TEST(GltfUri, AbsoluteUrisAreRefused) {
  TempDir dir;
  fs::create_directories(dir / "model");
  for (const char* uri : {"file:///etc/passwd", "/etc/passwd", "C:\\Windows\\win.ini", "%2Fetc%2Fpasswd",
                          "https://example.com/a.bin"}) {
    EXPECT_TRUE(has_all(uri_error(dir, uri), {"buffers[0].uri", "absolute"})) << uri;
  }
}

TEST(GltfUri, UrisLeadingOutsideTheFolderAreRefused) {
  TempDir dir;
  fs::create_directories(dir / "model" / "sub");
  write_bytes(dir / "secret.bin", triangle().bin);  // exists, so only the check can stop the read
  EXPECT_TRUE(has_all(uri_error(dir, "../secret.bin"), {"buffers[0].uri", "'../secret.bin'", "outside"}));
  EXPECT_TRUE(has_all(uri_error(dir, "sub/../../secret.bin"), {"outside"}));
  EXPECT_TRUE(has_all(uri_error(dir, "..%2Fsecret.bin"), {"decoded '../secret.bin'", "outside"}));
  EXPECT_TRUE(has_all(uri_error(dir, "..\\secret.bin"), {"outside"}));
  fs::create_symlink(dir / "secret.bin", dir / "model" / "link.bin");
  EXPECT_TRUE(has_all(uri_error(dir, "link.bin"), {"buffers[0].uri", "outside the model's folder"}));
}

TEST(GltfUri, MissingBufferAndImageFilesAreNamed) {
  TempDir dir;
  fs::create_directories(dir / "model");
  EXPECT_TRUE(has_all(uri_error(dir, "missing.bin"), {"buffers[0]", "missing.bin", "does not exist"}));
  Builder b = textured_quad(ImageAt::kFile);
  b.files.clear();
  EXPECT_TRUE(has_all(load_error(b.write(dir.path(), "q", Layout::kGlb)),
                      {"images[0]", "quad texture.png", "does not exist"}));
}

TEST(GltfUri, UnsupportedAndBrokenDataUrisAreRefused) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kDataUri);
  b.doc["images"][0]["uri"] = "data:image/webp;base64,AAAA";
  EXPECT_TRUE(has_all(load_error(b.write(dir.path(), "webp", Layout::kGlb)), {"images[0].uri", "data URI"}));
  Builder t = triangle();
  t.doc["buffers"] = json::array({json{{"byteLength", t.bin.size() + 1},
                                       {"uri", "data:application/octet-stream;base64," + base64(t.bin)}}});
  EXPECT_TRUE(has_all(load_error(t.write(dir.path(), "short", Layout::kDataUri)),
                      {"buffers[0].uri", "holds 36 bytes but byteLength is 37"}));
  // What only tinygltf checks comes with its message, kept short even when it quotes a long data: URI.
  Builder u = triangle();
  u.doc["buffers"] =
      json::array({json{{"uri", "data:application/octet-stream;base64," + std::string(4000, 'A')}}});
  const std::string message = load_error(u.write(dir.path(), "nolength", Layout::kDataUri));
  EXPECT_TRUE(has_all(message, {"not a valid glTF file", "byteLength"}));
  EXPECT_LT(message.size(), 600u);
}

// ---- Accessors -------------------------------------------------------------------------------------------

fs::path write_triangle_with(const TempDir& dir, const std::function<void(Builder&)>& edit) {
  Builder b = triangle();
  edit(b);
  return b.write(dir.path(), "m", Layout::kGlb);
}

TEST(GltfAccessor, RangePastTheBufferViewIsRefused) {
  TempDir dir;
  const std::string m =
      load_error(write_triangle_with(dir, [](Builder& b) { b.doc["accessors"][0]["count"] = 4; }));
  EXPECT_TRUE(has_all(m, {"accessors[0]", "count 4", "past the end of bufferViews[0] (36 bytes)"}));
  const std::string o =
      load_error(write_triangle_with(dir, [](Builder& b) { b.doc["accessors"][0]["byteOffset"] = 4; }));
  EXPECT_TRUE(has_all(o, {"accessors[0]", "byteOffset 4", "past the end"}));
}

TEST(GltfAccessor, BufferViewPastItsBufferIsRefused) {
  TempDir dir;
  const std::string m =
      load_error(write_triangle_with(dir, [](Builder& b) { b.doc["bufferViews"][0]["byteLength"] = 40; }));
  EXPECT_TRUE(has_all(m, {"bufferViews[0]", "past the end of buffers[0] (36 bytes)"}));
}

TEST(GltfAccessor, StrideSmallerThanTheElementIsRefused) {
  TempDir dir;
  const std::string m = load_error(write_triangle_with(dir, [](Builder& b) {
    b.doc["bufferViews"][0]["byteStride"] = 8;
    b.doc["accessors"][0]["count"] = 2;
  }));
  EXPECT_TRUE(has_all(m, {"accessors[0]", "byteStride 8", "smaller than the element", "12 bytes"}));
}

TEST(GltfAccessor, WrongAttributeTypesAreRefused) {
  TempDir dir;
  EXPECT_TRUE(has_all(
      load_error(write_triangle_with(dir, [](Builder& b) { b.doc["accessors"][0]["type"] = "VEC2"; })),
      {"meshes[0].primitives[0].attributes.POSITION", "accessors[0]", "VEC2 FLOAT", "VEC3 FLOAT"}));
  EXPECT_TRUE(has_all(load_error(write_triangle_with(dir,
                                                     [](Builder& b) {
                                                       b.primitive()["attributes"]["TEXCOORD_0"] =
                                                           b.accessor(b.view(std::vector<uint8_t>(6)),
                                                                      kUnsignedByte, 3, "VEC2");
                                                     })),
                      {"TEXCOORD_0", "accessors[1]", "VEC2 UNSIGNED_BYTE", "normalized"}));
  EXPECT_TRUE(has_all(
      load_error(write_triangle_with(
          dir,
          [](Builder& b) {
            b.primitive()["indices"] = b.accessor(b.view(std::vector<float>{0, 1, 2}), kFloat, 3, "SCALAR");
          })),
      {"meshes[0].primitives[0].indices", "SCALAR FLOAT", "UNSIGNED_INT"}));
  EXPECT_TRUE(has_all(
      load_error(write_triangle_with(
          dir,
          [](Builder& b) {
            b.primitive()["indices"] = b.accessor(b.view(std::vector<int32_t>{0, 1, 2}), kInt, 3, "SCALAR");
          })),
      {"indices", "accessors[1]"}));
  EXPECT_TRUE(has_all(load_error(write_triangle_with(dir,
                                                     [](Builder& b) {
                                                       b.primitive()["attributes"]["NORMAL"] = b.accessor(
                                                           b.view(std::vector<float>(6)), kFloat, 2, "VEC3");
                                                     })),
                      {"NORMAL", "has 2 elements but POSITION has 3"}));
}

TEST(GltfAccessor, MissingAccessorsAndPositionsAreRefused) {
  TempDir dir;
  EXPECT_TRUE(has_all(
      load_error(write_triangle_with(dir, [](Builder& b) { b.primitive()["attributes"]["POSITION"] = 9; })),
      {"attributes.POSITION", "accessors[9] does not exist"}));
  EXPECT_TRUE(has_all(load_error(write_triangle_with(dir,
                                                     [](Builder& b) {
                                                       b.primitive()["attributes"].erase("POSITION");
                                                       b.primitive()["attributes"]["NORMAL"] = 0;
                                                     })),
                      {"meshes[0].primitives[0].attributes", "POSITION is missing"}));
}

TEST(GltfAccessor, IndexValuesOutOfRangeAreRefused) {
  TempDir dir;
  const std::string m = load_error(write_triangle_with(dir, [](Builder& b) {
    b.primitive()["indices"] = b.accessor(b.view(std::vector<uint32_t>{0, 1, 3}), kUnsignedInt, 3, "SCALAR");
  }));
  EXPECT_TRUE(has_all(m, {"indices", "accessors[1]", "element 2 is 3", "out of range for 3 vertices"}));
  const std::string n = load_error(write_triangle_with(dir, [](Builder& b) {
    b.primitive()["indices"] =
        b.accessor(b.view(std::vector<uint8_t>{0, 1, 2, 0}), kUnsignedByte, 4, "SCALAR");
  }));
  EXPECT_TRUE(has_all(n, {"meshes[0].primitives[0]", "4 indices", "not a multiple of 3"}));
}

TEST(GltfAccessor, NonFinitePositionsAreRefused) {
  TempDir dir;
  Builder b = triangle();
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(b.bin.data() + 4, &inf, 4);
  EXPECT_TRUE(
      has_all(load_error(b.write(dir.path(), "m", Layout::kGlb)), {"POSITION", "vertex 0 is not finite"}));
}

TEST(GltfAccessor, CountsAboveTheLimitsAreRefusedBeforeReading) {
  TempDir dir;
  Limits limits;
  limits.max_vertices = 2;
  EXPECT_TRUE(has_all(load_error(triangle().write(dir.path(), "m", Layout::kGlb), limits),
                      {"attributes.POSITION", "3 vertices", "limit of 2 vertices"}));
  limits = {};
  limits.max_indices = 5;
  EXPECT_TRUE(
      has_all(load_error(textured_quad(ImageAt::kBufferView).write(dir.path(), "q", Layout::kGlb), limits),
              {"meshes[0].primitives[0].indices", "limit of 5 indices"}));
  // A count of 2^40 without a bufferView would be zeros only: it must fail on the limit, not allocate.
  const std::string huge = load_error(write_triangle_with(dir, [](Builder& b) {
    b.doc["accessors"][0].erase("bufferView");
    b.doc["accessors"][0]["count"] = uint64_t{1} << 40;
  }));
  EXPECT_TRUE(has_all(huge, {"limit of 5000000 vertices"}));
}

TEST(GltfAccessor, BrokenSparseAccessorsAreRefused) {
  TempDir dir;
  auto sparse = [&](int index, int count) {
    return write_triangle_with(dir, [=](Builder& b) {
      const int idx = b.view(std::vector<uint16_t>{static_cast<uint16_t>(index), 0});
      const int val = b.view(std::vector<float>{5, 5, 5});
      b.doc["accessors"][0]["sparse"] = {
          {"count", count},
          {"indices", {{"bufferView", idx}, {"componentType", kUnsignedShort}}},
          {"values", {{"bufferView", val}}}};
    });
  };
  EXPECT_TRUE(has_all(load_error(sparse(3, 1)), {"accessors[0].sparse.indices[0] = 3", "out of range"}));
  EXPECT_TRUE(
      has_all(load_error(sparse(0, 2)), {"accessors[0].sparse.values", "past the end of bufferViews[2]"}));
  EXPECT_TRUE(has_all(load_error(sparse(0, 5)), {"accessors[0].sparse", "count 5"}));
}

// ---- Primitives ------------------------------------------------------------------------------------------

TEST(GltfPrimitive, InvalidModeAndMaterialAreRefused) {
  TempDir dir;
  EXPECT_TRUE(has_all(load_error(write_triangle_with(dir, [](Builder& b) { b.primitive()["mode"] = 9; })),
                      {"meshes[0].primitives[0].mode", "9"}));
  EXPECT_TRUE(has_all(load_error(write_triangle_with(dir, [](Builder& b) { b.primitive()["material"] = 2; })),
                      {"meshes[0].primitives[0].material", "materials[2] does not exist"}));
}

// ---- Nodes -----------------------------------------------------------------------------------------------

fs::path write_nodes(const TempDir& dir, const json& nodes, const json& roots) {
  return write_triangle_with(dir, [&](Builder& b) {
    b.doc["nodes"] = nodes;
    b.doc["scenes"][0]["nodes"] = roots;
  });
}

TEST(GltfNodes, CyclesAreRefused) {
  TempDir dir;
  const json cycle = json::array({json{{"children", {1}}}, json{{"children", {2}}}, json{{"children", {0}}}});
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, cycle, json::array())), {"cycle", "nodes[0]", "nodes[2]"}));
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, cycle, {0})), {"cycle"}));
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, json::array({json{{"children", {0}}}}), {0})),
                      {"nodes[0].children[0]", "itself"}));
}

TEST(GltfNodes, NodeUnderTwoParentsIsRefused) {
  TempDir dir;
  const json nodes = json::array({json{{"children", {2}}}, json{{"children", {2}}}, json{{"mesh", 0}}});
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, nodes, {0, 1})),
                      {"nodes[1].children[0]", "nodes[2] is a child of both nodes[0] and nodes[1]"}));
  const json child = json::array({json{{"children", {1}}}, json{{"mesh", 0}}});
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, child, {0, 1})), {"scenes[0].nodes[1]", "not a root"}));
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, child, {0, 0})), {"scenes[0].nodes[1]", "twice"}));
}

TEST(GltfNodes, DeepAndLargeHierarchiesAreRefused) {
  TempDir dir;
  json chain = json::array();
  for (int i = 0; i < 1500; ++i)
    chain.push_back(i + 1 < 1500 ? json{{"children", {i + 1}}} : json{{"mesh", 0}});
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, chain, {0})), {"nested deeper than 1000 levels"}));
  Limits limits;
  limits.max_nodes = 100;
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, chain, {0}), limits), {"nodes:", "1500", "limit of 100"}));
}

TEST(GltfNodes, BadReferencesAndTransformsAreRefused) {
  TempDir dir;
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, json::array({json{{"mesh", 3}}}), {0})),
                      {"nodes[0].mesh", "meshes[3] does not exist"}));
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, json::array({json{{"children", {7}}}}), {0})),
                      {"nodes[0].children[0]", "nodes[7] does not exist"}));
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, json::array({json{{"rotation", {0, 0, 1}}}}), {0})),
                      {"nodes[0].rotation", "expected 4 numbers, got 3"}));
  EXPECT_TRUE(has_all(load_error(write_nodes(dir, json::array({json{{"mesh", 0}}}), {4})),
                      {"scenes[0].nodes[0]", "nodes[4]"}));
  EXPECT_TRUE(has_all(load_error(write_triangle_with(dir, [](Builder& b) { b.doc["scene"] = 5; })),
                      {"scene", "scenes[5] does not exist"}));
}

// ---- Images ----------------------------------------------------------------------------------------------

fs::path write_quad_with(const TempDir& dir, const std::function<void(Builder&)>& edit) {
  Builder b = textured_quad(ImageAt::kBufferView);
  edit(b);
  return b.write(dir.path(), "q", Layout::kGlb);
}

TEST(GltfImage, UndecodableImagesAreNamed) {
  TempDir dir;
  const std::string corrupt = load_error(write_quad_with(dir, [](Builder& b) {
    std::vector<uint8_t> png = png_2x2();
    std::fill(png.begin() + 8, png.end(), 0x5A);  // signature intact, chunks garbage
    b.doc["images"][0]["bufferView"] = b.view(png);
  }));
  // 0x5A5A5A5A as a chunk length: libpng stops at it.
  EXPECT_TRUE(has_all(corrupt, {"images[0] 'checker'", "cannot decode the PNG (libpng: "}));
  const std::string gif = load_error(write_quad_with(dir, [](Builder& b) {
    const std::string bytes = "GIF89a\x01\x00\x01\x00";
    b.doc["images"][0]["bufferView"] = b.view(bytes.data(), bytes.size());
  }));
  EXPECT_TRUE(has_all(gif, {"images[0]", "not a PNG, JPEG or WebP image"}));
}

TEST(GltfImage, TexturesAboveTheLimitsAreRefused) {
  TempDir dir;
  const fs::path quad = write_quad_with(dir, [](Builder&) {});
  Limits limits;
  limits.max_texture_size = 1;
  EXPECT_TRUE(has_all(load_error(quad, limits), {"images[0]", "2x2", "limit of 1"}));
  limits = {};
  limits.max_textures = 0;
  EXPECT_TRUE(has_all(load_error(quad, limits), {"limit of 0 textures"}));
}

TEST(GltfImage, TextureAndImageIndicesOutOfRangeAreRefused) {
  TempDir dir;
  EXPECT_TRUE(
      has_all(load_error(write_quad_with(
                  dir,
                  [](Builder& b) {
                    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5;
                  })),
              {"materials[0].pbrMetallicRoughness.baseColorTexture.index", "textures[5] does not exist"}));
  EXPECT_TRUE(
      has_all(load_error(write_quad_with(dir, [](Builder& b) { b.doc["textures"][0]["source"] = 3; })),
              {"textures[0].source", "images[3] does not exist"}));
  EXPECT_TRUE(
      has_all(load_error(write_quad_with(dir, [](Builder& b) { b.doc["images"][0]["bufferView"] = 40; })),
              {"images[0].bufferView", "bufferViews[40] does not exist"}));
  EXPECT_TRUE(has_all(
      load_error(write_quad_with(dir, [](Builder& b) { b.doc["bufferViews"][4]["byteOffset"] = 100000; })),
      {"images[0]", "bufferViews[4]", "does not fit in buffers[0]"}));
}

// ---- Fuzz ------------------------------------------------------------------------------------------------

// LAGOON_GLTF_FUZZ_SCALE=50 runs 50 times as many variants (same seeds), e.g. under AddressSanitizer.
int fuzz_iterations(int base) {
  const char* scale = std::getenv("LAGOON_GLTF_FUZZ_SCALE");
  return scale ? base * std::max(1, std::atoi(scale)) : base;
}

// Loads every variant `mutate` makes (written as `name`); any outcome but a crash, a hang, an inconsistent
// model or an error message that does not name the file is fine.
void fuzz(const TempDir& dir, const std::string& name, int iterations, uint32_t seed,
          const std::function<std::vector<uint8_t>(std::mt19937&)>& mutate) {
  std::mt19937 rng(seed);
  const fs::path path = dir / name;
  int loaded = 0;
  for (int i = 0; i < iterations; ++i) {
    write_bytes(path, mutate(rng));
    const auto start = std::chrono::steady_clock::now();
    Result<Model> model = load_gltf(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_LT(seconds, 5.0) << "variant " << i << " of seed " << seed;
    if (!model.ok()) {
      ASSERT_EQ(model.error().message.rfind(path.string(), 0), 0u) << model.error().message;
      continue;
    }
    ++loaded;
    for (const Mesh& mesh : model->meshes) {
      for (const Primitive& p : mesh.primitives) {
        for (uint32_t index : p.indices) ASSERT_LT(index, p.positions.size());
        ASSERT_EQ(p.indices.size() % 3, 0u);
        ASSERT_EQ(p.normals.size(), p.positions.size());
        ASSERT_EQ(p.uvs.size(), p.positions.size());
        ASSERT_EQ(p.uvs1.size(), p.positions.size());
        ASSERT_EQ(p.tangents.size(), p.positions.size());
        ASSERT_LT(p.material, static_cast<int>(model->materials.size()));
      }
    }
    for (const Material& m : model->materials) {
      for (const TextureRef* t :
           {&m.base_color, &m.metallic_roughness, &m.normal, &m.occlusion, &m.emissive}) {
        ASSERT_LT(t->image, static_cast<int>(model->textures.size()));
        ASSERT_TRUE(t->texcoord == 0 || t->texcoord == 1);
      }
    }
    for (const Texture& t : model->textures) ASSERT_EQ(t.rgba.size(), size_t{t.width} * t.height * 4);
    for (const Instance& instance : model->instances) ASSERT_LT(instance.mesh, model->meshes.size());
  }
  // Mutations that break everything would test nothing past the parser.
  EXPECT_GT(loaded, 0);
  std::printf("[ fuzz     ] %s: %d of %d variants loaded\n", name.c_str(), loaded, iterations);
}

TEST(GltfFuzz, MutatedGlbBytes) {
  TempDir dir;
  const std::vector<uint8_t> base =
      read_bytes(textured_quad(ImageAt::kBufferView).write(dir.path(), "b", Layout::kGlb));
  const size_t bin_start = 20 + (base[12] | base[13] << 8);
  fuzz(dir, "fuzz.glb", fuzz_iterations(2000), 1, [&](std::mt19937& rng) {
    std::vector<uint8_t> bytes = base;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      // Half of the edits hit the BIN chunk (vertex data, indices, the PNG), which JSON edits cannot reach.
      const bool in_bin = rng() % 2 && bytes.size() > bin_start;  // unless cut off by an earlier edit
      const size_t at = in_bin ? bin_start + rng() % (bytes.size() - bin_start) : rng() % bytes.size();
      switch (rng() % 4) {
        case 0:
          bytes[at] = static_cast<uint8_t>(rng());
          break;
        case 1:
          bytes[at] ^= static_cast<uint8_t>(1u << (rng() % 8));
          break;
        case 2: {  // a 32-bit field set to an edge value
          static constexpr uint32_t kEdges[] = {0,          1,          3,      0x7FFFFFFF,
                                                0x80000000, 0xFFFFFFFF, 0xFFFF, 1u << 24};
          const uint32_t v = kEdges[rng() % std::size(kEdges)];
          const size_t aligned = at & ~size_t{3};
          if (aligned + 4 <= bytes.size()) std::memcpy(bytes.data() + aligned, &v, 4);
          break;
        }
        default:
          if (rng() % 4 == 0) bytes.resize(std::max<size_t>(at, 1));
          break;
      }
    }
    return bytes;
  });
}

// JSON pointers of every value in `j`.
void collect_paths(const json& j, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
  out.push_back(at);
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) collect_paths(value, at / key, out);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) collect_paths(j[i], at / i, out);
  }
}

json edge_value(std::mt19937& rng) {
  switch (rng() % 14) {
    case 0:
      return -1;
    case 1:
      return 0;
    case 2:
      return 1;
    case 3:
      return 3;
    case 4:
      return 4294967295u;
    case 5:
      return uint64_t{1} << 62;
    case 6:
      return 2147483648.5;
    case 7:
      return "../x.bin";
    case 8:
      return "data:application/octet-stream;base64,AAAA";
    case 9:
      return json::array({0, 1, 2});
    case 10:
      return json::object();
    case 11:
      return nullptr;
    case 12:
      return "VEC3";
    default:
      return 1e300;
  }
}

// Values of the textured quad's JSON replaced by edge values, nudged or deleted; the binary data intact.
void fuzz_json_values(const TempDir& dir, Layout layout, uint32_t seed) {
  Builder base = textured_quad(ImageAt::kFile);
  base.view(std::vector<uint16_t>{0, 1, 2, 3});  // unused data for mutated offsets to point at
  const fs::path written = base.write(dir.path(), "fuzz", layout);  // with the .bin and .png it names
  json doc = layout == Layout::kGlb ? base.doc : json::parse(read_bytes(written));
  if (layout == Layout::kGlb) doc["buffers"] = json::array({json{{"byteLength", base.bin.size()}}});
  std::vector<json::json_pointer> paths;
  collect_paths(doc, json::json_pointer(), paths);
  fuzz(dir, written.filename().string(), fuzz_iterations(1500), seed, [&](std::mt19937& rng) {
    json d = doc;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const json::json_pointer& p = paths[rng() % paths.size()];
      if (p.empty() || !d.contains(p)) continue;
      if (rng() % 5 == 0) {
        json& parent = d[p.parent_pointer()];
        if (parent.is_object()) parent.erase(p.back());
        continue;
      }
      d[p] = d[p].is_number() && rng() % 2 ? json(d[p].get<double>() + static_cast<int>(rng() % 9) - 4)
                                           : edge_value(rng);
    }
    const std::string text = d.dump();
    return layout == Layout::kGlb ? make_glb(text, base.bin) : std::vector<uint8_t>(text.begin(), text.end());
  });
}

TEST(GltfFuzz, MutatedJsonValuesWithSeparateFiles) {
  TempDir dir;
  fuzz_json_values(dir, Layout::kSeparateBin, 2);
}

TEST(GltfFuzz, MutatedJsonValuesInGlb) {
  TempDir dir;
  fuzz_json_values(dir, Layout::kGlb, 3);
}

TEST(GltfFuzz, MutatedJsonText) {
  TempDir dir;
  const std::vector<uint8_t> text =
      read_bytes(textured_quad(ImageAt::kDataUri).write(dir.path(), "t", Layout::kDataUri));
  fuzz(dir, "fuzz.gltf", fuzz_iterations(1500), 4, [&](std::mt19937& rng) {
    std::vector<uint8_t> t = text;
    const int edits = 1 + static_cast<int>(rng() % 3);
    static constexpr char kChars[] = "[]{},:\"0123456789-.e";
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % t.size();
      if (rng() % 3 == 0) {
        t.erase(t.begin() + static_cast<std::ptrdiff_t>(at));
      } else {
        t[at] = static_cast<uint8_t>(kChars[rng() % (sizeof kChars - 1)]);
      }
    }
    return t;
  });
}

// ---- Materials, samplers, tangents, quantized meshes (issue 17) ------------------------------------------

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}

// The textured quad with a second uv set (u and v swapped) and every material slot filled.
Builder pbr_quad() {
  Builder b = textured_quad(ImageAt::kBufferView);
  const int uv1 = b.accessor(b.view(std::vector<float>{1, 0, 1, 1, 0, 1, 0, 0}), kFloat, 4, "VEC2");
  b.primitive()["attributes"]["TEXCOORD_1"] = uv1;
  json& m = b.doc["materials"][0];
  m["pbrMetallicRoughness"]["metallicFactor"] = 0.25;
  m["pbrMetallicRoughness"]["roughnessFactor"] = 0.6;
  m["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {
      {"index", 0},
      {"extensions",
       {{"KHR_texture_transform",
         {{"offset", {0.5, 0}}, {"rotation", 1.5707963267948966}, {"scale", {2, 3}}, {"texCoord", 1}}}}}};
  m["normalTexture"] = {{"index", 0}, {"texCoord", 1}, {"scale", 0.5}};
  m["occlusionTexture"] = {{"index", 0}, {"strength", 0.7}};
  m["emissiveTexture"] = {{"index", 0}};
  m["emissiveFactor"] = {1.0, 0.5, 0.0};
  m["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}};
  m["alphaMode"] = "MASK";
  m["alphaCutoff"] = 0.3;
  m["doubleSided"] = true;
  b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_emissive_strength"};
  return b;
}

TEST(GltfMaterials, EverySlotFactorAndExtensionIsRead) {
  TempDir dir;
  const Model m = load_ok(pbr_quad().write(dir.path(), "m", Layout::kGlb));
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
  ASSERT_EQ(m.materials.size(), 1u);
  const Material& mat = m.materials[0];
  EXPECT_FLOAT_EQ(mat.metallic, 0.25f);
  EXPECT_FLOAT_EQ(mat.roughness, 0.6f);
  EXPECT_FLOAT_EQ(mat.normal_scale, 0.5f);
  EXPECT_FLOAT_EQ(mat.occlusion_strength, 0.7f);
  expect_near(mat.emissive_factor, glm::vec3(4, 2, 0));  // times KHR_materials_emissive_strength
  EXPECT_EQ(mat.alpha_mode, Material::AlphaMode::Mask);
  EXPECT_FLOAT_EQ(mat.alpha_cutoff, 0.3f);
  EXPECT_TRUE(mat.double_sided);
  EXPECT_EQ(m.textures.size(), 1u);  // one image behind all five slots, decoded once
  for (const TextureRef* t :
       {&mat.base_color, &mat.metallic_roughness, &mat.normal, &mat.occlusion, &mat.emissive})
    EXPECT_EQ(t->image, 0);
  EXPECT_EQ(mat.normal.texcoord, 1);
  EXPECT_EQ(mat.occlusion.texcoord, 0);
  // KHR_texture_transform: uv' = T·R·S·uv with the spec's R = [[cos, sin], [−sin, cos]]; (1, 0) → S (2, 0)
  // → R (0, −2) → T (0.5, −2). Its texCoord overrides the textureInfo's.
  const glm::vec3 moved = mat.metallic_roughness.transform * glm::vec3(1, 0, 1);
  expect_near(moved, glm::vec3(0.5f, -2.0f, 1.0f));
  EXPECT_EQ(mat.metallic_roughness.texcoord, 1);
  expect_near(mat.base_color.transform * glm::vec3(0.3f, 0.7f, 1), glm::vec3(0.3f, 0.7f, 1));
  const Primitive& p = m.meshes[0].primitives[0];
  ASSERT_EQ(p.uvs1.size(), 4u);
  EXPECT_EQ(p.uvs1[1], glm::vec2(1, 1));
  EXPECT_EQ(p.uvs1[2], glm::vec2(0, 1));
}

TEST(GltfMaterials, OutOfRangeValuesAreRefusedByName) {
  TempDir dir;
  struct Case {
    std::function<void(json&)> edit;
    const char* message;
  };
  const std::vector<Case> cases = {
      {[](json& m) { m["pbrMetallicRoughness"]["metallicFactor"] = 2.0; },
       "materials[0].pbrMetallicRoughness.metallicFactor: must be between 0 and 1"},
      {[](json& m) { m["alphaMode"] = "SOMETIMES"; }, "materials[0].alphaMode: 'SOMETIMES' is not OPAQUE"},
      {[](json& m) { m["alphaCutoff"] = -1.0; }, "materials[0].alphaCutoff: must be a number >= 0"},
      {[](json& m) {
         m["emissiveFactor"] = {1.0, -1.0, 0.0};
       },
       "materials[0].emissiveFactor"},
      {[](json& m) { m["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -2.0; },
       "KHR_materials_emissive_strength.emissiveStrength: must be >= 0"},
      {[](json& m) { m["normalTexture"]["index"] = 7; },
       "materials[0].normalTexture.index: textures[7] does not exist"},
      {[](json& m) {
         m["pbrMetallicRoughness"]["metallicRoughnessTexture"]["extensions"]["KHR_texture_transform"]
          ["scale"] = "big";
       },
       "metallicRoughnessTexture.extensions.KHR_texture_transform.scale: expected 2 finite numbers"},
  };
  for (const Case& c : cases) {
    Builder b = pbr_quad();
    c.edit(b.doc["materials"][0]);
    expect_contains(load_error(b.write(dir.path(), "bad", Layout::kGlb)), c.message);
  }
}

TEST(GltfSamplers, EveryWrapAndFilterModeIsRead) {
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  // GL enums: 9728 NEAREST, 9729 LINEAR, 9984-9987 the mipmapped minifications; 10497 REPEAT, 33071
  // CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT.
  struct Mode {
    json sampler;
    Sampler expected;
  };
  using W = Sampler::Wrap;
  using F = Sampler::Filter;
  const std::vector<Mode> modes = {
      {json::object(), Sampler{}},
      {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33648}},
       Sampler{W::ClampToEdge, W::MirroredRepeat, F::Nearest, F::Nearest, false, F::Linear}},
      {{{"magFilter", 9729}, {"minFilter", 9729}},
       Sampler{W::Repeat, W::Repeat, F::Linear, F::Linear, false, F::Linear}},
      {{{"minFilter", 9984}}, Sampler{W::Repeat, W::Repeat, F::Linear, F::Nearest, true, F::Nearest}},
      {{{"minFilter", 9985}}, Sampler{W::Repeat, W::Repeat, F::Linear, F::Linear, true, F::Nearest}},
      {{{"minFilter", 9986}}, Sampler{W::Repeat, W::Repeat, F::Linear, F::Nearest, true, F::Linear}},
      {{{"minFilter", 9987}, {"wrapS", 10497}},
       Sampler{W::Repeat, W::Repeat, F::Linear, F::Linear, true, F::Linear}},
  };
  for (size_t i = 0; i < modes.size(); ++i) {
    b.doc["samplers"] = json::array({modes[i].sampler});
    b.doc["textures"][0]["sampler"] = 0;
    const Model m = load_ok(b.write(dir.path(), "s", Layout::kGlb));
    EXPECT_TRUE(m.materials[0].base_color.sampler == modes[i].expected) << "mode " << i;
  }
  b.doc["samplers"] = json::array({json{{"magFilter", 9986}}});
  expect_contains(load_error(b.write(dir.path(), "bad", Layout::kGlb)),
                  "samplers[0].magFilter: must be 9728 or 9729");
  b.doc["samplers"] = json::array({json{{"wrapT", 1}}});
  expect_contains(load_error(b.write(dir.path(), "bad", Layout::kGlb)), "samplers[0].wrapS/wrapT");
  b.doc["textures"][0]["sampler"] = 3;
  expect_contains(load_error(b.write(dir.path(), "bad", Layout::kGlb)),
                  "textures[0].sampler: samplers[3] does not exist");
}

TEST(GltfTangents, GeneratedTangentsPointAlongUAndKnowTheirHandedness) {
  TempDir dir;
  // The quad's u grows along +x and v along −y (uv (0,1) at the origin): tangent +x, and the bitangent
  // (the direction of growing v) −y = −(n × t), so w = −1.
  Model m = load_ok(textured_quad(ImageAt::kBufferView).write(dir.path(), "q", Layout::kGlb));
  const Primitive& p = m.meshes[0].primitives[0];
  ASSERT_EQ(p.tangents.size(), 4u);
  for (const glm::vec4& t : p.tangents) {
    expect_near(glm::vec3(t), glm::vec3(1, 0, 0));
    EXPECT_EQ(t.w, -1.0f);
  }
  // u along +y, v along +x: tangent +y, bitangent +x = −(z × y): w = −1; v along −x: w = +1.
  for (float sign : {1.0f, -1.0f}) {
    Builder b = textured_quad(ImageAt::kBufferView);
    const float o = sign > 0 ? 0.0f : 1.0f;
    const int uv = b.accessor(b.view(std::vector<float>{0, o, 0, 1 - o, 1, 1 - o, 1, o}), kFloat, 4, "VEC2");
    b.primitive()["attributes"]["TEXCOORD_0"] = uv;
    m = load_ok(b.write(dir.path(), "r", Layout::kGlb));
    for (const glm::vec4& t : m.meshes[0].primitives[0].tangents) {
      expect_near(glm::vec3(t), glm::vec3(0, 1, 0));
      EXPECT_EQ(t.w, -sign);
    }
  }
  // A file's own tangents are kept (normalised).
  Builder b = textured_quad(ImageAt::kBufferView);
  const int tan = b.accessor(b.view(std::vector<float>{0, 2, 0, 1, 0, 2, 0, 1, 0, 2, 0, 1, 0, 2, 0, 1}),
                             kFloat, 4, "VEC4");
  b.primitive()["attributes"]["TANGENT"] = tan;
  m = load_ok(b.write(dir.path(), "t", Layout::kGlb));
  expect_near(glm::vec3(m.meshes[0].primitives[0].tangents[2]), glm::vec3(0, 1, 0));
  EXPECT_EQ(m.meshes[0].primitives[0].tangents[2].w, 1.0f);
}

TEST(GltfQuantization, IntegerAttributesLoadWithTheExtensionAndAreRefusedWithout) {
  TempDir dir;
  Builder b;
  // Positions as plain SHORTs (a node scale brings them to metres), normals as normalized BYTEs,
  // texcoords as plain UNSIGNED_SHORTs: KHR_mesh_quantization's typical layout.
  // Vertex elements are 4-byte aligned: SHORT VEC3 and BYTE VEC3 are padded (strides 8 and 4).
  const int pos = b.accessor(b.view(std::vector<int16_t>{0, 0, 0, 0, 1000, 0, 0, 0, 0, 1000, 0, 0}, 8),
                             kShort, 3, "VEC3", {{"min", {0, 0, 0}}, {"max", {1000, 1000, 0}}});
  const int nrm = b.accessor(b.view(std::vector<int8_t>{0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0}, 4), kByte,
                             3, "VEC3", {{"normalized", true}});
  const int uv = b.accessor(b.view(std::vector<uint16_t>{0, 0, 2, 0, 0, 2}), kUnsignedShort, 3, "VEC2");
  b.push("meshes",
         {{"primitives",
           json::array({json{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}}})}});
  b.push("nodes", {{"mesh", 0}, {"scale", {0.001, 0.001, 0.001}}});
  b.doc["scenes"] = json::array({json{{"nodes", {0}}}});
  expect_contains(load_error(b.write(dir.path(), "plain", Layout::kGlb)), "VEC3 FLOAT");
  b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  const Model m = load_ok(b.write(dir.path(), "q", Layout::kGlb));
  EXPECT_TRUE(m.warnings.empty());
  const Primitive& p = m.meshes[0].primitives[0];
  expect_near(p.positions[1], glm::vec3(1000, 0, 0));
  expect_near(p.normals[2], glm::vec3(0, 0, 1));
  EXPECT_EQ(p.uvs[1], glm::vec2(2, 0));
  expect_near(m.bounds_max, glm::vec3(1, 1, 0), 1e-4f);
}

TEST(GltfLoad, NodesOnlyReadsCamerasWithoutDecodingImagesOrMeshes) {
  // camera.gltf reads only the nodes: a model whose image is broken still gives its camera, quickly.
  TempDir dir;
  Builder b = textured_quad(ImageAt::kBufferView);
  b.doc["images"][0] = {{"bufferView", b.view(std::vector<uint8_t>{0x89, 'P', 'N', 'G', 1, 2, 3})},
                        {"mimeType", "image/png"}};
  b.doc["cameras"] =
      json::array({json{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.2}}}}});
  b.doc["nodes"].push_back({{"camera", 0}, {"translation", {1, 2, 3}}});
  b.doc["scenes"][0]["nodes"] = {0, 1};
  const fs::path file = b.write(dir.path(), "m", Layout::kGlb);
  expect_contains(load_error(file), "images[0]");
  Result<Model> nodes = load_gltf(file, {}, Content::Nodes);
  ASSERT_TRUE(nodes) << nodes.error().message;
  ASSERT_EQ(nodes->cameras.size(), 1u);
  expect_near(glm::vec3(nodes->cameras[0].world[3]), glm::vec3(1, 2, 3));
  EXPECT_TRUE(nodes->meshes.empty() && nodes->textures.empty() && nodes->instances.empty());
}

}  // namespace
}  // namespace lagoon::gltf
