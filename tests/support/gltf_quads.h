// Small glTF files of textured quads for the tests of glTF materials (render and CLI tests).
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lagoon::test {

// A square quad, 2·half wide in its node's x-y plane facing −z (towards a camera on −z), u along +x and v
// along −y, with no tangents (the loader generates them), with its own material and node transform.
struct Quad {
  nlohmann::json material;
  nlohmann::json translation = {0, 0, 0};
  nlohmann::json rotation = {0, 0, 0, 1};
  float half = 2.0f;
};

// Writes `quads` as one glTF (buffers in a data URI); `extra` is merged into the top-level object (images,
// samplers, textures, extensionsUsed, ...).
void write_quads(const std::filesystem::path& path, const std::vector<Quad>& quads,
                 const nlohmann::json& extra = {});

// Base64 of `bytes`, for data URIs.
std::string base64(const std::vector<uint8_t>& bytes);

}  // namespace lagoon::test
