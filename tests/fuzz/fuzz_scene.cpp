// The scene loader as `lagoon render --scene FILE --set ...` uses it: the input up to the first 0xff byte is
// the file, each later part one --set override (at most 8). An empty file part takes the path of commands
// whose --scene is optional: the overrides applied to an empty document, then validated. Any input must give
// a scene or an error.
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto parts = lagoon::fuzz::split(lagoon::fuzz::as_text(data, size), '\xff');
  std::vector<std::string> overrides;
  for (size_t i = 1; i < parts.size() && i <= 8; ++i) overrides.emplace_back(parts[i]);
  if (!parts[0].empty()) {
    (void)lagoon::scene::load_scene(lagoon::fuzz::write_scratch("scene.json", parts[0]), overrides);
    return 0;
  }
  nlohmann::json document = nlohmann::json::object();
  for (const std::string& assignment : overrides)
    if (!lagoon::scene::apply_override(document, assignment)) return 0;
  (void)lagoon::scene::parse_scene(document, "(command line)");
  return 0;
}
