// lagoon lut --error-map DIR: how far the seed's RGB composites (eqs. 21, 22, 24) are from its spectral
// eq. 20 over measured bottoms (optics/composite_error.h), as CIEDE2000 maps over (r, h), a summary table
// (CSV and Markdown) and error.json (issue 16, item 2; docs/optics.md).
#pragma once
#include <string>

#include "core/result.h"
#include "optics/lut.h"

namespace lagoon::cli {

// Writes error_maps_linear.png, error_maps_seed.png, error_summary.csv, error_summary.md and error.json into
// `out` (staged: all or nothing). Prints a line per bottom as it goes.
Result<void> write_error_maps(const optics::LutInputs& inputs, const std::string& out);

}  // namespace lagoon::cli
