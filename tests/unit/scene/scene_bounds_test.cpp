// Documented bounds are the checked bounds (issue 36): every numeric field of the scene reference (the
// rows docs/scene-format.md is generated from) is set to each closed end of its documented range, as the
// docs print it, and the scene reader must not call it out of range. wakes.step_s = 0.005 was refused
// though the docs give 0.005 as its lower bound: a float field was checked as float against the double
// bound, and 0.005f < 0.005.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/json_fields.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

namespace lagoon::test {
namespace {

// "ocean.cascades[].resolution" → "ocean.cascades[0].resolution": the first element stands for all.
std::string first_element(std::string path) {
  for (size_t at = path.find("[]"); at != std::string::npos; at = path.find("[]")) path.replace(at, 2, "[0]");
  return path;
}

TEST(SceneBounds, EveryNumericFieldAcceptsBothEndsOfItsDocumentedRange) {
  int tried = 0;
  std::vector<std::string> refused;
  for (const scene::FieldInfo& f : scene::scene_fields()) {
    if (f.type != "number" && f.type != "integer") continue;
    std::vector<double> ends;
    if (std::isfinite(f.bounds.min) && !f.bounds.min_open) ends.push_back(f.bounds.min);
    if (std::isfinite(f.bounds.max) && !f.bounds.max_open) ends.push_back(f.bounds.max);
    for (double end : ends) {
      const std::string path = first_element(f.path);
      const std::string set = path + "=" + scene::format_number(end);
      const std::vector<std::string> overrides{set};
      Result<scene::Scene> s =
          scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json", overrides);
      ++tried;
      // Other rules may object to an extreme (a border wider than the window); "out of range" may not.
      if (!s && s.error().message.find(path + ": ") != std::string::npos &&
          s.error().message.find("out of range") != std::string::npos)
        refused.push_back(set + " -> " + s.error().message);
    }
  }
  EXPECT_GT(tried, 100) << "the reference lists the scene's numeric fields";
  for (const std::string& r : refused) ADD_FAILURE() << "a documented bound is refused: " << r;
}

}  // namespace
}  // namespace lagoon::test
