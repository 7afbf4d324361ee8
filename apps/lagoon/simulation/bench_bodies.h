// lagoon bench bodies: the cost of the floating objects' and vehicles' physics per 60 Hz frame, on the CPU.
#pragma once
#include "args.h"

namespace lagoon::cli {

int run_bench_bodies(const ParsedArgs& args, int rounds);

}  // namespace lagoon::cli
