// Inherent optical properties of water on the optics grid (spectrum.h): the ten Jerlov types and
// user-defined tables. χ(λ) and σ(λ) of Belyaev's eq. 3, in m⁻¹.
//
// Jerlov types: absorption a and scattering b of Solonenko & Mobley (2015), jerlov_sm2015_a.csv / _b.csv,
// with the cells that are empty there (corrupt 3C and 5C rows of their Table 7, data/README.md defect 1)
// taken from Williamson & Hollins (2022), jerlov_sm2015_gapfill_williamson2022.csv. 380-700 nm: linear
// interpolation in wavelength between the published wavelengths (375, 400, 425, ... 700 nm).
// Beyond 700 nm nothing is published, so each type is split into pure water plus the rest at 700 nm and
// the rest is carried on with its typical spectral shape:
//   a(λ) = a_w(λ) + a_nw(700)·exp(−0.014 nm⁻¹·(λ − 700)),  a_nw(700) = max(0, a(700) − a_w(700))
//     (non-water absorbers, CDOM and detritus, decay roughly exponentially with wavelength; 0.014 nm⁻¹ is
//     the usual CDOM slope);
//   b(λ) = b_sw(λ) + b_p(700)·(700 / λ),  b_p(700) = max(0, b(700) − b_sw(700))
//     (particle scattering ~ λ⁻¹).
// a_w is Pope & Fry (1997) to 725 nm and Kou et al. (1993) above, b_sw is Smith & Baker (1981), both from
// pure_water_absorption_scattering_5nm.csv. For the clear types I–III, S&M's a(700) = 0.582 m⁻¹ lies below
// Pope & Fry's a_w(700) = 0.624 m⁻¹, so a_nw clamps to 0: a jumps from 0.582 at 700 nm to a_w = 0.704 at
// 705 nm. Likewise b(700) of type I is below b_sw(700), so its b_p is 0.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.h"
#include "optics/spectrum.h"

namespace lagoon::optics {

struct WaterIops {
  std::string name;
  Spectrum absorption_per_m;  // χ(λ), m⁻¹, > 0
  Spectrum scattering_per_m;  // σ(λ), m⁻¹, >= 0
};

// "jerlov-I", "jerlov-IA", "jerlov-IB", "jerlov-II", "jerlov-III", "jerlov-1C", "jerlov-3C",
// "jerlov-5C", "jerlov-7C", "jerlov-9C": oceanic clearest to coastal most turbid.
const std::vector<std::string>& water_type_names();

// One of water_type_names() (exact spelling); otherwise an error listing the accepted names and
// suggesting the closest one.
Result<WaterIops> water_type(const std::string& name);

// A user-defined water: a CSV with columns wavelength_nm, absorption_per_m, scattering_per_m (others are
// ignored), rows in increasing wavelength at any spacing, covering at least 380-780 nm; resampled to the
// grid by linear interpolation. Errors name the file, and the line for a bad value: absorption must be
// > 0 (all water absorbs, and the four-flow model divides by χ + σ), scattering >= 0, both finite.
// The name is the file's stem.
Result<WaterIops> load_water_table(const std::filesystem::path& csv);

// Pure water absorption a_w (Pope & Fry 1997 / Kou et al. 1993) and pure seawater scattering b_sw
// (Smith & Baker 1981) on the grid, m⁻¹.
const Spectrum& pure_water_absorption();
const Spectrum& pure_seawater_scattering();

}  // namespace lagoon::optics
