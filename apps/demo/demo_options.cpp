#include "demo_options.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/bounded_file.h"
#include "exit_codes.h"
#include "scene_args.h"

namespace lagoon::demo {

namespace {

// Optional here: without --scene the demo starts from the format's defaults (plus --set).
cli::OptionSpec scene_option() {
  cli::OptionSpec o = cli::scene_option();
  o.required = false;
  o.help += "; default: every field's default";
  return o;
}

}  // namespace

const cli::CommandSpec& demo_command() {
  static const cli::CommandSpec spec{
      .name = "",
      .program = "lagoon-demo",
      .summary = "The ocean in a window: fly over it and change every scene parameter live.",
      .options = {scene_option(),
                  cli::set_option(),
                  {.name = "width",
                   .value_name = "PX",
                   .help = "window width (default: the scene's render.width)"},
                  {.name = "height", .value_name = "PX", .help = "window height (default: render.height)"},
                  {.name = "frames",
                   .value_name = "N",
                   .help = "run N frames with time advancing exactly 1/fps per frame (for scripted runs)"},
                  {.name = "fps",
                   .value_name = "F",
                   .help = "time step of --frames, frames per second (default 30)"},
                  {.name = "target-fps",
                   .value_name = "F",
                   .help = "dynamic resolution: draw live frames at the fraction of the window that holds F "
                           "frames a second, stretched to the window (default 15; 0 = always full size; "
                           "--frames runs and screenshots are full size)"},
                  {.name = "screenshot",
                   .value_name = "FILE",
                   .help = "write the last of --frames (the first frame without --frames) to this PNG"},
                  {.name = "save-scene",
                   .value_name = "FILE",
                   .help = "write the scene as JSON after the last of --frames"},
                  {.name = "script",
                   .value_name = "FILE",
                   .help = "lines 'FRAME path=value': change the scene at that frame, as the panel would"},
                  {.name = "hide-ui", .help = "start with the panel hidden (F2 toggles it)"},
                  {.name = "exit", .help = "quit after the last of --frames"},
                  {.name = "no-vsync", .help = "present without waiting for vertical sync (V toggles it)"}},
      .details =
          "Keys: F1 lists them all in the window. Mouse: hold the right button to look (fly) or turn "
          "(orbit); "
          "the wheel changes the speed (fly) or the distance (orbit).\n"
          "Exit codes: 0 ok, 1 bad scene or no device, 2 bad command line, 3 validation errors "
          "(LAGOON_VALIDATION=1).\n"
          "Needs a display; headless, run it under 'xvfb-run -a'."};
  return spec;
}

Result<std::vector<ScriptStep>> parse_script(std::string_view text, const std::string& name) {
  std::istringstream in{std::string(text)};
  std::vector<ScriptStep> steps;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    const size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos) continue;
    const size_t space = line.find_first_of(" \t", start);
    const std::optional<long long> frame =
        space == std::string::npos ? std::nullopt : cli::parse_integer(line.substr(start, space - start));
    const size_t rest = space == std::string::npos ? space : line.find_first_not_of(" \t", space);
    if (!frame || *frame < 0 || rest == std::string::npos)
      return make_error(
          name + ":" + std::to_string(number) +
          ": expected 'FRAME path=value' with FRAME a whole number >= 0, e.g. '10 sun.elevation_deg=20'");
    std::string assignment = line.substr(rest);
    while (!assignment.empty() && (assignment.back() == '\r' || assignment.back() == ' '))
      assignment.pop_back();
    steps.push_back({*frame, assignment});
  }
  return steps;
}

Result<std::vector<ScriptStep>> read_script(const std::string& path) {
  // A script is a line per edit; 16 MiB is hundreds of thousands. Checked before reading
  // (core/bounded_file.h): a FIFO or device is refused, not read for ever.
  Result<std::string> text = read_bounded_file(path, std::uintmax_t{16} << 20);
  if (!text)
    return make_error(path + ": cannot read the script: it " + text.error().message + " (check the path)");
  return parse_script(*text, path);
}

namespace {

// Every option but --scene, --set and the script's contents into `o`; the error is a usage error naming the
// option. A width or height of 0 means the scene's.
Result<void> read_options(const cli::ParsedArgs& parsed, DemoOptions& o) {
  const auto width = cli::integer_option(parsed, "width", -1, 64, 16384);
  const auto height = cli::integer_option(parsed, "height", -1, 64, 16384);
  const auto frames = cli::integer_option(parsed, "frames", -1, 1, 1000000);
  if (!width) return width.error();
  if (!height) return height.error();
  if (!frames) return frames.error();
  if (auto v = parsed.get("fps")) {
    const auto f = cli::parse_number(*v);
    if (!f || *f <= 0 || *f > 1000)
      return make_error("--fps " + *v + " must be a number of frames per second in (0, 1000]");
    o.fps = *f;
  }
  if (auto v = parsed.get("target-fps")) {
    const auto f = cli::parse_number(*v);
    if (!f || *f < 0 || *f > 240)
      return make_error("--target-fps " + *v + " must be a number of frames per second from 0 (off) to 240");
    o.target_fps = *f;
  }
  o.width = *width > 0 ? uint32_t(*width) : 0;
  o.height = *height > 0 ? uint32_t(*height) : 0;
  if (*frames > 0) o.frames = *frames;
  o.screenshot = parsed.get("screenshot").value_or("");
  if (!o.screenshot.empty() &&
      (o.screenshot.size() < 5 || o.screenshot.substr(o.screenshot.size() - 4) != ".png"))
    return make_error("--screenshot " + o.screenshot + " must name a .png file");
  o.save_scene = parsed.get("save-scene").value_or("");
  o.hide_ui = parsed.has("hide-ui");
  o.exit_after_frames = parsed.has("exit");
  o.vsync = !parsed.has("no-vsync");
  if (o.exit_after_frames && !o.frames) return make_error("--exit needs --frames N (how many frames to run)");
  if (parsed.has("script") && !o.frames)
    return make_error("--script needs --frames N (scripts count frames of a fixed time step)");
  return {};
}

}  // namespace

Result<DemoOptions> parse_demo_options(std::span<const std::string> args, int& exit_code) {
  const cli::CommandSpec& spec = demo_command();
  auto parsed = cli::parse_args(spec, args);
  if (!parsed) {
    std::fprintf(stderr, "lagoon-demo: %s\n\n%s", parsed.error().message.c_str(), cli::usage(spec).c_str());
    exit_code = cli::kExitUsage;
    return parsed.error();
  }
  if (parsed->help) {
    std::printf("%s", cli::usage(spec).c_str());
    exit_code = cli::kExitOk;
    return make_error("help");
  }
  DemoOptions o;
  if (auto r = read_options(*parsed, o); !r) {
    std::fprintf(stderr, "lagoon-demo: %s\n", r.error().message.c_str());
    exit_code = cli::kExitUsage;
    return r.error();
  }
  if (auto script = parsed->get("script")) {
    auto steps = read_script(*script);
    if (!steps) {
      std::fprintf(stderr, "lagoon-demo: %s\n", steps.error().message.c_str());
      exit_code = cli::kExitFailure;
      return steps.error();
    }
    o.script = std::move(*steps);
  }
  auto scene = cli::load_scene_from_args(*parsed, "lagoon-demo");
  if (!scene) {
    exit_code = cli::kExitFailure;
    return make_error("scene");
  }
  o.scene = std::move(*scene);
  if (o.width == 0) o.width = o.scene.render.width;
  if (o.height == 0) o.height = o.scene.render.height;
  exit_code = cli::kExitOk;
  return o;
}

}  // namespace lagoon::demo
