// The conformance report of `lagoon validate`: a table on stdout (law, reference, Lagoon, tolerance,
// verdict), and in the output folder report.md (the same table, each law's source, conditions and plot),
// report.json (every point) and one PNG plot per law.
#pragma once
#include <string>
#include <vector>

#include "core/result.h"
#include "io/staged_output.h"
#include "validate_law.h"

namespace lagoon::cli {

struct ReportContext {
  std::string device;  // the Vulkan device the laws ran on
  std::string mode;    // "quick" or "full"
  std::string broken;  // the broken variant, empty for none
  double seconds = 0;  // how long the run took
};

void print_table(const std::vector<Law>& laws);
Result<void> write_report(const io::StagedOutput& out, const std::vector<Law>& laws,
                          const ReportContext& context);

// The plot's file name for a law: its id with '.' as '-', ".png".
std::string plot_name(const Law& law);

}  // namespace lagoon::cli
