#include "support/gltf_quads.h"

#include <fstream>
#include <string>

namespace lagoon::test {
namespace {

using nlohmann::json;

template <typename T>
void append(std::vector<uint8_t>& bin, const std::vector<T>& values) {
  const auto* p = reinterpret_cast<const uint8_t*>(values.data());
  bin.insert(bin.end(), p, p + values.size() * sizeof(T));
}

}  // namespace

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= bytes[i + 2];
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? k[v & 63] : '=';
  }
  return out;
}

void write_quads(const std::filesystem::path& path, const std::vector<Quad>& quads, const json& extra) {
  json doc = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", json::array({json{{"nodes", json::array()}}})}};
  std::vector<uint8_t> bin;
  for (size_t q = 0; q < quads.size(); ++q) {
    const float h = quads[q].half;
    const size_t offset = bin.size();
    append(bin, std::vector<float>{-h, -h, 0, h, -h, 0, h, h, 0, -h, h, 0});
    append(bin, std::vector<float>{0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1});
    append(bin, std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});
    append(bin, std::vector<uint16_t>{0, 2, 1, 0, 3, 2});  // counter-clockwise seen from −z
    const int v = int(doc["bufferViews"].size());
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", 48}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset + 48}, {"byteLength", 48}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset + 96}, {"byteLength", 32}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset + 128}, {"byteLength", 12}});
    const int a = int(doc["accessors"].size());
    doc["accessors"].push_back({{"bufferView", v},
                                {"componentType", 5126},
                                {"count", 4},
                                {"type", "VEC3"},
                                {"min", {-h, -h, 0}},
                                {"max", {h, h, 0}}});
    doc["accessors"].push_back(
        {{"bufferView", v + 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    doc["accessors"].push_back(
        {{"bufferView", v + 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
    doc["accessors"].push_back(
        {{"bufferView", v + 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}});
    while (bin.size() % 4) bin.push_back(0);
    doc["materials"].push_back(quads[q].material);
    doc["meshes"].push_back(
        {{"primitives",
          json::array({json{{"attributes", {{"POSITION", a}, {"NORMAL", a + 1}, {"TEXCOORD_0", a + 2}}},
                            {"indices", a + 3},
                            {"material", q}}})}});
    doc["nodes"].push_back(
        {{"mesh", q}, {"translation", quads[q].translation}, {"rotation", quads[q].rotation}});
    doc["scenes"][0]["nodes"].push_back(q);
  }
  doc["buffers"] = json::array(
      {json{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
  if (extra.is_object()) doc.update(extra);
  std::ofstream(path) << doc.dump();
}

}  // namespace lagoon::test
