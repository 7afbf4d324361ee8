// How far the seed's RGB composites are from its spectral eq. 20, for a bottom of known reflectance spectrum
// R̂(λ), over the LUT's (r, h) grid (issue 16, item 2; docs/optics.md).
//
// For one column (bottom depth h) the four-flow model gives B(λ) = G₊(τ₀) + F₊(τ₀), the light reaching the
// bottom, U(λ) = F₋(0), the light the column scatters up (average bottom), and for a path l = sqrt(r² + h²)
// Bouguer's α(λ) = e^{−ε l}; ᾱ is its mean over 380–780 nm and a = 1 − (1 − ᾱ)^γ (eq. 23). With Φ a
// spectrum's colour and T_bottom = Φ(R̂ E_d) the bottom's texture colour:
//   eq. 20 (exact)  Φ(α R̂ B + (1 − α) U)
//   eq. 21          Φ(α B) · T_bottom + Φ((1 − α) U)
//   eq. 22          a · Φ(α B / ᾱ) · T_bottom + (1 − a) · Φ((1 − α) U / (1 − ᾱ))   (the tables Lagoon ships)
//   eq. 24          T_α · T_bottom · Φ(B) + (1 − T_α) · Φ(U),  T_α = Φ(α E_d)
// with · per RGB channel and every table clipped at 0 as the LUTs are (or not: clip_tables). Two Φ:
//   Linear  Lagoon's: von Kries-adapted linear sRGB; the frame is tone-mapped once, after compositing.
//   Seed    the seed's: the same followed by eq. 18's tone map, applied to each table before compositing.
// The error is CIEDE2000 between the displayed colours (tone-mapped, clipped to [0, 1]).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/result.h"
#include "optics/lut.h"

namespace lagoon::optics {

enum class Composite { Eq21 = 0, Eq22 = 1, Eq24 = 2 };
inline constexpr int kComposites = 3;
const char* composite_name(Composite c);  // "eq21", "eq22", "eq24"

enum class PhiMode { Linear, Seed };
const char* phi_mode_name(PhiMode m);  // "linear", "seed"

struct CompositeErrors {
  std::vector<double> r_m, h_m;   // the LUT's axes
  std::vector<glm::dvec3> exact;  // [r][h] displayed eq. 20, linear display RGB in [0, 1]
  std::array<std::vector<glm::dvec3>, kComposites> approx;  // [r][h] displayed approximations
  std::array<std::vector<double>, kComposites> delta_e;     // [r][h] ΔE00 against eq. 20
  // [r][h] 1 where eq. 22's T0 or T1 has a channel below 0 (spectral blue-greens outside sRGB) that the
  // LUT clips; there eq. 22 differs from eq. 20 even for a grey bottom.
  std::vector<uint8_t> eq22_clipped;
  std::vector<double> a;  // [r][h] eq. 23's a: how much of the bottom shows
};

// `clip_tables`: clip every table at 0 as the LUTs are (what the renderer shows); false keeps them signed,
// to separate the composites' own error from the clipping's.
Result<CompositeErrors> composite_errors(const LutInputs& inputs, const Spectrum& bottom_reflectance,
                                         PhiMode mode, bool clip_tables = true);

struct ErrorSummary {
  double mean = 0, p95 = 0, max = 0;
  double visible_share = 0;  // share of the grid with ΔE00 > 2 (a clearly visible difference)
};
// Over the nodes where at least `min_a` of the bottom shows (a ≥ min_a; 0 = the whole grid): in deep or far
// water every composite is the water's colour alone and agrees with eq. 20.
ErrorSummary summarise(const CompositeErrors& errors, Composite composite, double min_a = 0.0);

}  // namespace lagoon::optics
