// lagoon bench render --baseline OTHER_LAGOON: this build's frame against an older build's, scene by scene,
// each measured by its own `bench render` process in alternating order, and the ratios printed (issue 34).
#pragma once
#include "args.h"

namespace lagoon::cli {

// `rounds` frames per scene and build at width x height; the scene is --scene, or every scenes/*.json.
int run_bench_baseline(const ParsedArgs& args, int rounds, long long width, long long height);

}  // namespace lagoon::cli
