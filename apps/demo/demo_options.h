// lagoon-demo's command line. Scripted runs (--frames, --script, --screenshot, --save-scene, --exit) make
// the demo testable under xvfb: they step time by exactly 1/fps per frame.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "args.h"
#include "scene/scene.h"

namespace lagoon::demo {

// One line of a --script file: at frame `frame` (0-based), apply `assignment` ("path=value") to the scene.
struct ScriptStep {
  long long frame = 0;
  std::string assignment;
};

struct DemoOptions {
  scene::Scene scene;                   // --scene with --set applied (all defaults without --scene)
  uint32_t width = 1280, height = 720;  // window size; default the scene's render size
  std::optional<long long> frames;      // run exactly this many frames at a fixed step of 1/fps
  double fps = 30.0;
  // Live frames are drawn at the fraction of the window's size that holds this frame rate (0: always the
  // window's size); --frames runs and screenshots are always at the window's size (resolution_scale.h).
  double target_fps = 15.0;
  std::string screenshot;  // PNG of the last of --frames (or of the first frame without --frames)
  std::string save_scene;  // the scene as JSON after the last of --frames
  bool hide_ui = false;
  bool exit_after_frames = false;
  bool vsync = true;
  std::vector<ScriptStep> script;
};

const cli::CommandSpec& demo_command();

// Parses the command line (without argv[0]). On failure returns the exit code to use, after printing the
// problem (usage errors: kExitUsage; unreadable scene or script: kExitFailure); --help prints and returns
// kExitOk as an "error" too.
Result<DemoOptions> parse_demo_options(std::span<const std::string> args, int& exit_code);

// Parses "FRAME path=value" lines ('#' starts a comment). Errors name `name` (the file) and the line.
Result<std::vector<ScriptStep>> parse_script(std::string_view text, const std::string& name);

// Reads the file at `path` and parses it with parse_script().
Result<std::vector<ScriptStep>> read_script(const std::string& path);

}  // namespace lagoon::demo
