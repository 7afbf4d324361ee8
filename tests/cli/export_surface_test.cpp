// lagoon export --surface: the sea over a window of the world, as the scene draws it over its floor (issue
// 37), where the cascades' tiles are the deep sea's. Its layout is checked against `lagoon probe` at the same
// points and times, and its physics against the floor: nothing on the dry beach, waves offshore.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/npy.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

const std::string kBeach = std::string(LAGOON_SOURCE_DIR) + "/scenes/beach.json";

// `lagoon probe`'s height at (x, z) and time t, NaN when it cannot be read.
double probe_height(double x, double z, double t) {
  std::ostringstream args;
  args << "probe --scene " << shell_quote(kBeach) << " --time " << t << " --at " << x << "," << z;
  const ProcessResult r = lagoon(args.str());
  if (r.exit_code != 0) return NAN;
  return nlohmann::json::parse(r.output.substr(0, r.output.find('\n')))["height_m"].get<double>();
}

TEST(ExportSurface, TheWindowIsTheSeaLagoonProbeAnswersOverTheBeachFloor) {
  TempDir dir;
  // The beach's floor slopes from 2 m above the water at z = 0 to 20 m deep at z = 400: the shore is at
  // z = 36.4 m. The window runs from the sand to 9 m of water, not square, so a transposed layout fails.
  const ProcessResult r =
      lagoon("export --scene " + shell_quote(kBeach) + " --out " + shell_quote((dir / "out").string()) +
             " --frames 2 --dt 0.5 --surface -20,0,20,200 --surface-spacing 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream meta_file(dir / "out" / "meta.json");
  const nlohmann::json meta = nlohmann::json::parse(meta_file);
  const nlohmann::json& surface = meta.at("surface");
  EXPECT_EQ(surface.at("columns"), 21);
  EXPECT_EQ(surface.at("rows"), 101);
  EXPECT_EQ(surface.at("origin_m"), nlohmann::json({-20.0, 0.0}));
  auto heights = io::read_npy(dir / "out" / "surface_height.npy");
  ASSERT_TRUE(heights) << heights.error().message;
  ASSERT_EQ(heights->shape, (std::vector<size_t>{2, 101, 21}));
  auto at = [&](int frame, int i, int j) {
    return double(heights->data[(size_t(frame) * 101 + j) * 21 + i]);
  };

  // Column i, row j is x = -20 + 2i, z = 2j, at times_s[frame] (4 and 4.5 s): probe agrees to float32's
  // rounding at corners, on the sand and offshore.
  const std::vector<double> times = meta.at("times_s");
  ASSERT_EQ(times, (std::vector<double>{4.0, 4.5}));
  for (auto [frame, i, j] :
       {std::tuple{0, 0, 0}, {0, 20, 100}, {1, 20, 100}, {1, 0, 100}, {0, 7, 60}, {1, 13, 25}})
    EXPECT_NEAR(at(frame, i, j), probe_height(-20 + 2 * i, 2 * j, times[size_t(frame)]), 1e-5)
        << "frame " << frame << ", x " << -20 + 2 * i << ", z " << 2 * j;

  // Over the floor: no sea on the sand (z < 34 m, 0.15 m above the water), waves where it is 3-9 m deep.
  auto row_rms = [&](int j) {
    double sum = 0;
    for (int i = 0; i < 21; ++i) sum += at(0, i, j) * at(0, i, j);
    return std::sqrt(sum / 21);
  };
  for (int j = 0; j < 17; ++j) EXPECT_EQ(row_rms(j), 0.0) << "waves on the sand at z = " << 2 * j;
  double offshore = 0;
  for (int j = 90; j <= 100; ++j) offshore = std::max(offshore, row_rms(j));
  EXPECT_GT(offshore, 0.1);
}

TEST(ExportSurface, ABadWindowIsRefusedWithTheFix) {
  TempDir dir;
  const std::string base =
      "export --scene " + shell_quote(kBeach) + " --out " + shell_quote((dir / "o").string());
  struct Case {
    std::string args, expected;
  };
  for (const Case& c : {Case{" --surface 1,2,3", "must be four numbers X0,Z0,X1,Z1"},
                        Case{" --surface 0,0,nan,1", "must be four numbers"},
                        Case{" --surface 0,0,0.5,0.5", "fewer than 2 samples a side"},
                        Case{" --surface 0,0,5000,10", "more than 2048 a side"},
                        Case{" --surface 0,0,10,10 --surface-spacing 0", "--surface-spacing 0 must be"},
                        Case{" --surface-spacing 2", "--surface-spacing needs --surface"}}) {
    const ProcessResult r = lagoon(base + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "o")) << c.args;
  }
}

}  // namespace
}  // namespace lagoon::test
