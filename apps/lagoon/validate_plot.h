// One law's picture for the validation report: Lagoon's measurements (dots, green where they hold, red where
// not) over the published law (a line) and its tolerance band (a lighter area), drawn by Lagoon itself.
#pragma once
#include "io/png.h"
#include "validate_law.h"

namespace lagoon::cli {

io::Image8 law_plot(const Law& law);

}  // namespace lagoon::cli
