// The optics reference data: the strict CSV reader, the CIE tables and the water IOPs (Jerlov types and
// user tables).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "optics/cie.h"
#include "optics/csv_table.h"
#include "optics/water_types.h"

namespace lagoon::optics {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Writes `text` to a file in the test's temporary folder and returns its path.
std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / ("lagoon_optics_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(OpticsCsv, ReadsColumnsByName) {
  auto t = CsvTable::parse(
      "\xEF\xBB\xBFwavelength_nm, \"a\" ,note\r\n400,0.5,x\r\n\r\n410,+1e-2,\"y, z\"\r\n", "t.csv");
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ(t->rows(), 2u);
  EXPECT_EQ(t->line(1), 4);
  auto a = t->numbers("a");
  ASSERT_TRUE(a.ok()) << a.error().message;
  EXPECT_EQ(*a, (std::vector<double>{0.5, 0.01}));
  auto notes = t->texts("note");
  ASSERT_TRUE(notes.ok());
  EXPECT_EQ((*notes)[1], "y, z");
}

TEST(OpticsCsv, ErrorsNameTableLineAndColumn) {
  auto t = CsvTable::parse("wavelength_nm,a\n400,0.5\n410,abc\n420,nan\n430,\n", "t.csv");
  ASSERT_TRUE(t.ok());
  auto a = t->numbers("a");
  ASSERT_FALSE(a.ok());
  EXPECT_TRUE(contains(a.error().message, "t.csv line 3, column 'a'")) << a.error().message;
  auto gaps = t->numbers_or_empty("wavelength_nm");
  ASSERT_TRUE(gaps.ok());
  auto missing = t->numbers("b");
  ASSERT_FALSE(missing.ok());
  EXPECT_TRUE(contains(missing.error().message, "t.csv: no column 'b'")) << missing.error().message;

  auto nan = CsvTable::parse("a\n1\nnan\n", "n.csv")->numbers("a");
  ASSERT_FALSE(nan.ok());
  EXPECT_TRUE(contains(nan.error().message, "n.csv line 3, column 'a'")) << nan.error().message;
  auto empty = CsvTable::parse("a,b\n1,\n", "e.csv")->numbers("b");
  ASSERT_FALSE(empty.ok());
  EXPECT_TRUE(contains(empty.error().message, "e.csv line 2")) << empty.error().message;
  auto with_gap = CsvTable::parse("a,b\n1,\n", "e.csv")->numbers_or_empty("b");
  ASSERT_TRUE(with_gap.ok());
  EXPECT_FALSE((*with_gap)[0].has_value());

  auto ragged = CsvTable::parse("a,b\n1,2\n3\n", "r.csv");
  ASSERT_FALSE(ragged.ok());
  EXPECT_TRUE(contains(ragged.error().message, "r.csv line 3")) << ragged.error().message;
  EXPECT_FALSE(CsvTable::parse("a,a\n1,2\n", "d.csv").ok());
  EXPECT_FALSE(CsvTable::parse("", "empty.csv").ok());
  EXPECT_FALSE(CsvTable::parse("a\n\"1\n", "q.csv").ok());
}

TEST(OpticsCsv, FreeTextLastColumnKeepsCommas) {
  const std::string text = "row,c_X,source\nR,1.5,white (0.3127,0.3290)\n";
  EXPECT_FALSE(CsvTable::parse(text, "s.csv").ok());
  auto t = CsvTable::parse(text, "s.csv", {.last_column_free_text = true});
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ((*t->texts("source"))[0], "white (0.3127,0.3290)");
}

TEST(OpticsCsv, EmbeddedTablesLoad) {
  for (const char* name :
       {"cie1931_2deg_cmf_5nm.csv", "cie_d65_5nm.csv", "astm_g173_380_780.csv",
        "pure_water_absorption_scattering_5nm.csv", "jerlov_sm2015_a.csv", "jerlov_sm2015_b.csv",
        "jerlov_sm2015_gapfill_williamson2022.csv", "von_kries_xyz_to_lms.csv"}) {
    auto t = CsvTable::embedded(name);
    EXPECT_TRUE(t.ok()) << name << ": " << t.error().message;
  }
  auto missing = CsvTable::embedded("no_such_table.csv");
  ASSERT_FALSE(missing.ok());
  EXPECT_TRUE(contains(missing.error().message, "no_such_table.csv"));
}

TEST(OpticsCie, D65ChromaticityThroughTheCmfs) {
  const glm::dvec2 xy = chromaticity(spectrum_to_xyz(cie_d65()));
  EXPECT_NEAR(xy.x, 0.3127, 2e-4);
  EXPECT_NEAR(xy.y, 0.3290, 2e-4);
  EXPECT_DOUBLE_EQ(cie_y_bar()[sample_index(555)], 1.0);
  EXPECT_DOUBLE_EQ(cie_x_bar()[sample_index(600)], 1.0622);
  EXPECT_DOUBLE_EQ(cie_d65()[sample_index(560)], 100.0);
  EXPECT_EQ(chromaticity(glm::dvec3(0.0)), glm::dvec2(0.0));
}

TEST(OpticsCie, XyzIsTheFiveNanometreSum) {
  Spectrum flat;
  flat.fill(1.0);
  const glm::dvec3 xyz = spectrum_to_xyz(flat);
  double y = 0.0;
  for (double v : cie_y_bar()) y += v;
  EXPECT_NEAR(xyz.y, 5.0 * y, 1e-9);
  // The three CMFs have (nearly) equal integrals: illuminant E is at x = y = 1/3.
  EXPECT_NEAR(chromaticity(xyz).x, 1.0 / 3.0, 1e-3);
  EXPECT_NEAR(chromaticity(xyz).y, 1.0 / 3.0, 1e-3);
}

TEST(OpticsWater, JerlovSpotValuesMatchTheTables) {
  auto one = water_type("jerlov-I");
  ASSERT_TRUE(one.ok()) << one.error().message;
  EXPECT_EQ(one->name, "jerlov-I");
  EXPECT_DOUBLE_EQ(one->absorption_per_m[sample_index(400)], 0.022);   // jerlov_sm2015_a.csv, 400 nm
  EXPECT_DOUBLE_EQ(one->scattering_per_m[sample_index(400)], 0.0062);  // jerlov_sm2015_b.csv, 400 nm
  // 380 nm lies between the 375 and 400 nm rows: linear interpolation.
  EXPECT_NEAR(one->absorption_per_m[sample_index(380)], 0.03 + (0.022 - 0.03) * 5.0 / 25.0, 1e-12);
  EXPECT_NEAR(one->absorption_per_m[sample_index(410)], 0.022 + (0.017 - 0.022) * 10.0 / 25.0, 1e-12);

  auto three_c = water_type("jerlov-3C");
  ASSERT_TRUE(three_c.ok());
  EXPECT_DOUBLE_EQ(three_c->absorption_per_m[sample_index(700)], 0.592);  // Williamson & Hollins gap fill
  EXPECT_DOUBLE_EQ(three_c->scattering_per_m[sample_index(675)], 0.745);
  auto five_c = water_type("jerlov-5C");
  ASSERT_TRUE(five_c.ok());
  EXPECT_DOUBLE_EQ(five_c->scattering_per_m[sample_index(600)], 1.147);
  EXPECT_DOUBLE_EQ(five_c->absorption_per_m[sample_index(650)], 0.367);
  EXPECT_DOUBLE_EQ(five_c->absorption_per_m[sample_index(575)], 0.119);  // a published cell, not a fill
}

TEST(OpticsWater, EveryTypeIsPositiveAndFiniteOnTheGrid) {
  ASSERT_EQ(water_type_names().size(), 10u);
  const Spectrum& a_w = pure_water_absorption();
  EXPECT_DOUBLE_EQ(a_w[sample_index(750)], 2.8484);  // Kou et al. (1993) via the pure-water table
  for (const std::string& name : water_type_names()) {
    auto w = water_type(name);
    ASSERT_TRUE(w.ok()) << w.error().message;
    EXPECT_EQ(w->name, name);
    for (int i = 0; i < kSamples; ++i) {
      EXPECT_TRUE(std::isfinite(w->absorption_per_m[i]) && w->absorption_per_m[i] > 0.0) << name << " " << i;
      EXPECT_TRUE(std::isfinite(w->scattering_per_m[i]) && w->scattering_per_m[i] > 0.0) << name << " " << i;
    }
    for (int nm = 705; nm <= kLambdaMaxNm; nm += 5) {
      EXPECT_GE(w->absorption_per_m[sample_index(nm)], a_w[sample_index(nm)]) << name << " " << nm;
      EXPECT_GE(w->scattering_per_m[sample_index(nm)], pure_seawater_scattering()[sample_index(nm)])
          << name << " " << nm;
    }
  }
}

TEST(OpticsWater, ExtensionBeyond700nm) {
  const Spectrum& a_w = pure_water_absorption();
  const Spectrum& b_sw = pure_seawater_scattering();
  auto nine_c = water_type("jerlov-9C");
  ASSERT_TRUE(nine_c.ok());
  // a(700) = 0.651 > a_w(700) = 0.624: the non-water part decays with the CDOM slope 0.014 nm⁻¹.
  EXPECT_NEAR(nine_c->absorption_per_m[sample_index(750)],
              a_w[sample_index(750)] + (0.651 - 0.624) * std::exp(-0.7), 1e-12);
  EXPECT_NEAR(nine_c->scattering_per_m[sample_index(780)],
              b_sw[sample_index(780)] + (2.07 - b_sw[sample_index(700)]) * 700.0 / 780.0, 1e-12);
  // Type I: a(700) = 0.582 is below a_w(700), so beyond 700 nm it is pure water.
  auto one = water_type("jerlov-I");
  ASSERT_TRUE(one.ok());
  EXPECT_DOUBLE_EQ(one->absorption_per_m[sample_index(705)], a_w[sample_index(705)]);
  EXPECT_DOUBLE_EQ(one->scattering_per_m[sample_index(705)], b_sw[sample_index(705)]);
}

TEST(OpticsWater, TurbidWaterAbsorbsMoreInTheBlue) {
  auto one = water_type("jerlov-I");
  auto nine_c = water_type("jerlov-9C");
  ASSERT_TRUE(one.ok() && nine_c.ok());
  EXPECT_GT(nine_c->absorption_per_m[sample_index(450)], 10.0 * one->absorption_per_m[sample_index(450)]);
  EXPECT_GT(nine_c->scattering_per_m[sample_index(450)], one->scattering_per_m[sample_index(450)]);
}

TEST(OpticsWater, UnknownTypeListsNamesAndSuggests) {
  auto w = water_type("jerlov-1b");
  ASSERT_FALSE(w.ok());
  const std::string& message = w.error().message;
  EXPECT_TRUE(contains(message, "'jerlov-1b'")) << message;
  EXPECT_TRUE(contains(message, "did you mean 'jerlov-IB'")) << message;
  for (const std::string& name : water_type_names()) EXPECT_TRUE(contains(message, name)) << name;
  auto c = water_type("jerlov-3c");
  ASSERT_FALSE(c.ok());
  EXPECT_TRUE(contains(c.error().message, "did you mean 'jerlov-3C'")) << c.error().message;
}

TEST(OpticsWater, LoadsAUserTable) {
  std::string text = "wavelength_nm,absorption_per_m,scattering_per_m,comment\n";
  for (int nm = 370; nm <= 790; nm += 10)
    text += std::to_string(nm) + "," + std::to_string(0.01 + 0.001 * (nm - 370)) + ",0.5,x\n";
  const auto path = write_temp("user_water.csv", text);
  auto w = load_water_table(path);
  ASSERT_TRUE(w.ok()) << w.error().message;
  EXPECT_EQ(w->name, "lagoon_optics_user_water");
  for (int i = 0; i < kSamples; ++i) {
    EXPECT_NEAR(w->absorption_per_m[i], 0.01 + 0.001 * (wavelength_nm(i) - 370), 1e-12);
    EXPECT_DOUBLE_EQ(w->scattering_per_m[i], 0.5);
  }
}

TEST(OpticsWater, UserTableErrorsNameTheFile) {
  const auto missing = std::filesystem::path(::testing::TempDir()) / "lagoon_optics_no_such_water.csv";
  auto a = load_water_table(missing);
  ASSERT_FALSE(a.ok());
  EXPECT_TRUE(contains(a.error().message, missing.string())) << a.error().message;

  const auto no_column = write_temp("no_column.csv", "wavelength_nm,absorption_per_m\n380,0.1\n780,2\n");
  auto b = load_water_table(no_column);
  ASSERT_FALSE(b.ok());
  EXPECT_TRUE(contains(b.error().message, no_column.string())) << b.error().message;
  EXPECT_TRUE(contains(b.error().message, "scattering_per_m")) << b.error().message;

  const auto short_blue = write_temp("short_blue.csv",
                                     "wavelength_nm,absorption_per_m,scattering_per_m\n"
                                     "400,0.1,0.1\n780,2,0.1\n");
  auto c = load_water_table(short_blue);
  ASSERT_FALSE(c.ok());
  EXPECT_TRUE(contains(c.error().message, short_blue.string())) << c.error().message;
  EXPECT_TRUE(contains(c.error().message, "missing 380-400 nm")) << c.error().message;

  const auto short_red = write_temp("short_red.csv",
                                    "wavelength_nm,absorption_per_m,scattering_per_m\n"
                                    "380,0.1,0.1\n700,2,0.1\n");
  auto d = load_water_table(short_red);
  ASSERT_FALSE(d.ok());
  EXPECT_TRUE(contains(d.error().message, short_red.string())) << d.error().message;
  EXPECT_TRUE(contains(d.error().message, "missing 700-780 nm")) << d.error().message;
}

TEST(OpticsWater, UserTableBadValuesNameTheRow) {
  const std::string header = "wavelength_nm,absorption_per_m,scattering_per_m\n";
  const auto negative = write_temp("negative.csv", header + "380,0.1,0.1\n500,0.2,-0.1\n780,2,0.1\n");
  auto a = load_water_table(negative);
  ASSERT_FALSE(a.ok());
  EXPECT_TRUE(contains(a.error().message, negative.string() + " line 3, column 'scattering_per_m'"))
      << a.error().message;
  const auto not_finite = write_temp("not_finite.csv", header + "380,0.1,0.1\n500,inf,0.1\n780,2,0.1\n");
  auto b = load_water_table(not_finite);
  ASSERT_FALSE(b.ok());
  EXPECT_TRUE(contains(b.error().message, not_finite.string() + " line 3, column 'absorption_per_m'"))
      << b.error().message;
  const auto unsorted =
      write_temp("unsorted.csv", header + "380,0.1,0.1\n600,0.2,0.1\n500,0.2,0.1\n780,2,0.1\n");
  auto c = load_water_table(unsorted);
  ASSERT_FALSE(c.ok());
  EXPECT_TRUE(contains(c.error().message, unsorted.string() + " line 4")) << c.error().message;
}

}  // namespace
}  // namespace lagoon::optics
