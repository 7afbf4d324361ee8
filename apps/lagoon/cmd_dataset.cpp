// lagoon dataset verify DIR: checks a rendered set against its manifests (io/dataset_manifest.h).
#include <cstdio>

#include "commands.h"
#include "io/dataset_manifest.h"

namespace lagoon::cli {
namespace {

int run_dataset(const ParsedArgs& args) {
  const std::string action = *args.get("action");
  if (action != "verify") {
    std::fprintf(stderr, "lagoon dataset: unknown action '%s'; available: verify\n", action.c_str());
    return kExitUsage;
  }
  const auto dir = args.get("dir");
  if (!dir) {
    std::fprintf(stderr,
                 "lagoon dataset verify: name the folder to check, e.g. lagoon dataset verify out/set\n");
    return kExitUsage;
  }
  const io::DatasetReport report = io::verify_dataset(*dir);
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
      .spec = {.name = "dataset",
               .summary =
                   "Checks a rendered dataset: 'verify DIR' reads every manifest (OUT.shard-I-of-N.jsonl) in "
                   "DIR and checks that all shards are there, every frame is finished exactly once, and "
                   "every file has the size and SHA-256 its manifest lists.",
               .options = {{"action", "verify", "what to do: verify", true},
                           {"dir", "DIR", "the folder a sharded or multi-frame lagoon render wrote into"}},
               .positional = {"action", "dir"},
               .details = "Exit status 0 when the set is complete and intact, 1 with one line per problem "
                          "(and what to run to mend it) otherwise. docs/datasets.md.\n"
                          "example:\n  lagoon dataset verify out/set\n"},
      .run = run_dataset};
  return command;
}

}  // namespace lagoon::cli
