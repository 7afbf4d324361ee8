// Waves over the floor (issue 37; docs/ocean.md "Waves over the floor"): linear wave theory's transformation
// of each directly evaluated wave over a depth profile (ocean/depth_profile.h), and the random sea's
// depth-limited height. Plain C++, double precision; the table the shaders read is its float copy
// (shared/shoaling.h), interpolated by the same arithmetic (shared/shoaling_math.h).
//
// A wave of frequency ω keeps ω and its wavenumber along the depth contours k_v (Snell's law over contours
// that are straight and parallel); its wavenumber k(h) follows ω² = g k tanh(k h) (seed 001 eq. 8), so it
// turns toward the shallows (k_u = sqrt(k² - k_v²)); its energy flux E c_g cos θ is conserved between rays,
// so its amplitude is A0 K_s K_r with K_s = sqrt(c_g0 / c_g) and K_r = sqrt(cos θ0 / cos θ); and where the
// wave height would exceed γ h (McCowan's breaker index γ = 0.78) it breaks and stays at γ h, down to the
// shoreline where it ends. The phase is θ = k0·x + φ(s) - ω t + φ0 with φ(s) = ∫ (k_u - k_u0) ds, so a
// crest's spacing is the local wavelength. The wave's own (k0, ω) holds wherever the floor is deeper than
// half its wavelength (or than ocean.depth_m, the depth a finite-depth wave is given at): there nothing
// changes, and a sea with no shallower floor is not transformed at all.
//
// Over a floor sampled in two dimensions (a glTF floor) the same laws are solved on the grid: the phase from
// the eikonal equation |∇S| = k(h) by fast marching from where the wave is its own (the cells deeper than
// half its wavelength; where the grid has none, its upwind edges, an approximation), the direction from ∇S,
// and the amplitude from the energy flux's conservation
// ∇·(E c_g k̂) = 0 marched along the rays in the same order (first-order accurate; where rays cross, behind
// a shoal, the amplitude is held to 4 a0 and the phase is the first arrival's).
//
// The random sea (the FFT cascades) has one wavelength per lattice mode everywhere. Each cascade is read at a
// moved point instead (shared/shoaling_math.h, sh_lattice_point): the rest position moved along the
// cascade's representative wave (its modes' energy-weighted wavenumber and direction) by that wave's phase
// offset over the floor, so that wave shortens, slows and turns exactly as a directly evaluated one, and the
// cascade's other modes with it (approximately: each is shortened by its representative's ratio). Its height
// shoals by the representative waves' energy-weighted K_s K_r, up to its depth limit: a significant height of
// at most 0.6 h (Thornton & Guza 1983: H_rms <= 0.42 h in the surf zone), falling to nothing at the
// shoreline.
#pragma once
#include <array>
#include <cmath>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

#include "ocean/depth_profile.h"

namespace lagoon::ocean {

inline constexpr double kBreakerIndex = 0.78;       // H / h at breaking (McCowan 1894)
inline constexpr double kSurfZoneHsPerDepth = 0.6;  // the random sea's H_s / h in the surf zone

struct ShoalingWave {
  glm::dvec2 k{0.0};                // its own wavevector (rad/m): where the floor is deep
  double omega = 0;                 // rad/s
  double amplitude_m = 0;           // its own amplitude
  double height_per_amplitude = 2;  // crest-to-trough height / amplitude: 2 for cos θ, 1 for the sines'
  double steepness = 0;             // Q (horizontal displacement Q A)
  double own_depth_m = HUGE_VAL;    // the depth its (k, ω) hold at (a finite-depth dispersion's D)
};

// The random sea over the floor: its significant height (its depth limit) and one representative wave per
// cascade whose lattice is moved (k = 0: a cascade with no waves, not moved).
struct RandomSea {
  double significant_height_m = 0;  // 0 when there is none
  std::vector<ShoalingWave> lattice;
};

struct ShoalingInputs {
  std::shared_ptr<const DepthProfile> floor;
  std::vector<ShoalingWave> waves;
  double reference_depth_m = HUGE_VAL;  // where the waves' (k, ω) hold: ocean.depth_m for finite-depth waves
  double breaker_index = kBreakerIndex;
  RandomSea sea;
};

// The transformation: a table over the profile's samples, layer 0 for the floor, one layer per wave, then one
// per cascade of the random sea (its representative wave: lattice_layer(c)).
class Shoaling {
 public:
  explicit Shoaling(ShoalingInputs inputs);

  // Whether any value differs from the untransformed sea's (a floor shallow enough for some wave or the sea).
  bool active() const { return active_; }
  const DepthProfile& floor() const { return *inputs_.floor; }
  size_t wave_count() const { return inputs_.waves.size(); }
  size_t lattice_count() const { return inputs_.sea.lattice.size(); }
  size_t lattice_layer(size_t cascade) const { return 1 + wave_count() + cascade; }
  size_t samples() const { return inputs_.floor->depth_m.size(); }  // per layer
  // Layer 0 at (x, z): (depth m, the random sea's height scale (its shoaling up to its depth limit), the
  // waves' steepness scale, breaking ratio:
  // the summed linear height over γ h, >= 1 where the waves break).
  glm::dvec4 ground(glm::dvec2 xz) const;
  // Wave i at (x, z): (phase offset φ rad, amplitude m, k_u, k_v rad/m).
  glm::dvec4 wave(size_t i, glm::dvec2 xz) const;
  // Every cascade's move at the rest position xz (shared/shoaling_math.h), one lookup of the table's cell:
  // where its textures are read, and ∇φ there (its local wavevector less its own); and, from the same
  // lookup, the random sea's height scale there (ground(xz).y, to the bit).
  static constexpr size_t kMaxLattices = 4;  // LAGOON_MAX_CASCADES
  struct LatticeMoves {
    std::array<glm::dvec2, kMaxLattices> point{}, grad{};
    double sea_scale = 1;
  };
  LatticeMoves lattice_moves(glm::dvec2 xz) const;
  // A slope of cascade c read at its moved point, as the surface's at the rest position (the chain rule).
  glm::dvec2 lattice_slope(size_t c, const LatticeMoves& moves, glm::dvec2 slope) const;
  // (k0, k0/|k0|²) of cascade c's representative wave, as the shaders take it (zeros: not moved).
  glm::dvec4 lattice_wave(size_t c) const;
  // Its local wavevector in world (x, z).
  glm::dvec2 wavevector(const glm::dvec4& value) const;
  // The table, layer after layer (samples() texels each, rows of columns), for the GPU.
  const std::vector<glm::dvec4>& table() const { return table_; }

  // Linear theory's pieces, exposed for tests: k solving ω² = g k tanh(k h), and c_g there.
  static double wavenumber(double omega, double depth_m);
  static double group_velocity(double omega, double depth_m);

 private:
  struct Where {
    size_t i0, i1, j0, j1;
    double fu, fv, beyond_u, beyond_v;
  };
  Where locate(glm::dvec2 xz) const;
  glm::dvec4 at(size_t layer, const Where& w) const;
  glm::dvec4 wave_at(size_t layer, const ShoalingWave& wave, const Where& w) const;
  const ShoalingWave& layer_wave(size_t layer) const;
  // Each fills a wave's layer (1 + i for wave i, lattice_layer(c) for a cascade's) and returns the wave's
  // amplitude before breaking at every sample.
  std::vector<double> build_profile_wave(size_t layer);  // one row: straight contours, closed form along u
  std::vector<double> build_grid_wave(size_t layer);     // rows: the eikonal and the energy flux on the grid
  ShoalingInputs inputs_;
  std::vector<glm::dvec4> table_;
  std::vector<glm::dvec4> lattice_waves_;  // lattice_wave(c) for each cascade, made once
  bool active_ = false;
};

}  // namespace lagoon::ocean
