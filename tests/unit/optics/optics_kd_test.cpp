// The model against measurements: the diffuse attenuation of downwelling light K_d = -d ln(G+ + F+)/dz
// in deep water against Jerlov's (1976) Table XXVII. The seed's eq. 4 gives the diffuse flows no
// path-length factor (diffuse light attenuates like a vertical beam), which makes K_d low where diffuse
// light dominates: turbid water. Clear ocean water (I, IA) must match within 25 % (measured 0.80-1.15);
// the others stay within a bound that documents that known deviation (measured 0.5-1.0).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "optics/csv_table.h"
#include "optics/four_flow.h"
#include "optics/kd.h"
#include "optics/lut.h"
#include "optics/surface.h"
#include "optics/water_types.h"

namespace lagoon::optics {
namespace {

TEST(OpticsKd, DeepWaterAttenuationAgainstJerlov1976) {
  auto table = CsvTable::embedded("jerlov1976_kd_table27.csv");
  ASSERT_TRUE(table) << table.error().message;
  const std::vector<double> nm = numbers_or_abort(*table, "wavelength_nm");
  const char* types[] = {"I", "IA", "IB", "II", "III", "1C", "3C", "5C", "7C", "9C"};
  for (const char* type : types) {
    WaterParams p;
    p.type = std::string("jerlov-") + type;
    auto in = lut_inputs(p, 60.0);
    ASSERT_TRUE(in) << in.error().message;
    const std::vector<double> measured = numbers_or_abort(*table, type);
    for (size_t row = 0; row < nm.size(); ++row) {
      if (nm[row] < 400 || nm[row] > 600) continue;  // the band where the IOP tables and Jerlov overlap well
      const int i = int(std::lround((nm[row] - kLambdaMinNm) / kLambdaStepNm));
      const double ratio = model_kd(*in, i, 1.0) / measured[row];
      if (std::string(type) == "I" || std::string(type) == "IA") {
        EXPECT_NEAR(ratio, 1.0, 0.25) << type << " at " << nm[row] << " nm";
      } else {
        EXPECT_GT(ratio, 0.45) << type << " at " << nm[row] << " nm";
        EXPECT_LT(ratio, 1.15) << type << " at " << nm[row] << " nm";
      }
    }
  }
}

// With the diffuse path-length factor D = 2 (isotropic diffuse light, the default): the geometric mean of
// model / Jerlov over 400-600 nm per type. Six types are within 15 %, II is at 15.0 %; 1C, 3C and 5C are
// 16-28 % low (the docs list them). Over all types the mean |ln ratio| falls from the seed's D = 1 to a third
// of it.
TEST(OpticsKd, ThePathLengthFactorBringsTurbidWaterToJerlov) {
  auto table = CsvTable::embedded("jerlov1976_kd_table27.csv");
  ASSERT_TRUE(table) << table.error().message;
  const std::vector<double> nm = numbers_or_abort(*table, "wavelength_nm");
  const std::map<std::string, double> allowed{{"I", 0.15},   {"IA", 0.15}, {"IB", 0.15}, {"II", 0.16},
                                              {"III", 0.15}, {"1C", 0.30}, {"3C", 0.20}, {"5C", 0.20},
                                              {"7C", 0.15},  {"9C", 0.15}};
  double misfit[2] = {0, 0};
  for (const auto& [type, tolerance] : allowed) {
    WaterParams p;
    p.type = "jerlov-" + type;
    auto in = lut_inputs(p, 60.0);
    ASSERT_TRUE(in) << in.error().message;
    const std::vector<double> measured = numbers_or_abort(*table, type);
    double log_sum[2] = {0, 0};
    int count = 0;
    for (size_t row = 0; row < nm.size(); ++row) {
      if (nm[row] < 400 || nm[row] > 600) continue;
      const int i = int(std::lround((nm[row] - kLambdaMinNm) / kLambdaStepNm));
      log_sum[0] += std::log(model_kd(*in, i, 1.0) / measured[row]);
      log_sum[1] += std::log(model_kd(*in, i, 2.0) / measured[row]);
      ++count;
    }
    const double with_factor = std::exp(log_sum[1] / count);
    RecordProperty("kd_ratio_d2_" + type, std::to_string(with_factor));
    RecordProperty("kd_ratio_d1_" + type, std::to_string(std::exp(log_sum[0] / count)));
    EXPECT_NEAR(with_factor, 1.0, tolerance) << type;
    misfit[0] += std::fabs(log_sum[0] / count) / double(allowed.size());
    misfit[1] += std::fabs(log_sum[1] / count) / double(allowed.size());
  }
  RecordProperty("mean_abs_log_ratio_d1", std::to_string(misfit[0]));
  RecordProperty("mean_abs_log_ratio_d2", std::to_string(misfit[1]));
  EXPECT_LT(misfit[1], 0.5 * misfit[0]);
}

}  // namespace
}  // namespace lagoon::optics
