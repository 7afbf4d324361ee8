// Measured reflectance spectra of sea-floor materials (data/bottom_reflectance_5nm.csv, sources in
// data/README.md), for measuring how well the RGB composites of eqs. 21, 22 and 24 reproduce eq. 20 over
// coloured bottoms (composite_error.h).
#pragma once
#include <string>
#include <vector>

#include "optics/spectrum.h"

namespace lagoon::optics {

struct BottomSpectrum {
  std::string name;         // the table's column: sand, coral, coralline_algae, macroalgae, basalt
  std::string description;  // what it is and whose measurement
  Spectrum reflectance;     // irradiance reflectance (albedo), 0..1
};

const std::vector<BottomSpectrum>& bottom_spectra();

}  // namespace lagoon::optics
