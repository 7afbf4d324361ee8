// The water as a participating medium, for a camera under water: what a view ray of length d at depth z
// transmits and what the water adds along it, from the same IOPs, sky and Φ as the colour LUTs (lut.h), so
// that the sea seen from above and from below agree. docs/optics.md, "Under the surface", derives it.
//
// Per wavelength, with ε = χ + σ and the flows of a bottomless column (four_flow.h, τ = εz):
//   E_d(z)   = G+(τ) + F+(τ)                  downwelling light at depth z (falls as exp(−K_d z))
//   f        = g² (g = X1/3)                   forward peak of the phase function (delta-Eddington): light
//                                              scattered into it stays on the ray, blurred, not lost
//   α(d)     = exp(−(χ + σ(1 − f))·d)          light from a target that still reaches the eye
//   α_s(d)   = exp(−(χ + σ)·d)                 of which this part is unscattered (sharp)
//   target   = Φ(α(d)·E_d(z))                  a white Lambertian target at depth z seen from d metres
//   blur     = 1 − Y(α_s·E_d) / Y(α·E_d)        the share of that light that arrives blurred
//   water↓   = Φ((1 − α(d))·F−(z))             light the water adds along a ray looking down
//   water↑   = Φ((1 − α(d))·(F+(z) − F+(0)e^{−τ}))  ... looking up: the scattered part of the diffuse
//                                              downwelling light (the unscattered part is the surface's own)
// Units as the LUTs: linear sRGB relative to the downwelling light above the water (a white Lambertian
// surface above the water is (1, 1, 1)). At z = 0 and d → ∞, water↓ is the LUT's deep-water colour.
#pragma once
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/result.h"
#include "optics/lut.h"

namespace lagoon::optics {

struct UnderwaterAxes {
  uint32_t d_count = 64, z_count = 64;
  double d_max_m = 100;  // longest view path tabulated; longer paths see only the water (α < 1e-3 there
                         // for every Jerlov type below 580 nm)
  double z_max_m = 60;   // deepest point tabulated; deeper points use z_max
};

struct UnderwaterTable {
  uint32_t d_count = 0, z_count = 0;
  // d_m[i] = d_max (i/(D−1))², z_m[j] = z_max (j/(Z−1))²: a shader looks up u = sqrt(d/d_max), v =
  // sqrt(z/z_max).
  std::vector<double> d_m, z_m;
  std::vector<float> target;      // [d][z][4]: RGB of a white target at depth z seen from d metres, A = blur
  std::vector<float> water_down;  // [d][z][3]: RGB of water↓
  std::vector<float> water_up;    // [d][z][3]: RGB of water↑
  // K_d of the downwelling light's luminance between 0 and 10 m: −ln(Y(E_d(10 m))/Y(E_d(0)))/10 m. Per RGB
  // channel it is not defined: through clear water the light leaves the sRGB gamut (red clips to 0).
  double kd_luminance_per_m = 0;
  double build_ms = 0;

  // Entry (i, j) of a table with `channels` floats per entry.
  const float* at(const std::vector<float>& table, uint32_t i, uint32_t j, uint32_t channels) const {
    return &table[(size_t{i} * z_count + j) * channels];
  }
};

// One entry, in double, for any d >= 0 and z >= 0 (the table samples this; tests and `lagoon lut --explain`
// use it directly).
struct UnderwaterSample {
  glm::dvec3 target{0}, water_down{0}, water_up{0};
  double blur = 0;
  // Of the light falling on a horizontal target at depth z, E_d(z), the share (in luminance) that is the
  // sun's direct beam, G+/(G+ + F+): the part caustics redistribute.
  double direct_share = 0;
};
Result<UnderwaterSample> underwater_sample(const LutInputs& inputs, double d_m, double z_m);

// Fails for axes with fewer than 2 samples or non-positive extents, and with solve_four_flow's messages.
Result<UnderwaterTable> build_underwater_table(const LutInputs& inputs, const UnderwaterAxes& axes = {});

}  // namespace lagoon::optics
