#include "scene_args.h"

#include <cstdio>

#include "scene/model_overrides.h"
#include "scene/scene_io.h"

namespace lagoon::cli {

OptionSpec scene_option() {
  return {"scene", "FILE", "scene JSON (see docs/scene-format.md)", true};
}

OptionSpec set_option() {
  return {"set", "PATH=VALUE", "override a scene field, e.g. --set ocean.spectrum.type=pm (repeatable)",
          false, true};
}

namespace {

// "render" -> "lagoon render"; a whole program name ("lagoon-demo") is kept.
std::string program(const std::string& command) {
  return command.rfind("lagoon", 0) == 0 ? command : "lagoon " + command;
}

}  // namespace

std::optional<scene::Scene> load_scene_from_args(const ParsedArgs& args, const std::string& command,
                                                 std::vector<std::string> extra_overrides) {
  for (const std::string& s : args.all("set")) extra_overrides.push_back(s);
  if (!args.has("scene")) {
    // Commands whose --scene is optional start from an empty scene: every default, plus the overrides.
    nlohmann::json document = nlohmann::json::object();
    for (const std::string& s : extra_overrides) {
      if (auto applied = scene::apply_override(document, s); !applied) {
        std::fprintf(stderr, "%s: %s\n", program(command).c_str(), applied.error().message.c_str());
        return std::nullopt;
      }
    }
    for (const std::string& note : scene::apply_model_constraints(document, extra_overrides))
      std::fprintf(stderr, "%s: note: %s\n", program(command).c_str(), note.c_str());
    auto scene = scene::parse_scene(document, "(command line)");
    if (!scene) {
      std::fprintf(stderr, "%s: %s\n", program(command).c_str(), scene.error().message.c_str());
      return std::nullopt;
    }
    return std::move(scene).value();
  }
  std::vector<std::string> notes;
  auto scene = scene::load_scene(*args.get("scene"), extra_overrides, &notes);
  for (const std::string& note : notes)
    std::fprintf(stderr, "%s: note: %s\n", program(command).c_str(), note.c_str());
  if (!scene) {
    std::fprintf(stderr, "%s: %s\n", program(command).c_str(), scene.error().message.c_str());
    return std::nullopt;
  }
  return std::move(scene).value();
}

}  // namespace lagoon::cli
