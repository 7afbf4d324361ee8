// Models gerstner and sines with their own list of waves are evaluated directly (seed 001 eq. 11, eqs. 1-3;
// docs/models.md): every wave keeps its exact wavelength and direction and, for Gerstner waves, its own
// steepness Q_i. The renderer sums them where it draws (common/direct_waves.glsl), the step writes them at
// the first cascade's texels (gpu/direct_waves_gpu.h), and WaveQuery, probe and the bodies answer from
// GerstnerSurface, the same sums in double precision. The cascades' spectra stay empty.
//
// Waves sampled from the spectrum (`spectrum_waves` > 0: up to 64, the case where one FFT is cheaper than a
// sum per pixel) still go through the cascades, on their lattice (gerstner.h, sines.h), and there the FFT
// equals the direct sum of those lattice waves.
#pragma once
#include <optional>
#include <vector>

#include "ocean/gerstner.h"
#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "ocean/shoaling.h"
#include "shared/direct_waves.h"

namespace lagoon::ocean {

// The waves the scene's model evaluates directly, or nothing when the cascades carry its sea.
std::optional<GerstnerParams> direct_wave_params(const OceanParams& params);
inline bool evaluated_directly(const OceanParams& params) {
  return direct_wave_params(params).has_value();
}

// Swell trains over the random sea (OceanParams::swell_waves), or nothing: for the cascade models only. Their
// table over the floor holds the random sea's depth-limited scale and its lattices' moves too
// (ocean/random_sea.h).
std::optional<GerstnerParams> swell_wave_params(const OceanParams& params, const RandomSea& sea);
// The waves the surface sums where it is drawn: the model's own, or the swell over the cascades.
std::optional<GerstnerParams> summed_wave_params(const OceanParams& params, const RandomSea& sea);

// The random sea's significant height, 4σ over its spectra, as the renderer's shading takes it: what its
// depth limit over the floor is computed from (ocean/shoaling.h).
double sea_significant_height(const std::vector<CascadeSpectrum>& spectra);
// The random sea over the floor on its own (when no waves are summed, whose table holds it too), or null
// where the floor changes nothing.
std::shared_ptr<const Shoaling> sea_over_floor(const OceanParams& params, const RandomSea& sea);

// The waves as the shaders read them. With `at_time`, each phase is φ - ω t reduced to [-π, π] in double
// (the frame's: the shaders add k·x0); without, the phase is φ and ω turns it (the step's).
std::vector<gpu::DirectWaveGpu> direct_waves_gpu(const GerstnerSurface& surface,
                                                 std::optional<double> at_time = std::nullopt);

}  // namespace lagoon::ocean
