// lagoon lut end to end: the files, the explanation, and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/npy.h"
#include "io/png.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

TEST(LutCli, WritesTablesMetadataAndPreviews) {
  TempDir dir;
  const fs::path out = dir / "lut";
  auto r =
      lagoon("lut --water jerlov-IA --out " + out.string() + " --sun-elevation 50 --set water.lut_size=32");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto t0 = io::read_npy(out / "T0.npy");
  auto t1 = io::read_npy(out / "T1.npy");
  ASSERT_TRUE(t0 && t1);
  EXPECT_EQ(t0->shape, (std::vector<size_t>{32, 32, 4}));
  EXPECT_EQ(t1->shape, (std::vector<size_t>{32, 32, 3}));
  std::ifstream meta_file(out / "lut.json");
  const auto meta = nlohmann::json::parse(meta_file);
  EXPECT_EQ(meta["r_m"].size(), 32u);
  EXPECT_EQ(meta["h_m"].size(), 32u);
  EXPECT_EQ(meta["parameters"]["water_type"], "jerlov-IA");
  EXPECT_EQ(meta["parameters"]["sun_elevation_deg"], 50.0);
  EXPECT_TRUE(meta.contains("axes") && meta.contains("previews") && meta.contains("deep_colour_rgb"));
  // The underwater tables: a white target fades with distance, the water's own light grows with it.
  auto target = io::read_npy(out / "underwater_target.npy");
  auto down = io::read_npy(out / "underwater_water_down.npy");
  ASSERT_TRUE(target && down);
  ASSERT_EQ(target->shape.size(), 3u);
  const size_t d = target->shape[0], z = target->shape[1];
  EXPECT_EQ(target->shape[2], 4u);
  EXPECT_EQ(down->shape, (std::vector<size_t>{d, z, 3}));
  EXPECT_EQ(meta["underwater"]["d_m"].size(), d);
  const size_t green_near = (0 * z + 8) * 4 + 1, green_far = ((d / 2) * z + 8) * 4 + 1;
  EXPECT_GT(target->data[green_near], 2 * target->data[green_far]);
  EXPECT_LT(down->data[(0 * z + 8) * 3 + 2], down->data[((d / 2) * z + 8) * 3 + 2]);
  for (const char* png : {"T0.png", "T1.png", "underwater.png"}) {
    auto image = io::read_png(out / png);
    ASSERT_TRUE(image) << png;
    EXPECT_GE(image->width, 32u);
  }
}

// Eq. 10 through the CLI: the tables are built for the scene's sea. Stronger wind, steeper slopes: more
// upwelling light escapes through tilted facets (rw_ff falls from the flat 0.4746) and less sky is reflected
// at the sun's angle; the coefficients written in lut.json follow the wind, and the tables with them.
TEST(LutCli, TheSurfaceFollowsTheWind) {
  TempDir dir;
  auto surface = [&](const std::string& name, double wind) {
    const fs::path out = dir / name;
    auto r = lagoon("lut --water jerlov-IA --out " + out.string() +
                    " --sun-elevation 10 --set water.lut_size=16 --set ocean.spectrum.wind_speed_mps=" +
                    std::to_string(wind));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(out / "lut.json");
    return nlohmann::json::parse(in)["parameters"]["surface"];
  };
  const nlohmann::json calm = surface("calm", 1), gale = surface("gale", 25);
  EXPECT_TRUE(calm["wavy"].get<bool>());
  EXPECT_NEAR(calm["rw_ff"].get<double>(), 0.4746, 0.002);  // a 1 m/s sea is nearly a mirror
  EXPECT_LT(gale["rw_ff"].get<double>(), calm["rw_ff"].get<double>() - 0.005);
  EXPECT_LT(gale["r_dd"].get<double>(), calm["r_dd"].get<double>() - 0.01);  // the sun at 80° from zenith
}

// --kd-plot draws the model's K_d against Jerlov's (10 panels) and refuses a file that is not a PNG.
TEST(LutCli, KdPlotDrawsEveryType) {
  TempDir dir;
  const fs::path out = dir / "kd.png";
  auto r = lagoon("lut --kd-plot " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto image = io::read_png(out);
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(image->width, 1500u);
  EXPECT_EQ(image->height, 440u);
  r = lagoon("lut --kd-plot " + (dir / "kd.jpg").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("must name a .png file"), std::string::npos) << r.output;
}

// --error-map: the composites of eqs. 21, 22, 24 against eq. 20 over the measured bottoms and a grey one,
// both Φ, as two PNG sheets and a summary; over the grey bottom eq. 22 with signed tables is eq. 20 exactly.
TEST(LutCli, ErrorMapMeasuresTheCompositesAgainstEq20) {
  TempDir dir;
  const fs::path out = dir / "errors";
  auto r = lagoon("lut --error-map " + out.string() + " --water jerlov-IB --set water.lut_size=16");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* png : {"error_maps_linear.png", "error_maps_seed.png"}) {
    const auto image = io::read_png(out / png);
    ASSERT_TRUE(image) << png;
    EXPECT_GT(image->width, 300u);
  }
  std::ifstream meta_file(out / "error.json");
  const auto meta = nlohmann::json::parse(meta_file);
  EXPECT_EQ(meta["bottoms"].size(), 6u);
  size_t rows = 0;
  for (const auto& row : meta["summary"]) {
    ++rows;
    const bool grey_signed = row["bottom"] == "grey 0.3" && row["phi"] == "linear" &&
                             row["equation"] == "eq22" && row["tables"] == "signed";
    if (grey_signed) {
      EXPECT_LT(row["max"].get<double>(), 1e-6);
    }
    if (row["bottom"] == "coralline_algae" && row["equation"] == "eq24") {
      EXPECT_GT(row["max"].get<double>(), 0.5);
    }
  }
  EXPECT_EQ(rows, 6u * (4 + 3));  // linear: eq21, eq22, eq22 signed, eq24; seed: eq21, eq22, eq24
  std::ifstream csv(out / "error_summary.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "phi,bottom,equation,tables,mean_de2000,p95_de2000,max_de2000,share_above_2");
  EXPECT_TRUE(fs::exists(out / "error_summary.md"));
}

TEST(LutCli, ExplainPrintsEveryQuantityPerWavelength) {
  auto r = lagoon("lut --water jerlov-II --explain 4,2.5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j["spectral"].size(), 81u);
  const auto& w = j["spectral"][20];  // 480 nm
  EXPECT_EQ(w["wavelength_nm"], 480.0);
  for (const char* key :
       {"chi", "sigma", "X1", "k", "S", "S1", "S2", "E_sun", "E_sky", "surface_coefficients",
        "bottom_coefficients", "flows_at_surface", "flows_at_bottom", "alpha_l", "l_m"})
    EXPECT_TRUE(w.contains(key)) << key;
  for (const char* key : {"t_dd", "r_dd", "t_df", "r_df", "t_ff", "r_ff", "rw_dd", "rw_df", "rw_ff", "tw_ff"})
    EXPECT_TRUE(w["surface_coefficients"].contains(key)) << key;
  EXPECT_NEAR(j["l_m"].get<double>(), std::hypot(4.0, 2.5), 1e-12);
  EXPECT_EQ(j["T0_rgb"].size(), 3u);
  EXPECT_TRUE(j.contains("a") && j.contains("T1_rgb"));
}

TEST(LutCli, BadInputIsNamed) {
  TempDir dir;
  const std::string out = (dir / "lut").string();
  auto unknown = lagoon("lut --water jerlov-IV --out " + out);
  EXPECT_EQ(unknown.exit_code, 1) << unknown.output;
  EXPECT_NE(unknown.output.find("water.type"), std::string::npos) << unknown.output;
  EXPECT_NE(unknown.output.find("jerlov-IB"), std::string::npos) << unknown.output;
  auto albedo = lagoon("lut --water jerlov-I --out " + out + " --set water.bottom_albedo=2");
  EXPECT_EQ(albedo.exit_code, 1) << albedo.output;
  EXPECT_NE(albedo.output.find("water.bottom_albedo"), std::string::npos) << albedo.output;
  auto custom = lagoon("lut --set water.type=custom --out " + out);
  EXPECT_EQ(custom.exit_code, 1) << custom.output;
  EXPECT_NE(custom.output.find("water.table"), std::string::npos) << custom.output;
  auto missing_table =
      lagoon("lut --set water.type=custom --set water.table=/nonexistent/iops.csv --out " + out);
  EXPECT_EQ(missing_table.exit_code, 1) << missing_table.output;
  EXPECT_NE(missing_table.output.find("/nonexistent/iops.csv"), std::string::npos) << missing_table.output;
  EXPECT_EQ(lagoon("lut --water jerlov-I --explain 3").exit_code, 2);
  EXPECT_EQ(lagoon("lut --water jerlov-I").exit_code, 2);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace lagoon::test
