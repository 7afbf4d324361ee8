// The dynamic wave layer (issue 14, docs/physics.md "Wakes"): linear water waves on an N x N grid around the
// camera, forced by the pressure of moving hulls, added to the FFT ocean. Each mode is advanced exactly
// (shaders/shared/dynamic_layer_math.h), so any step is stable; a border of growing damping absorbs what
// leaves the window. This is the CPU reference in double precision (FFTs by fft/cpu_fft.h); the renderer runs
// the same steps on the GPU (ocean/gpu/dynamic_layer_gpu.h), and the two are tested against each other. The
// hulls' foam trails live on the same grid: injected behind the sterns, saturating at 1, decaying with
// foam_lifetime_s.
//
// Storage is toroidal: world cell (a, b), at (x, z) = (a, b) · cell, lives at index (a mod n, b mod n), so
// the window moves by whole cells without copying; cells that enter it come from the opposite border, where
// the sponge has already brought them to rest.
#pragma once
#include <complex>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "fft/cpu_fft.h"

namespace lagoon::ocean {

struct DynamicLayerParams {
  uint32_t n = 512;             // cells per side (a supported FFT size)
  double cell_m = 0.25;         // cell size
  double gravity = 9.81;        // m/s²
  double depth_m = 0;           // of the water; <= 0: deep
  double decay_per_s = 0.02;    // damping of every mode
  double sponge_m = 16;         // width of the absorbing border
  double sponge_per_s = 3;      // damping rate at the very edge
  double foam_lifetime_s = 20;  // a trail's foam fades to 5 % (e^-3) in this time
  // The trails' diffusivity (m²/s): a trail widens as it ages, its variance across growing by 2 D t (seed
  // 002 §3.3: the trail is the hull's width at its start and wider toward its end). 0 = a band of fixed
  // width.
  double foam_spread_m2_s = 0.1;
};

// A hull's pressure on the water as the still-water depression it makes: a Gaussian of `sigma` (along and
// across its heading) and `depression` metres deep at its centre, moving at `velocity` from `centre` at the
// step's start; a submerged one (`depth` below the surface) shows at the surface through exp(-k depth).
struct WakeSource {
  glm::dvec2 centre{0.0};    // world (x, z), m
  glm::dvec2 velocity{0.0};  // m/s
  double heading = 0;        // rad, compass (clockwise from north, core/compass.h)
  glm::dvec2 sigma{1.0};     // m
  double depression = 0;     // m
  double depth = 0;          // m
  double foam_per_s = 0;     // foam builds this fast behind its stern (0.3 of it at its bow); 0 = none
};

// How many parts a step's forcing is split into: the sources move at most a quarter of their sigma along
// their motion per part, so the moving footprint is sampled finely enough to make no waves of its own.
uint32_t dynamic_substeps(double dt, std::span<const WakeSource> sources);
// The share of its foam a cell keeps over dt: e^-3 over the lifetime.
double foam_decay_factor(double lifetime_s, double dt);
// D dt / cell² of the trails' explicit diffusion step (shared/dynamic_layer_math.h's dl_foam_spread), held at
// 0.24, below the scheme's stability limit of 1/4: a longer step or a finer cell spreads no faster than that.
double foam_spread_factor(double spread_m2_s, double cell_m, double dt);

class DynamicLayerCpu {
 public:
  explicit DynamicLayerCpu(DynamicLayerParams params, unsigned threads = 2);

  // The window's first cell (world cell index); cells both windows share keep their waves.
  void set_window(glm::ivec2 origin) { origin_ = origin; }
  glm::ivec2 window() const { return origin_; }
  // Off: steps leave the foam at 0 (a user of the heights alone skips the per-cell trail work).
  void set_foam(bool on) { foam_on_ = on; }
  void step(double dt, std::span<const WakeSource> sources);

  const DynamicLayerParams& params() const { return params_; }
  // Height and its rate at world cell (a, b) (any cell: the storage repeats every n cells).
  double height(int a, int b) const { return state_[index(a, b)].real(); }
  double rate(int a, int b) const { return state_[index(a, b)].imag(); }
  // (h, dh/dt) per storage index (a mod n) + n (b mod n).
  const std::vector<std::complex<double>>& state() const { return state_; }
  std::vector<std::complex<double>>& state() { return state_; }
  // The foam trails' coverage, 0..1, per storage index.
  double foam(int a, int b) const { return foam_[index(a, b)]; }
  const std::vector<double>& foam() const { return foam_; }

 private:
  size_t index(int a, int b) const;

  DynamicLayerParams params_;
  unsigned threads_;
  fft::CpuFft2d forward_, inverse_;
  glm::ivec2 origin_{0};
  std::vector<std::complex<double>> state_;  // h + i dh/dt
  std::vector<double> foam_;
  std::vector<double> previous_foam_;  // the step's foam before it spreads (scratch)
  bool foam_on_ = true;
  // dl_turn of every mode for substeps of turns_dt_ (the same each step while the substep is: the sin, cos,
  // tanh and sqrt of a mode were most of a step's per-cell work).
  std::vector<glm::dvec4> turns_;
  double turns_dt_ = -1;
};

}  // namespace lagoon::ocean
