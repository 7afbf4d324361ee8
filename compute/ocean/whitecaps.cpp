#include "ocean/whitecaps.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "ocean/direct_waves.h"
#include "ocean/slope_statistics.h"
#include "ocean/spectral_fields.h"
#include "shared/foam.h"

namespace lagoon::ocean {
namespace {

// The persisting foam's ramp, in standard deviations of the cascade's J: a folding crest whitens fully,
// and what lasts is its fading, not J's passing through a wide ramp.
constexpr double kRampWidthSigma = 0.5;

// Φ⁻¹(p) by bisection on the normal distribution function (p in (0, 1)).
double normal_quantile(double p) {
  double lo = -10, hi = 10;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double jacobian(double lambda, double a, double b, double c) {
  return (1 + lambda * a) * (1 + lambda * b) - lambda * lambda * c * c;
}

// The whole sea's J for waves summed directly (direct_waves.h): eq. 11's Jacobian at the grid's points.
std::vector<double> jacobian_samples(const GerstnerSurface& surface, double side) {
  constexpr uint32_t kGrid = 256;
  std::vector<double> out;
  out.reserve(size_t{kGrid} * kGrid);
  for (uint32_t j = 0; j < kGrid; ++j)
    for (uint32_t i = 0; i < kGrid; ++i)
      out.push_back(surface.at_rest(glm::dvec2(i + 0.5, j + 0.5) * (side / kGrid), 0.0).jacobian);
  return out;
}

// How a cascade's foam is stepped (the still frame's warm-up steps at 0.1 s, OceanStepPass::kWarmupStep),
// and how far back the calibration looks for foam that is still at least ½ now.
constexpr double kStepS = 0.1;
constexpr double kFadeOffset = LAGOON_FOAM_FADE_OFFSET;
constexpr double kLookBackS = 4.0;
// The calibration's points: every cascade's J on a lattice of at most 128² of its texels (exactly those
// texels' values: evaluate_fields_on_lattice), at kEnds times 0.1 s apart.
constexpr uint32_t kLattice = 128;
constexpr int kEnds = 16;

// For each lattice point of one cascade and each of the kEnds times: the least J(t - τ) + width f(τ) over the
// steps τ back to where f reaches 1. Foam m made τ ago shows (m + c) e^{-dτ} - c now (shared/foam_math.h),
// at least ½ when m >= f(τ) = (½ + c) e^{dτ} - c; m = clamp((onset - J)/width, 0, 1), so the point is white
// now exactly when this least value is at most the onset, whatever the onset.
std::vector<double> whitening_levels(const CascadeSpectrum& s, double lambda, double width, double decay) {
  static constexpr Field kTerms[] = {Field::DxDx, Field::DzDz, Field::DxDz};
  const InverseFft2d fft = cpu_inverse_fft(1);
  const uint32_t stride = std::max(s.resolution / kLattice, 1u);
  auto needed = [&](double tau) { return (0.5 + kFadeOffset) * std::exp(decay * tau) - kFadeOffset; };
  const double reach_s = decay > 0
                             ? std::min(std::log((1 + kFadeOffset) / (0.5 + kFadeOffset)) / decay, kLookBackS)
                             : kLookBackS;
  const int back = int(std::floor(reach_s / kStepS + 1e-9));
  std::vector<std::vector<double>> series;  // [step][point]: J
  for (int k = 0; k < back + kEnds; ++k) {
    const auto f = evaluate_fields_on_lattice(s, k * kStepS, kTerms, fft, stride);
    std::vector<double> j(f[0].size());
    for (size_t i = 0; i < j.size(); ++i) j[i] = jacobian(lambda, f[0][i], f[1][i], f[2][i]);
    series.push_back(std::move(j));
  }
  std::vector<double> levels;
  for (int end = back; end < back + kEnds; ++end)
    for (size_t i = 0; i < series[0].size(); ++i) {
      double least = series[end][i] + width * needed(0);
      for (int k = 1; k <= back; ++k)
        least = std::min(least, series[end - k][i] + width * needed(k * kStepS));
      levels.push_back(least);
    }
  std::sort(levels.begin(), levels.end());
  return levels;
}

// The onset at which `share` of the levels (whitening_levels) lie below: read off the levels where at least
// 20 lie below it; for the calmest seas from their mean and standard deviation as if Gaussian (J's lower
// tail is heavier than a Gaussian's: the Gaussian's quantile whitens 3-5 x the share where the levels have
// it).
double persisting_onset(const std::vector<double>& levels, double share) {
  if (share * double(levels.size()) >= 20) return levels[size_t(share * double(levels.size()))];
  double mean = 0, square = 0;
  for (double v : levels) mean += v, square += v * v;
  mean /= double(levels.size());
  const double sigma = std::sqrt(std::max(square / double(levels.size()) - mean * mean, 0.0));
  return mean + sigma * normal_quantile(share);
}

// The ramp whose foam, applied afresh every frame, covers `coverage` of a sea with J samples `j` (its
// standard deviation σ): J's lower tail is not Gaussian (J = (1 + a)(1 + b) - c²), so the quantile is read
// off the samples where enough lie below it, and taken from the Gaussian only for the calmest seas. The
// ramp is one σ wide (a crest whitens over one standard deviation of squeezing, not in a hard edge).
FoamRamp instant_ramp(std::vector<double> j, double coverage, double sigma) {
  sigma = std::max(sigma, 1e-3);
  const size_t below = size_t(coverage * double(j.size()));
  if (below >= 20) {
    std::nth_element(j.begin(), j.begin() + long(below), j.end());
    return {j[below] + 0.5 * sigma, sigma};
  }
  return {1.0 + sigma * normal_quantile(coverage) + 0.5 * sigma, sigma};
}

}  // namespace

double foam_memory_s(double decay_per_s) {
  return decay_per_s > 0 ? std::log(1 + 1 / kFadeOffset) / decay_per_s
                         : std::numeric_limits<double>::infinity();
}

double monahan_coverage(double wind_speed_mps) {
  return 3.84e-6 * std::pow(std::max(wind_speed_mps, 0.0), 3.41);
}

FoamRule foam_rule(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra) {
  const FoamRamp seed{params.foam.threshold, 1.0};
  const std::vector<FoamRamp> seeds(spectra.size(), seed);
  if (params.foam.coverage == FoamCoverage::Threshold || params.model == SurfaceModel::Springs ||
      spectra.empty())
    return {seed, seeds};
  const double coverage = std::clamp(monahan_coverage(params.spectrum.wind_speed_mps), 1e-9, 0.5);
  if (const std::optional<GerstnerParams> direct = direct_wave_params(params)) {
    // σ_J² = Σ (Q k A)²/2: for waves summed directly J - 1 ≈ -Σ Q k A cos θ.
    const GerstnerSurface surface(*direct);
    double variance = 0;
    for (size_t i = 0; i < surface.size(); ++i) {
      const double qka =
          surface.steepness(i) * glm::length(surface.wavevector(i)) * direct->waves[i].amplitude_m;
      variance += 0.5 * qka * qka;
    }
    // A sea that moves only up and down (the sines) has J = 1 everywhere: nothing squeezes it, and a rule
    // fitted to no spread would whiten all of it.
    if (variance == 0) return {{0.0, 1.0}, seeds};
    return {
        instant_ramp(jacobian_samples(surface, spectra.front().patch_size_m), coverage, std::sqrt(variance)),
        seeds};
  }
  // Equal shares whose union (the cascades' foam independent of each other) is W.
  const double share = 1 - std::pow(1 - coverage, 1.0 / double(spectra.size()));
  FoamRule rule{kNoFoam, {}};
  for (const CascadeSpectrum& s : spectra) {
    // J - 1 ≈ λ Σ |k| h̃: σ_J² = λ² × the cascade's mean square slope.
    const double sigma = params.choppiness * std::sqrt(mean_square_slope(s));
    if (!(sigma > 0)) {  // a cascade without waves, or choppiness 0: J = 1, nothing folds
      rule.cascades.push_back(kNoFoam);
      continue;
    }
    const double width = kRampWidthSigma * sigma;
    const std::vector<double> levels = whitening_levels(s, params.choppiness, width, params.foam.decay_per_s);
    rule.cascades.push_back({persisting_onset(levels, share), width});
  }
  return rule;
}

}  // namespace lagoon::ocean
