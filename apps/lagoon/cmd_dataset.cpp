// lagoon dataset verify DIR: checks a rendered set against its manifests (dataset/manifest.h); lagoon
// dataset preview FRAME.json: a frame and its ground truth side by side (dataset/preview.h).
#include <cstdio>

#include "commands.h"
#include "dataset/manifest.h"
#include "dataset/preview.h"
#include "io/png.h"

namespace lagoon::cli {
namespace {

// lagoon dataset preview FRAME.json --out FILE.png
int run_preview(const ParsedArgs& args) {
  const auto frame = args.get("target");
  const auto out = args.get("out");
  if (!frame || !out) {
    std::fprintf(stderr,
                 "lagoon dataset preview: name a frame's JSON and --out, e.g. lagoon dataset preview "
                 "set/frame_0007.json --out preview.png\n");
    return kExitUsage;
  }
  Result<io::Image8> sheet = dataset::preview(*frame);
  if (!sheet) {
    std::fprintf(stderr, "lagoon dataset preview: %s\n", sheet.error().message.c_str());
    return kExitFailure;
  }
  if (Result<void> ok = io::write_png(*out, *sheet); !ok) {
    std::fprintf(stderr, "lagoon dataset preview: %s\n", ok.error().message.c_str());
    return kExitFailure;
  }
  std::printf("wrote %s (%ux%u)\n", out->c_str(), sheet->width, sheet->height);
  return kExitOk;
}

int run_dataset(const ParsedArgs& args) {
  const std::string action = *args.get("action");
  if (action == "preview") return run_preview(args);
  if (action != "verify") {
    std::fprintf(stderr, "lagoon dataset: unknown action '%s'; available: verify, preview\n", action.c_str());
    return kExitUsage;
  }
  if (args.has("out")) {
    std::fprintf(stderr, "lagoon dataset verify: --out applies to 'dataset preview' only\n");
    return kExitUsage;
  }
  const auto dir = args.get("target");
  if (!dir) {
    std::fprintf(stderr,
                 "lagoon dataset verify: name the folder to check, e.g. lagoon dataset verify out/set\n");
    return kExitUsage;
  }
  const dataset::DatasetReport report = dataset::verify_dataset(*dir);
  for (const std::string& problem : report.problems)
    std::fprintf(stderr, "lagoon dataset verify: %s\n", problem.c_str());
  std::printf("%s: %lld set(s), %lld frames, %lld files, %.1f MiB verified; %zu problem(s)\n", dir->c_str(),
              report.sets, report.frames, report.files, double(report.bytes) / (1 << 20),
              report.problems.size());
  return report.problems.empty() ? kExitOk : kExitFailure;
}

}  // namespace

const Command& dataset_command() {
  static const Command command{
      .spec =
          {.name = "dataset",
           .summary = "Checks and shows a rendered dataset. 'verify DIR' reads every manifest "
                      "(OUT.shard-I-of-N.jsonl) in DIR and checks that all shards are there, every frame is "
                      "finished exactly once, and every file has the size and SHA-256 its manifest lists. "
                      "'preview FRAME.json --out FILE.png' draws a frame and each ground truth it lists side "
                      "by side, labelled, in false colour.",
           .options = {{"action", "verify|preview", "what to do: verify or preview", true},
                       {"target", "DIR|FRAME.json",
                        "verify: the folder a sequence was rendered into; preview: a frame's metadata JSON"},
                       {"out", "FILE.png", "preview: the picture to write"}},
           .positional = {"action", "target"},
           .details = "verify exits 0 when the set is complete and intact, 1 with one line per problem "
                      "(and what to run to mend it) otherwise. docs/datasets.md.\n"
                      "examples:\n  lagoon dataset verify out/set\n"
                      "  lagoon dataset preview out/set/frame_0007.json --out preview.png\n"},
      .run = run_dataset};
  return command;
}

}  // namespace lagoon::cli
