// A shipped scene (scenes/NAME.json) with `--set`-style overrides, for tests; a failure to load fails the
// test and gives a default scene.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_io.h"

namespace lagoon::test {

inline scene::Scene shipped_scene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/" + name + ".json", overrides);
  EXPECT_TRUE(s) << s.error().message;
  return s ? *s : scene::Scene{};
}

}  // namespace lagoon::test
