#include "ocean/validate.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/direct_waves.h"
#include "ocean/gerstner.h"
#include "ocean/initial_spectrum.h"
#include "ocean/model_constraints.h"
#include "ocean/sines.h"
#include "ocean/springs.h"

namespace lagoon::ocean {
namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

class Problems {
 public:
  void add(const std::string& field, const std::string& message) {
    if (!text_.empty()) text_ += '\n';
    text_ += "ocean." + field + ": " + message;
  }
  // NaN fails every comparison, so each check is written to reject it.
  void positive(const std::string& field, double v, const char* unit) {
    if (!(v > 0.0) || !std::isfinite(v)) add(field, num(v) + " must be > 0 (" + unit + ")");
  }
  void range(const std::string& field, double v, double lo, double hi, const char* why) {
    if (!(v >= lo && v <= hi))
      add(field, num(v) + " must be in [" + num(lo) + ", " + num(hi) + "]" + (*why ? " (" : "") + why +
                     (*why ? ")" : ""));
  }
  Result<void> result() const {
    if (text_.empty()) return {};
    return make_error(text_);
  }

 private:
  std::string text_;
};

bool power_of_two_in_range(uint32_t n) {
  return n >= kMinResolution && n <= kMaxResolution && (n & (n - 1)) == 0;
}

void check_cascades(const OceanParams& p, Problems& problems) {
  const size_t count = p.cascades.size();
  if (count < 1 || count > kMaxCascades) {
    problems.add("cascades", std::to_string(count) + " cascades given; use 1 to " +
                                 std::to_string(kMaxCascades) + " (largest patch first)");
    if (count < 1) return;
  }
  bool sizes_ok = true;
  for (size_t i = 0; i < count; ++i) {
    const CascadeParams& c = p.cascades[i];
    const std::string at = "cascades[" + std::to_string(i) + "].";
    if (!power_of_two_in_range(c.resolution))
      problems.add(at + "resolution", std::to_string(c.resolution) + " is not a power of two between " +
                                          std::to_string(kMinResolution) + " and " +
                                          std::to_string(kMaxResolution) + "; use 64, 128, 256, 512 or 1024");
    if (!(c.patch_size_m > 0.0) || !std::isfinite(c.patch_size_m)) {
      problems.positive(at + "patch_size_m", c.patch_size_m, "metres");
      sizes_ok = false;
    }
  }
  if (!sizes_ok) return;
  for (size_t i = 1; i < count; ++i) {
    const CascadeParams &prev = p.cascades[i - 1], &c = p.cascades[i];
    const std::string field = "cascades[" + std::to_string(i) + "].patch_size_m";
    const std::string prev_field = "cascades[" + std::to_string(i - 1) + "].patch_size_m";
    if (!(c.patch_size_m < prev.patch_size_m)) {
      problems.add(field, num(c.patch_size_m) + " m must be smaller than " + prev_field + " (" +
                              num(prev.patch_size_m) + " m): list cascades largest patch first");
      continue;
    }
    if (!power_of_two_in_range(prev.resolution) || !power_of_two_in_range(c.resolution)) continue;
    // Bands (initial_spectrum.h): cascade i carries [k_max(i-1), k_max(i)), k_max = π N/(2L).
    const double pi = std::numbers::pi;
    const double band_start = pi * prev.resolution / (2.0 * prev.patch_size_m);
    const double band_end = pi * c.resolution / (2.0 * c.patch_size_m);
    if (2.0 * pi / c.patch_size_m > band_start) {
      // Its lowest wave 2π/L lies above where its band starts: the waves in between would be missing.
      const double min_size = 2.0 * pi / band_start;  // = 4 L(i-1) / N(i-1)
      const double max_prev = prev.resolution * c.patch_size_m / 4.0;
      problems.add(field, num(c.patch_size_m) + " m is too small to carry the start of its band (k = " +
                              num(band_start) + " rad/m, where " + prev_field +
                              "'s band ends): its longest wave has k = 2π/L = " +
                              num(2.0 * pi / c.patch_size_m) + " rad/m; use at least " + num(min_size) +
                              " m here, or at most " + num(max_prev) + " m for " + prev_field);
    } else if (!(band_end > band_start)) {
      const double max_size = c.resolution * prev.patch_size_m / prev.resolution;  // k_max(i) > k_max(i-1)
      problems.add(field, num(c.patch_size_m) +
                              " m leaves this cascade no waves: its band would end at π N/(2L) = " +
                              num(band_end) + " rad/m, not above where it starts (" + num(band_start) +
                              " rad/m); the largest allowed size is below " + num(max_size) +
                              " m (or raise its resolution)");
    }
  }
}

// Waves evaluated directly (direct_waves.h): each its own Q_i, and no loops (Σ Q_i k_i A_i <= 1).
void check_direct_steepness(const GerstnerParams& direct, const OceanParams& p, Problems& problems) {
  double sum = 0, fixed = 0, chopped = 0;  // Σ Q k A; of it, the waves with their own Q and those with λ
  for (size_t i = 0; i < direct.waves.size(); ++i) {
    const GerstnerWave& w = direct.waves[i];
    const double k = 2 * std::numbers::pi / w.wavelength_m;
    if (!(w.steepness >= 0) || !(w.steepness <= 1))
      problems.add(
          "gerstner.waves[" + std::to_string(i) + "].steepness",
          num(w.steepness) + " must be 0 to 1 (Q of eq. 11: 0 = a sine, 1 = the document's circles)");
    sum += w.steepness * k * w.amplitude_m;
    (p.gerstner.waves[i].steepness ? fixed : chopped) += w.steepness * k * w.amplitude_m;
  }
  if (sum <= 1 + 1e-12) return;
  if (chopped > 0)
    problems.add("choppiness",
                 num(p.choppiness) + " loops the crests of these Gerstner waves: Σ Q k A = " + num(sum) +
                     " > 1 (Q = choppiness where a wave sets no steepness); use at most " +
                     num(std::max(0.0, 1 - fixed) / (chopped / p.choppiness)) + " or lower the amplitudes");
  else
    problems.add("gerstner.waves", "their steepness loops the crests: Σ Q_i k_i A_i = " + num(sum) +
                                       " > 1; lower the waves' steepness or amplitudes");
}

// Model gerstner: every wave finite and held by some cascade's band, and no loops (Σ λ k A <= 1).
void check_gerstner(const OceanParams& p, Problems& problems) {
  const std::vector<GerstnerWaveSpec> waves = gerstner_wave_specs(p);
  const bool sampled = p.gerstner.spectrum_waves > 0;
  // Where a wave's fix goes: the wave the file lists, or the sampling setting.
  const auto field = [sampled](size_t i, const char* name) {
    return sampled ? "gerstner.spectrum_waves (sampled wave " + std::to_string(i) + ", " + name + ")"
                   : "gerstner.waves[" + std::to_string(i) + "]." + name;
  };
  if (waves.empty()) problems.add("gerstner.waves", "is empty; model gerstner needs at least one wave");
  double sum = 0;
  bool finite = true;
  for (size_t i = 0; i < waves.size(); ++i) {
    const GerstnerWaveSpec& w = waves[i];
    if (!(w.amplitude_m >= 0) || !std::isfinite(w.amplitude_m)) {
      problems.add(field(i, "amplitude_m"), num(w.amplitude_m) + " must be >= 0 (metres)");
      finite = false;
    }
    if (!(w.wavelength_m > 0) || !std::isfinite(w.wavelength_m)) {
      problems.add(field(i, "wavelength_m"), num(w.wavelength_m) + " must be > 0 (metres)");
      finite = false;
    }
    if (!std::isfinite(w.direction_deg) || !std::isfinite(w.phase_deg)) {
      problems.add(field(i, "direction_deg"), "direction and phase must be finite angles in degrees");
      finite = false;
    }
    if (finite) sum += 2 * std::numbers::pi / w.wavelength_m * w.amplitude_m;
  }
  if (!finite) return;
  if (std::optional<GerstnerParams> direct = direct_wave_params(p)) {
    check_direct_steepness(*direct, p, problems);
    return;
  }
  std::vector<int> cascade_of;
  lattice_gerstner_waves(p, &cascade_of);
  const double shortest = 2 * std::numbers::pi / cascade_bands(p).back().k_max;
  for (size_t i = 0; i < cascade_of.size(); ++i)
    if (cascade_of[i] < 0)
      problems.add(field(i, "wavelength_m"),
                   num(waves[i].wavelength_m) + " m is held by no cascade: they hold waves from " +
                       num(p.cascades.front().patch_size_m) + " m (the first patch) down to " +
                       num(shortest) + " m (4 texels of the last); change the wavelength or the cascades");
  if (p.choppiness * sum > 1 + 1e-12)
    problems.add("choppiness", num(p.choppiness) + " loops the crests of these Gerstner waves: Σ Q k A = " +
                                   num(p.choppiness * sum) + " > 1 (Q = choppiness); use at most " +
                                   num(1 / sum) + " or lower the amplitudes");
}

// Model sines: points move only vertically, and every wave with all its harmonics in one cascade's band.
void check_sines(const OceanParams& p, Problems& problems) {
  for (const ModelConstraint& c : model_constraints(SurfaceModel::Sines))
    if (p.*c.member != c.value)
      problems.add(c.field, num(p.*c.member) + " must be " + num(c.value) + " for model sines: " + c.reason);
  const std::vector<SineWaveSpec> waves = sines_wave_specs(p);
  if (waves.empty()) problems.add("sines.waves", "is empty; model sines needs at least one wave");
  for (size_t i = 0; i < waves.size(); ++i) {
    const SineWaveSpec& w = waves[i];
    const std::string at = "sines.waves[" + std::to_string(i) + "].";
    if (!(w.wavelength_m > 0) || !std::isfinite(w.wavelength_m) || !(w.amplitude_m >= 0) ||
        !std::isfinite(w.amplitude_m) || !std::isfinite(w.direction_deg) || !std::isfinite(w.phase_deg) ||
        w.steepness < 1 || w.steepness > 8) {
      problems.add(at + "wavelength_m",
                   "needs wavelength_m > 0, amplitude_m >= 0, a finite direction and "
                   "phase, and steepness 1 to 8");
      return;
    }
  }
  if (evaluated_directly(p)) return;  // exact waves: no lattice to hold them
  const std::vector<SineLattice> lattice = sines_lattice(p);
  const double shortest = 2 * std::numbers::pi / cascade_bands(p).back().k_max;
  for (size_t i = 0; i < lattice.size(); ++i)
    if (!lattice[i].harmonics_held)
      problems.add("sines.waves[" + std::to_string(i) + "].wavelength_m",
                   num(waves[i].wavelength_m) + " m with steepness " + std::to_string(waves[i].steepness) +
                       ": no cascade holds the wave and its harmonics down to wavelength / steepness, 4 "
                       "texels each, on "
                       "a patch at least a wavelength wide (the patches are " +
                       num(p.cascades.back().patch_size_m) + " to " + num(p.cascades.front().patch_size_m) +
                       " m; the finest grid's shortest wave is " + num(shortest) +
                       " m); lengthen the wave or lower its steepness");
}

// Model perlin: the last octave's cells must keep 2 grid samples each on the first cascade.
void check_perlin(const OceanParams& p, Problems& problems) {
  const PerlinParams& n = p.perlin;
  problems.range("perlin.amplitude_m", n.amplitude_m, 0.0, 100.0, "metres");
  problems.range("perlin.persistence", n.persistence, 0.0, 1.0, "amplitude ratio between octaves");
  if (n.cells < 1 || n.octaves < 1 || n.lacunarity < 2) {
    problems.add("perlin.cells", "cells, octaves >= 1 and lacunarity >= 2 are needed");
    return;
  }
  const double last = double(n.cells) * std::pow(double(n.lacunarity), double(n.octaves - 1));
  const uint32_t samples = p.cascades.front().resolution;
  if (last * 2 > samples)
    problems.add("perlin.octaves",
                 std::to_string(n.octaves) + " octaves reach " + num(last) +
                     " cells across the first cascade, more than its " + std::to_string(samples) +
                     " samples can draw (2 per cell); use fewer octaves or cells, or a finer "
                     "first cascade");
}

// Model springs: positive constants, a step within the stability limit, excitations that fit the GPU's list.
void check_springs(const OceanParams& p, Problems& problems) {
  const SpringsParams& s = p.springs;
  problems.positive("springs.mass_kg", s.mass_kg, "kg per node (4 in Table 1)");
  problems.positive("springs.stiffness_n_per_m", s.stiffness_n_per_m, "N/m per spring (7 in Table 1)");
  problems.range("springs.damping_kg_per_s", s.damping_kg_per_s, 0.0, 1e6, "kg/s (0.05 in Table 1)");
  problems.positive("springs.step_s", s.step_s, "seconds per step (0.4 in Table 1)");
  problems.range("springs.rest_length", s.rest_length, 0.0, 0.99, "eq. 4's L as a fraction of the spacing");
  problems.range("springs.boundary_amplitude_m", s.boundary_amplitude_m, 0.0, 100.0, "metres; 0 = off");
  problems.positive("springs.boundary_period_s", s.boundary_period_s, "seconds");
  if (!problems.result()) return;
  const double limit = springs_stability_limit_s(s);
  if (s.step_s > limit)
    problems.add("springs.step_s", num(s.step_s) + " s is above the grid's stability limit " + num(limit) +
                                       " s = 2 / sqrt(8 c / m): the stiffest wave would grow without bound; "
                                       "use a smaller step, a heavier mass or softer springs");
  if (s.drops.size() + s.gusts.size() > LAGOON_SPRINGS_MAX_EXCITATIONS)
    problems.add("springs.drops", std::to_string(s.drops.size() + s.gusts.size()) +
                                      " drops and gusts; at most " +
                                      std::to_string(LAGOON_SPRINGS_MAX_EXCITATIONS) + " together");
  const double last = double(std::numeric_limits<uint32_t>::max() - 1) * s.step_s;
  for (size_t i = 0; i < s.drops.size(); ++i) {
    const std::string at = "springs.drops[" + std::to_string(i) + "]";
    problems.positive(at + ".radius_m", s.drops[i].radius_m, "metres");
    problems.range(at + ".time_s", s.drops[i].time_s, 0.0, last, "seconds");
  }
  for (size_t i = 0; i < s.gusts.size(); ++i) {
    const std::string at = "springs.gusts[" + std::to_string(i) + "]";
    problems.positive(at + ".radius_m", s.gusts[i].radius_m, "metres");
    problems.range(at + ".time_s", s.gusts[i].time_s, 0.0, last, "seconds");
    problems.range(at + ".duration_s", s.gusts[i].duration_s, 0.0, last, "seconds");
  }
}

}  // namespace

Result<void> validate(const OceanParams& p) {
  Problems problems;
  problems.positive("depth_m", p.depth_m, "metres of water");
  problems.range("choppiness", p.choppiness, 0.0, 5.0, "0 = no horizontal displacement");
  if (!(p.loop_period_s >= 0.0) || !std::isfinite(p.loop_period_s))
    problems.add("loop_period_s", num(p.loop_period_s) + " must be >= 0 (seconds; 0 = no loop)");

  const SpectrumParams& s = p.spectrum;
  if (std::string_view(to_string(s.type)) == "?")
    problems.add("spectrum.type",
                 "unknown spectrum; use phillips, pm, jonswap, tma, jonswap-eq15 or phillips-eq18");
  if (std::string_view(to_string(s.spreading)) == "?")
    problems.add("spectrum.spreading", "unknown spreading; use cos2, cos2s or donelan-banner");
  problems.positive("spectrum.wind_speed_mps", s.wind_speed_mps, "m/s at 10 m height");
  if (!std::isfinite(s.wind_direction_deg))
    problems.add("spectrum.wind_direction_deg",
                 num(s.wind_direction_deg) + " must be a finite angle in degrees");
  problems.positive("spectrum.fetch_km", s.fetch_km, "km of open water upwind");
  problems.range("spectrum.gamma", s.gamma, 1.0, 20.0, "JONSWAP peak enhancement, 3.3 is typical");
  problems.range("spectrum.swell", s.swell, 0.0, 1.0, "");
  if (!(s.amplitude > 0.0) || !(s.amplitude <= 1.0))
    problems.add("spectrum.amplitude", num(s.amplitude) + " must be in (0, 1] (phillips-eq18's A)");
  problems.range("spectrum.directional_exponent", s.directional_exponent, 0.0, 64.0,
                 "phillips-eq18's p in |cos φ|^p, 2 in the document");
  if (!(s.small_wave_cutoff_m >= 0.0) || !std::isfinite(s.small_wave_cutoff_m))
    problems.add("spectrum.small_wave_cutoff_m",
                 num(s.small_wave_cutoff_m) + " must be >= 0 (metres; 0 = none)");

  if (!std::isfinite(p.foam.threshold))
    problems.add("foam.threshold",
                 num(p.foam.threshold) + " must be a finite Jacobian value (0.5 is typical)");
  if (!(p.foam.decay_per_s >= 0.0) || !std::isfinite(p.foam.decay_per_s))
    problems.add("foam.decay_per_s", num(p.foam.decay_per_s) + " must be >= 0 (1/s)");

  check_cascades(p, problems);
  if (p.model == SurfaceModel::Gerstner && problems.result()) check_gerstner(p, problems);
  if (p.model == SurfaceModel::Sines && problems.result()) check_sines(p, problems);
  if (p.model == SurfaceModel::Perlin && problems.result()) check_perlin(p, problems);
  if (p.model == SurfaceModel::Springs && problems.result()) check_springs(p, problems);
  return problems.result();
}

}  // namespace lagoon::ocean
