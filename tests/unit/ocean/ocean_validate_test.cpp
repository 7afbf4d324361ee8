// validate(): every bad parameter is reported with its JSON path under "ocean." and a fix.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "ocean/validate.h"

namespace lagoon::ocean {
namespace {

TEST(OceanValidate, DefaultsAreValid) {
  const Result<void> r = validate(OceanParams{});
  EXPECT_TRUE(r.ok()) << r.error().message;
}

struct BadCase {
  const char* what;
  std::function<void(OceanParams&)> change;
  std::string expected;  // substring of the message
};

TEST(OceanValidate, EachBadParameterNamesItsField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<BadCase> cases = {
      {"wind", [](OceanParams& p) { p.spectrum.wind_speed_mps = -3; },
       "ocean.spectrum.wind_speed_mps: -3 must be > 0"},
      {"wind 0", [](OceanParams& p) { p.spectrum.wind_speed_mps = 0; },
       "ocean.spectrum.wind_speed_mps: 0 must be > 0"},
      {"wind nan", [&](OceanParams& p) { p.spectrum.wind_speed_mps = nan; }, "ocean.spectrum.wind_speed_mps"},
      {"direction", [&](OceanParams& p) { p.spectrum.wind_direction_deg = nan; },
       "ocean.spectrum.wind_direction_deg"},
      {"fetch", [](OceanParams& p) { p.spectrum.fetch_km = 0; }, "ocean.spectrum.fetch_km: 0 must be > 0"},
      {"depth", [](OceanParams& p) { p.depth_m = -1; }, "ocean.depth_m: -1 must be > 0"},
      {"depth nan", [&](OceanParams& p) { p.depth_m = nan; }, "ocean.depth_m"},
      {"gamma low", [](OceanParams& p) { p.spectrum.gamma = 0.5; },
       "ocean.spectrum.gamma: 0.5 must be in [1, 20]"},
      {"gamma high", [](OceanParams& p) { p.spectrum.gamma = 25; },
       "ocean.spectrum.gamma: 25 must be in [1, 20]"},
      {"swell low", [](OceanParams& p) { p.spectrum.swell = -0.1; },
       "ocean.spectrum.swell: -0.1 must be in [0, 1]"},
      {"swell high", [](OceanParams& p) { p.spectrum.swell = 1.5; },
       "ocean.spectrum.swell: 1.5 must be in [0, 1]"},
      {"cutoff", [](OceanParams& p) { p.spectrum.small_wave_cutoff_m = -1; },
       "ocean.spectrum.small_wave_cutoff_m"},
      {"chop low", [](OceanParams& p) { p.choppiness = -1; }, "ocean.choppiness: -1 must be in [0, 5]"},
      {"chop high", [](OceanParams& p) { p.choppiness = 6; }, "ocean.choppiness: 6 must be in [0, 5]"},
      {"loop", [](OceanParams& p) { p.loop_period_s = -2; }, "ocean.loop_period_s: -2 must be >= 0"},
      {"decay", [](OceanParams& p) { p.foam.decay_per_s = -1; }, "ocean.foam.decay_per_s: -1 must be >= 0"},
      {"threshold", [&](OceanParams& p) { p.foam.threshold = nan; }, "ocean.foam.threshold"},
      {"resolution 300", [](OceanParams& p) { p.cascades[1].resolution = 300; },
       "ocean.cascades[1].resolution: 300 is not a power of two between 64 and 1024"},
      {"resolution 32", [](OceanParams& p) { p.cascades[0].resolution = 32; },
       "ocean.cascades[0].resolution: 32"},
      {"resolution 2048", [](OceanParams& p) { p.cascades[2].resolution = 2048; },
       "ocean.cascades[2].resolution: 2048"},
      {"no cascades", [](OceanParams& p) { p.cascades.clear(); },
       "ocean.cascades: 0 cascades given; use 1 to 4"},
      {"five cascades",
       [](OceanParams& p) {
         p.cascades = {{5000, 256}, {1000, 256}, {200, 256}, {40, 256}, {8, 256}};
       },
       "ocean.cascades: 5 cascades given; use 1 to 4"},
      {"patch 0", [](OceanParams& p) { p.cascades[2].patch_size_m = 0; },
       "ocean.cascades[2].patch_size_m: 0 must be > 0"},
      {"not decreasing", [](OceanParams& p) { p.cascades[2].patch_size_m = 100; },
       "ocean.cascades[2].patch_size_m: 100 m must be smaller than cascades[1].patch_size_m"},
      // Cascade 0 (1000 m, 256) ends its band at k = π 256/2000 = 0.402 rad/m; a 10 m cascade's longest wave
      // has k = 0.628 rad/m, leaving a gap. It needs at least 2π/0.402 = 15.625 m.
      {"gap",
       [](OceanParams& p) {
         p.cascades = {{1000, 256}, {10, 256}};
       },
       "ocean.cascades[1].patch_size_m: 10 m is too small"},
      {"gap size",
       [](OceanParams& p) {
         p.cascades = {{1000, 256}, {10, 256}};
       },
       "use at least 15.625 m"},
      // 1000 m at 1024 ends at 1.608 rad/m; 900 m at 64 would end at 0.112: empty. The largest size is
      // 64·1000/1024 = 62.5 m.
      {"empty band",
       [](OceanParams& p) {
         p.cascades = {{1000, 1024}, {900, 64}};
       },
       "ocean.cascades[1].patch_size_m: 900 m leaves this cascade no waves"},
      {"empty band size",
       [](OceanParams& p) {
         p.cascades = {{1000, 1024}, {900, 64}};
       },
       "below 62.5 m"},
  };
  for (const BadCase& c : cases) {
    OceanParams p;
    c.change(p);
    const Result<void> r = validate(p);
    ASSERT_FALSE(r.ok()) << c.what;
    EXPECT_NE(r.error().message.find(c.expected), std::string::npos)
        << c.what << ": expected \"" << c.expected << "\" in \"" << r.error().message << "\"";
    EXPECT_EQ(r.error().message.rfind("ocean.", 0), 0u) << c.what;
  }
}

TEST(OceanValidate, ReportsEveryProblemOnItsOwnLine) {
  OceanParams p;
  p.depth_m = 0;
  p.spectrum.gamma = 50;
  p.cascades[1].resolution = 100;
  const Result<void> r = validate(p);
  ASSERT_FALSE(r.ok());
  const std::string& m = r.error().message;
  EXPECT_NE(m.find("ocean.depth_m"), std::string::npos);
  EXPECT_NE(m.find("\nocean.spectrum.gamma"), std::string::npos);
  EXPECT_NE(m.find("\nocean.cascades[1].resolution"), std::string::npos);
}

TEST(OceanValidate, EdgeValuesAreAccepted) {
  OceanParams p;
  p.spectrum.gamma = 1.0;
  p.spectrum.swell = 1.0;
  p.choppiness = 0.0;
  p.loop_period_s = 0.0;
  p.cascades = {{500.0, 64}};
  EXPECT_TRUE(validate(p).ok());
  // Just above the gap limit L1 = 4 L0/N0 = 15.625 m.
  p.cascades = {{1000.0, 256}, {15.63, 256}};
  EXPECT_TRUE(validate(p).ok()) << validate(p).error().message;
}

}  // namespace
}  // namespace lagoon::ocean
