// lagoon lut --kd-plot: the model's diffuse attenuation K_d(λ) with the seed's D = 1 and with D = 2 against
// Jerlov's measurements (1976, Table XXVII), one panel per water type, drawn by Lagoon itself (issue 16).
#pragma once
#include "core/result.h"
#include "io/png.h"

namespace lagoon::cli {

Result<io::Image8> kd_plot();

}  // namespace lagoon::cli
