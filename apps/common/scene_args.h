// Loading the --scene file with its --set overrides, the same way for every command.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "args.h"
#include "scene/scene.h"

namespace lagoon::cli {

// The standard options every scene-taking command declares.
OptionSpec scene_option();
OptionSpec set_option();

// Prints the problems (prefixed with "lagoon <command>", or with `command` itself when it is a program name
// such as "lagoon-demo") and returns nullopt on failure. Without --scene (for
// commands where it is optional) the scene is all defaults plus the overrides.
std::optional<scene::Scene> load_scene_from_args(const ParsedArgs& args, const std::string& command,
                                                 std::vector<std::string> extra_overrides = {});

}  // namespace lagoon::cli
