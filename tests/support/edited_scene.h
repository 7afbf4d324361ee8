// Scenes a test builds from a shipped one: read scenes/NAME.json as JSON, change it, and load it from a
// file in the test's folder (so the models the test writes there resolve against it).
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"
#include "scene/scene_io.h"

namespace lagoon::test {

inline nlohmann::json shipped_scene_json(const std::string& name) {
  std::ifstream in(std::string(LAGOON_SOURCE_DIR) + "/scenes/" + name + ".json");
  return nlohmann::json::parse(in);
}

// Makes every cascade of `scene` 64² instead of the shipped 256², for tests whose property is not the
// sea's detail (a model's materials, how frames are shared out): each step, and the 30 steps of a still
// frame's foam warm-up, costs about a sixteenth.
inline void use_small_cascades(nlohmann::json& scene) {
  for (auto& cascade : scene["ocean"]["cascades"]) cascade["resolution"] = 64;
}

// Writes `scene` to `file` and loads it; a failure to load fails the test and gives a default scene.
inline scene::Scene write_and_load(const nlohmann::json& scene, const std::filesystem::path& file) {
  std::ofstream(file) << scene.dump();
  auto s = scene::load_scene(file);
  EXPECT_TRUE(s) << s.error().message;
  return s ? *s : scene::Scene{};
}

}  // namespace lagoon::test
