#include "optics/composite_error.h"

#include <algorithm>
#include <cmath>

#include "optics/colour.h"
#include "optics/colour_difference.h"

namespace lagoon::optics {
namespace {

constexpr double kVisibleDeltaE = 2.0;

Spectrum times(const Spectrum& a, const Spectrum& b) {
  Spectrum out{};
  for (int i = 0; i < kSamples; ++i) out[i] = a[i] * b[i];
  return out;
}

struct Colour {
  PhiMode mode;
  Spectrum white;
  bool clip;
  // Φ of a spectral irradiance (the four flows' unit, W m⁻² nm⁻¹), clipped at 0 as the LUTs are.
  glm::dvec3 phi(const Spectrum& irradiance) const {
    const glm::dvec3 signed_rgb = adapted_linear_srgb(irradiance, white);
    const glm::dvec3 rgb = clip ? glm::max(signed_rgb, glm::dvec3(0.0)) : signed_rgb;
    return mode == PhiMode::Seed ? tone_map(rgb) : rgb;
  }
  // What the display shows of a composited colour: the seed's tables are already tone-mapped.
  glm::dvec3 display(glm::dvec3 rgb) const {
    return mode == PhiMode::Seed ? glm::clamp(rgb, 0.0, 1.0) : tone_map(rgb);
  }
};

}  // namespace

const char* composite_name(Composite c) {
  switch (c) {
    case Composite::Eq21:
      return "eq21";
    case Composite::Eq22:
      return "eq22";
    case Composite::Eq24:
      return "eq24";
  }
  return "?";
}

const char* phi_mode_name(PhiMode m) {
  return m == PhiMode::Seed ? "seed" : "linear";
}

Result<CompositeErrors> composite_errors(const LutInputs& in, const Spectrum& bottom, PhiMode mode,
                                         bool clip_tables) {
  const uint32_t n = std::max(2u, in.params.lut_size);
  CompositeErrors out;
  out.r_m = lut_axis(in.params.lut_r_max_m, n);
  out.h_m = lut_axis(in.params.lut_h_max_m, n);
  const Colour colour{mode, downwelling_white(in.sky), clip_tables};
  const glm::dvec3 t_bottom =
      glm::max(adapted_linear_srgb(times(bottom, colour.white), colour.white), glm::dvec3(0.0));
  out.exact.resize(size_t{n} * n);
  for (auto& v : out.approx) v.resize(size_t{n} * n);
  for (auto& v : out.delta_e) v.resize(size_t{n} * n);
  out.eq22_clipped.resize(size_t{n} * n);
  out.a.resize(size_t{n} * n);
  for (uint32_t j = 0; j < n; ++j) {
    auto column = lut_column(in, out.h_m[j]);
    if (!column) return column.error();
    const glm::dvec3 t0_h = colour.phi(column->at_bottom), t1_h = colour.phi(column->upwelling);
    for (uint32_t i = 0; i < n; ++i) {
      const LutPath p = lut_path(*column, out.r_m[i], out.h_m[j], in.params.lut_gamma);
      Spectrum exact{}, bottom_part{}, scatter_part{};
      for (int k = 0; k < kSamples; ++k) {
        bottom_part[k] = p.alpha[k] * column->at_bottom[k];
        scatter_part[k] = (1.0 - p.alpha[k]) * column->upwelling[k];
        exact[k] = bottom[k] * bottom_part[k] + scatter_part[k];
      }
      const size_t at = size_t{i} * n + j;
      out.a[at] = p.a;
      out.exact[at] = colour.display(Colour{mode, colour.white, false}.phi(exact));
      const glm::dvec3 eq21 = colour.phi(bottom_part) * t_bottom + colour.phi(scatter_part);
      Spectrum bottom_per_alpha = bottom_part, scatter_per_rest = scatter_part;
      for (int k = 0; k < kSamples; ++k) {
        bottom_per_alpha[k] /= std::max(p.mean_alpha, 1e-300);
        scatter_per_rest[k] /= std::max(1.0 - p.mean_alpha, 1e-300);
      }
      const glm::dvec3 eq22 =
          p.a * colour.phi(bottom_per_alpha) * t_bottom + (1 - p.a) * colour.phi(scatter_per_rest);
      const glm::dvec3 raw_t0 = adapted_linear_srgb(bottom_per_alpha, colour.white);
      const glm::dvec3 raw_t1 = adapted_linear_srgb(scatter_per_rest, colour.white);
      out.eq22_clipped[size_t{i} * n + j] =
          std::min({raw_t0.x, raw_t0.y, raw_t0.z, raw_t1.x, raw_t1.y, raw_t1.z}) < 0;
      const glm::dvec3 t_alpha = colour.phi(times(p.alpha, colour.white));
      const glm::dvec3 eq24 = t_alpha * t_bottom * t0_h + (glm::dvec3(1.0) - t_alpha) * t1_h;
      const glm::dvec3 approx[kComposites] = {eq21, eq22, eq24};
      const glm::dvec3 exact_lab = linear_srgb_to_lab(out.exact[at]);
      for (int c = 0; c < kComposites; ++c) {
        out.approx[c][at] = colour.display(approx[c]);
        out.delta_e[c][at] = delta_e_2000(exact_lab, linear_srgb_to_lab(out.approx[c][at]));
      }
    }
  }
  return out;
}

ErrorSummary summarise(const CompositeErrors& errors, Composite composite, double min_a) {
  ErrorSummary s;
  std::vector<double> sorted;
  const std::vector<double>& delta_e = errors.delta_e[int(composite)];
  for (size_t k = 0; k < delta_e.size(); ++k)
    if (errors.a[k] >= min_a) sorted.push_back(delta_e[k]);
  if (sorted.empty()) return s;
  std::sort(sorted.begin(), sorted.end());
  double sum = 0;
  size_t visible = 0;
  for (double d : sorted) sum += d, visible += d > kVisibleDeltaE ? 1 : 0;
  s.mean = sum / double(sorted.size());
  s.p95 = sorted[std::min(sorted.size() - 1, size_t(0.95 * double(sorted.size())))];
  s.max = sorted.back();
  s.visible_share = double(visible) / double(sorted.size());
  return s;
}

}  // namespace lagoon::optics
