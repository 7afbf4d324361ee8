#include "optics/colour.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "optics/cie.h"
#include "optics/csv_table.h"

namespace lagoon::optics {
namespace {

// The 3x3 matrix whose rows are the (c_X, c_Y, c_Z) of the rows named `names` in the `row` column.
glm::dmat3 matrix_rows(const char* table_name, const char* const names[3]) {
  const CsvTable table = embedded_table_or_abort(table_name, {.last_column_free_text = true});
  auto row_names = table.texts("row");
  if (!row_names) abort_table_defect(row_names.error().message);
  const std::vector<double> cx = numbers_or_abort(table, "c_X");
  const std::vector<double> cy = numbers_or_abort(table, "c_Y");
  const std::vector<double> cz = numbers_or_abort(table, "c_Z");
  glm::dmat3 m(0.0);
  for (int r = 0; r < 3; ++r) {
    const auto it = std::find(row_names->begin(), row_names->end(), names[r]);
    if (it == row_names->end()) abort_table_defect(table.source() + ": no row '" + names[r] + "'");
    const std::size_t i = static_cast<std::size_t>(it - row_names->begin());
    m[0][r] = cx[i];  // glm: m[column][row]
    m[1][r] = cy[i];
    m[2][r] = cz[i];
  }
  return m;
}

double tumblin_gamma(double luminance_cd_m2) {
  return luminance_cd_m2 > 100.0 ? 2.655 : 1.855 + 0.4 * std::log10(luminance_cd_m2 + 2.3e-5);
}

// B = S·M⁻¹·(1,1,1): the sRGB colour of the adapted white before balancing.
const glm::dvec3& white_balance() {
  static const glm::dvec3 b = xyz_to_linear_srgb() * glm::inverse(xyz_to_lms()) * glm::dvec3(1.0);
  return b;
}

}  // namespace

const glm::dmat3& xyz_to_lms() {
  static const char* const names[3] = {"L", "M", "S"};
  static const glm::dmat3 m = matrix_rows("von_kries_xyz_to_lms.csv", names);
  return m;
}

const glm::dmat3& xyz_to_linear_srgb() {
  static const char* const names[3] = {"R_exact", "G_exact", "B_exact"};
  static const glm::dmat3 m = matrix_rows("srgb_xyz_to_linear_rgb_d65.csv", names);
  return m;
}

const glm::dmat3& linear_srgb_to_xyz() {
  static const char* const names[3] = {"X_from_rgb", "Y_from_rgb", "Z_from_rgb"};
  static const glm::dmat3 m = matrix_rows("srgb_xyz_to_linear_rgb_d65.csv", names);
  return m;
}

double linear_srgb_luminance(glm::dvec3 linear_rgb) {
  return (linear_srgb_to_xyz() * linear_rgb).y;
}

glm::dvec3 adapted_linear_srgb(const Spectrum& f, const Spectrum& white) {
  static const glm::dmat3 lms_to_rgb = xyz_to_linear_srgb() * glm::inverse(xyz_to_lms());
  const glm::dvec3 lms_white = xyz_to_lms() * spectrum_to_xyz(white);
  if (!(lms_white.x > 0.0 && lms_white.y > 0.0 && lms_white.z > 0.0)) return glm::dvec3(0.0);
  const glm::dvec3 adapted = xyz_to_lms() * spectrum_to_xyz(f) / lms_white;  // eq. 17
  return lms_to_rgb * adapted / white_balance();
}

ToneMapCurve tone_map_curve(const ToneMapParams& p) {
  const double exponent = tumblin_gamma(p.world_adaptation_cd_m2) / tumblin_gamma(p.display_adaptation_cd_m2);
  const double m = std::pow(std::sqrt(p.display_max_contrast), exponent - 1.0);
  return {m, exponent, p.world_adaptation_luminance, p.white_luminance};
}

double tone_map_luminance(double L_w, const ToneMapParams& p) {
  if (!(L_w > 0.0) || !(p.world_adaptation_luminance > 0.0)) return 0.0;
  const ToneMapCurve c = tone_map_curve(p);
  const double L_d = c.m * std::pow(L_w / c.world_adaptation, c.exponent);  // in units of L_da
  const double white = c.white;
  if (L_d >= white) return 1.0;
  return std::min(1.0, L_d * (1.0 + L_d / (white * white)) / (1.0 + L_d));
}

glm::dvec3 tone_map(glm::dvec3 linear_rgb, const ToneMapParams& params) {
  const double L = linear_srgb_luminance(linear_rgb);
  if (!(L > 0.0)) return glm::dvec3(0.0);
  return glm::clamp(linear_rgb * (tone_map_luminance(L, params) / L), 0.0, 1.0);
}

glm::dvec3 encode_srgb(glm::dvec3 linear) {
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    const double v = linear[c] > 0.0 ? std::min(linear[c], 1.0) : 0.0;  // NaN -> 0
    out[c] = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  }
  return out;
}

glm::dvec3 decode_srgb(glm::dvec3 encoded) {
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    const double v = encoded[c];
    out[c] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  return out;
}

}  // namespace lagoon::optics
