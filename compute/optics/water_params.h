// The scene's "water" block: which water, the bottom, and the LUTs built from them (docs/scene-format.md).
#pragma once
#include <cstdint>
#include <string>

namespace lagoon::optics {

struct WaterParams {
  std::string type = "jerlov-IB";  // a Jerlov type (water_types.h) or "custom" with `table`
  std::string table;               // "custom": CSV with wavelength_nm, absorption_per_m, scattering_per_m
  double bottom_albedo = 0.3;      // R̂: average bottom reflectance in [0, 1] (diffuse)
  // Scattering phase function, through its first Legendre coefficient X1 (3g for asymmetry g):
  //  "mixed": per wavelength, the scattering-weighted mix of pure sea water (molecular, X1 = 0) and particles
  //           (Petzold's average ocean particle, g = 0.924, X1 = 2.77): clear water backscatters like water,
  //           turbid water like particles. "constant": phase_x1 at every wavelength.
  std::string phase = "mixed";
  double phase_x1 = 2.0;   // [0, 3), used when phase is "constant"
  double lut_gamma = 1.0;  // γ of eq. 23: how fast the bottom fades into the water colour with path length
  // D: the diffuse flows' path length per unit depth (four_flow.h). The seed's eq. 4 is 1; 2 (isotropic
  // diffuse light) brings the model's K_d within 15 % of Jerlov's for seven of the ten types, against two
  // with 1 (docs/optics.md), so 2 is the default.
  double diffuse_path_factor = 2.0;
  double ior = 1.333;        // index of refraction of water relative to air
  uint32_t lut_size = 64;    // samples along r and along h
  double lut_r_max_m = 100;  // largest horizontal distance r in the LUT
  double lut_h_max_m = 30;   // largest bottom depth h in the LUT; deeper water uses the deep-water colour
};

}  // namespace lagoon::optics
