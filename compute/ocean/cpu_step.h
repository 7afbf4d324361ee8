// The CPU reference of one GPU ocean step (gpu/gpu_ocean.h), in double precision from the same h0 and ω:
// displacement, normal, Jacobian and foam with the same conventions and foam update.
#pragma once
#include <vector>

#include "ocean/ocean_params.h"
#include "ocean/spectral_fields.h"
#include "ocean/whitecaps.h"

namespace lagoon::ocean {

struct CpuCascadeFields {
  uint32_t resolution = 0;
  // Row-major [z][x]; 4 values per texel as in the GPU textures.
  std::vector<double> displacement;     // (λDx, h, λDz, foam)
  std::vector<double> normal_jacobian;  // (nx, ny, nz, J)
  std::vector<double> jacobian_terms;   // (λ∂Dx/∂x, λ∂Dz/∂z, λ∂Dx/∂z, foam)
};

class CpuOceanStep {
 public:
  // Each cascade's foam follows foam_rule(params, spectra).cascades, as the GPU step's does.
  CpuOceanStep(const OceanParams& params, std::vector<CascadeSpectrum> spectra, InverseFft2d fft);
  // Advances to `time_s`; dt_s is the time since the previous step (foam). The first step starts foam at 0.
  void step(double time_s, double dt_s);
  const std::vector<CpuCascadeFields>& cascades() const { return cascades_; }

 private:
  OceanParams params_;
  std::vector<CascadeSpectrum> spectra_;
  InverseFft2d fft_;
  std::vector<FoamRamp> foam_;  // per cascade
  std::vector<CpuCascadeFields> cascades_;
  bool first_ = true;
};

}  // namespace lagoon::ocean
