// The ocean step on the CPU in single precision with FFTW: the baseline `lagoon bench compute` measures
// the GPU against. Same work as the GPU step (evolve, 4 packed complex inverse FFTs per cascade, assembly
// of displacement, normal, Jacobian and foam), written to be fast rather than to be a reference.
#pragma once
#include <fftw3.h>

#include <vector>

#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"

namespace lagoon::cli {

class FftwOceanStep {
 public:
  FftwOceanStep(const ocean::OceanParams& params, const std::vector<ocean::CascadeSpectrum>& spectra,
                int threads);
  ~FftwOceanStep();
  FftwOceanStep(const FftwOceanStep&) = delete;
  FftwOceanStep& operator=(const FftwOceanStep&) = delete;

  void step(float time_s, float dt_s);
  const std::vector<float>& displacement(size_t cascade) const { return cascades_[cascade].displacement; }

 private:
  struct Cascade {
    uint32_t n = 0;
    float dk = 0;
    std::vector<float> pairs;  // (h0(k), conj(h0(-k))) per k
    std::vector<float> omega;
    fftwf_complex* fields = nullptr;  // 4 planes
    fftwf_plan plan = nullptr;
    std::vector<float> displacement, normal_jacobian, jacobian_terms;
  };
  void evolve(Cascade& c, float t, uint32_t row_begin, uint32_t row_end);
  void assemble(Cascade& c, float decay, size_t begin, size_t end);
  ocean::OceanParams params_;
  int threads_;
  std::vector<Cascade> cascades_;
};

}  // namespace lagoon::cli
