// The scene file: what to render and how. Format and every field: docs/scene-format.md.
#pragma once
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "ocean/ocean_params.h"
#include "optics/water_params.h"
#include "scene/json_fields.h"
#include "scene/overrides.h"
#include "vk/result.h"

namespace lagoon::scene {

// World space: y is up, the mean water surface is y = 0, +z is north, +x is east; distances in metres.
struct Camera {
  glm::vec3 position{0.f, 6.f, -40.f};
  glm::vec3 look_at{0.f, 0.f, 0.f};
  float fov_deg = 55.f;  // vertical
  float near_m = 0.1f;
  float far_m = 5000.f;
};

struct Sun {
  float elevation_deg = 35.f;
  float azimuth_deg = 210.f;  // clockwise from +z (north) toward +x (east)
  float intensity = 1.f;
};

struct RenderSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  float exposure = 1.f;
  float gamma = 2.2f;
};

struct Scene {
  std::filesystem::path source;  // file it came from ("" when parsed from memory)
  Camera camera;
  Sun sun;
  ocean::OceanParams ocean;
  optics::WaterParams water;  // water.table, when relative, is resolved against the scene file's folder
  RenderSettings render;
  float time_s = 0.f;  // simulation time of the rendered frame
};

// Reads and validates a scene. `overrides` are "a.b.c=value" strings applied to the JSON before validation
// (value parsed as JSON if it parses, otherwise taken as a string), so they are validated exactly like the
// file. On failure the error lists every problem, one per line. Never throws.
Result<Scene> load_scene(const std::filesystem::path& path, std::span<const std::string> overrides = {});

// Validates an already-parsed document; `source_name` prefixes error messages. Never throws.
Result<Scene> parse_scene(const nlohmann::json& document, const std::string& source_name);

// Every field of the format with its type, unit, default, range and meaning (the docs' reference table).
std::vector<FieldInfo> scene_fields();

}  // namespace lagoon::scene
