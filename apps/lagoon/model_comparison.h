// One surface model measured for `lagoon compare` (issue 15, docs/models.md): its render, the GPU time of its
// step, and what its height field shows (field_statistics.h): Hs, peak wavelength and period, the error of
// its spectrum against the scene's target (where it has one), and the tiling correlation at the patch period.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "io/png.h"
#include "ocean/field_statistics.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace lagoon::cli {

struct ModelMeasure {
  std::string model;
  std::string note;         // what compare changed for this model (e.g. choppiness 0 for sines)
  double step_ms = 0;       // GPU timestamps, median over the rounds
  double step_wall_ms = 0;  // submit and wait, median
  double surface_ms = 0;    // the surface pass in the render (GPU), where directly summed waves are evaluated
  double hs_m = 0;          // 4 σ of the summed field
  double peak_wavelength_m = 0;
  double peak_period_s = 0;              // 2π / ω of the peak mode, ω the model's own law
  std::optional<double> spectrum_error;  // band energies against the target (fft, and waves sampled from it)
  double tiling = 0;                     // correlation of h(x) and h(x + L0)
  io::Image8 render;
  ocean::ModeEnergy spectrum;  // of the first cascade, for the plot
};

// The GPU time of one step of the model in `params` (median over `rounds`, after 3 to warm up): for springs
// one step of its grid, for the others a frame at 60 Hz. Device timestamps where the device has them, else
// the wall time of submit and wait.
struct StepTime {
  double device_ms = 0, wall_ms = 0;
  std::vector<double> device_rounds, wall_rounds;
};
StepTime time_model_step(vk::Context& ctx, const ocean::OceanParams& params, int rounds);

// `scene` already has the model set. Renders at scene.time_s; times `rounds` steps.
ModelMeasure measure_model(vk::Context& ctx, const scene::Scene& scene, int rounds);

}  // namespace lagoon::cli
