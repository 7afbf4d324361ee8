#include "ocean/cpu_step.h"

#include <algorithm>
#include <cmath>

#include "ocean/foam_law.h"

namespace lagoon::ocean {

CpuOceanStep::CpuOceanStep(const OceanParams& params, std::vector<CascadeSpectrum> spectra, InverseFft2d fft)
    : params_(params),
      spectra_(std::move(spectra)),
      fft_(std::move(fft)),
      foam_(foam_rule(params_, spectra_).cascades),
      cascades_(spectra_.size()) {}

void CpuOceanStep::step(double time_s, double dt_s) {
  static constexpr Field kFields[] = {Field::Dx,     Field::Height, Field::Dz,   Field::SlopeX,
                                      Field::SlopeZ, Field::DxDx,   Field::DzDz, Field::DxDz};
  const double lambda = params_.choppiness;
  const double fade = std::exp(-params_.foam.decay_per_s * dt_s);
  for (size_t c = 0; c < spectra_.size(); ++c) {
    const auto f = evaluate_fields(spectra_[c], time_s, kFields, fft_);
    CpuCascadeFields& out = cascades_[c];
    const size_t texels = f[0].size();
    out.resolution = spectra_[c].resolution;
    out.displacement.resize(texels * 4, 0.0);
    out.normal_jacobian.resize(texels * 4);
    out.jacobian_terms.resize(texels * 4);
    for (size_t i = 0; i < texels; ++i) {
      const double jxx = 1 + lambda * f[5][i], jzz = 1 + lambda * f[6][i], jxz = lambda * f[7][i];
      const double jacobian = jxx * jzz - jxz * jxz;
      const double previous = first_ ? 0.0 : out.displacement[4 * i + 3];
      const double foam =
          foam_after_step(previous, fade, foam_made(foam_[c].onset, foam_[c].width, jacobian));
      const double inv_len = 1.0 / std::sqrt(f[3][i] * f[3][i] + 1.0 + f[4][i] * f[4][i]);
      const double d[4] = {lambda * f[0][i], f[1][i], lambda * f[2][i], foam};
      const double n[4] = {-f[3][i] * inv_len, inv_len, -f[4][i] * inv_len, jacobian};
      std::copy(d, d + 4, &out.displacement[4 * i]);
      std::copy(n, n + 4, &out.normal_jacobian[4 * i]);
      const double terms[4] = {jxx - 1, jzz - 1, jxz, foam};
      std::copy(terms, terms + 4, &out.jacobian_terms[4 * i]);
    }
  }
  first_ = false;
}

}  // namespace lagoon::ocean
