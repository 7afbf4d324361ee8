#include "optics/cie.h"

#include "optics/csv_table.h"

namespace lagoon::optics {
namespace {

struct CieTables {
  Spectrum x, y, z, d65;
};

const CieTables& tables() {
  static const CieTables t = [] {
    const CsvTable cmf = embedded_table_or_abort("cie1931_2deg_cmf_5nm.csv");
    const CsvTable d65 = embedded_table_or_abort("cie_d65_5nm.csv");
    return CieTables{grid_column_or_abort(cmf, "x_bar"), grid_column_or_abort(cmf, "y_bar"),
                     grid_column_or_abort(cmf, "z_bar"), grid_column_or_abort(d65, "relative_spd")};
  }();
  return t;
}

}  // namespace

const Spectrum& cie_x_bar() {
  return tables().x;
}
const Spectrum& cie_y_bar() {
  return tables().y;
}
const Spectrum& cie_z_bar() {
  return tables().z;
}
const Spectrum& cie_d65() {
  return tables().d65;
}

glm::dvec3 spectrum_to_xyz(const Spectrum& f) {
  const CieTables& t = tables();
  glm::dvec3 xyz(0.0);
  for (int i = 0; i < kSamples; ++i) xyz += f[i] * glm::dvec3(t.x[i], t.y[i], t.z[i]);
  return xyz * static_cast<double>(kLambdaStepNm);
}

glm::dvec2 chromaticity(glm::dvec3 xyz) {
  const double sum = xyz.x + xyz.y + xyz.z;
  if (!(sum > 0.0)) return glm::dvec2(0.0);
  return glm::dvec2(xyz.x, xyz.y) / sum;
}

}  // namespace lagoon::optics
