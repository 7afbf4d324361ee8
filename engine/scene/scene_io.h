// The scene file: reading and checking a scene (scene/scene.h) from JSON, with --set overrides, and writing
// it back. Format and every field: docs/scene-format.md.
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/result.h"
#include "scene/json_fields.h"
#include "scene/overrides.h"
#include "scene/scene.h"

namespace lagoon::scene {

// Reads and validates a scene. `overrides` are "a.b.c=value" strings applied to the JSON before validation
// (value parsed as JSON if it parses, otherwise taken as a string), so they are validated exactly like the
// file. An override that picks a surface model also sets what that model needs of the other fields
// (scene/model_overrides.h); `notes`, when given, receives one line per such change for the user. On failure
// the error lists every problem, one per line. Never throws.
Result<Scene> load_scene(const std::filesystem::path& path, std::span<const std::string> overrides = {},
                         std::vector<std::string>* notes = nullptr);

// Validates an already-parsed document; `source_name` prefixes error messages. Never throws.
Result<Scene> parse_scene(const nlohmann::json& document, const std::string& source_name);

// A frame time alone against the file's time_s field (finite, its bounds), the message as parse_scene()'s;
// for hosts that choose each frame's time without reading a whole scene again. The floating bodies' cost
// rule is not applied: it depends on where the host's bodies are.
Result<void> check_time_s(double time_s, const std::string& source_name);

// The scene as a document parse_scene() reads back to an equal scene; file paths are written relative to
// `folder` (the folder of the file it will be saved in) when they are inside it.
nlohmann::ordered_json scene_to_json(const Scene& scene, const std::filesystem::path& folder);

// Writes scene_to_json() to `path` (via a temporary file and a rename, so a failure leaves no half file).
Result<void> save_scene(const Scene& scene, const std::filesystem::path& path);

// Every field of the format with its type, unit, default, range and meaning (the docs' reference table).
std::vector<FieldInfo> scene_fields();
// The same rows with `scene`'s values in FieldInfo::default_value (for editors).
std::vector<FieldInfo> scene_fields(const Scene& scene);

}  // namespace lagoon::scene
