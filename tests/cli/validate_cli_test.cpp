// lagoon validate (issue 33): the quick conformance run writes its report (table, report.md, report.json, a
// plot per law), the laws hold except those the report documents as open findings, and every law fails on
// the deliberately broken variant named for it: the laws can tell a broken Lagoon from a working one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

// Laws Lagoon does not meet yet in the quick run, each a finding of the report (docs/validation.md, "Open
// findings"): they are measured and reported, and must be taken off this list when fixed. bodies.sphere-rao
// holds at the resonance the quick run measures (its finding is at 3-4 s, in the full run only).
const std::set<std::string> kOpenFindings{"light.secchi", "foam.streaks"};

std::map<std::string, bool> verdicts(const fs::path& report) {
  const nlohmann::json j = nlohmann::json::parse(read_file(report));
  std::map<std::string, bool> out;
  for (const auto& law : j.at("laws")) out[law.at("id").get<std::string>()] = law.at("holds").get<bool>();
  return out;
}

TEST(ValidateCli, TheQuickRunWritesTheReportAndTheLawsHold) {
  TempDir dir("lagoon_validate");
  const fs::path out = dir.path() / "report";
  auto r = lagoon("validate --quick --out " + out.string());
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
  ASSERT_TRUE(fs::exists(out / "report.md")) << r.output;
  const auto laws = verdicts(out / "report.json");
  EXPECT_GE(laws.size(), 28u);
  bool all = true;
  for (const auto& [id, holds] : laws) {
    all = all && holds;
    EXPECT_TRUE(fs::exists(out / (std::string(id).replace(id.find('.'), 1, "-") + ".png"))) << id;
    if (!kOpenFindings.count(id)) {
      EXPECT_TRUE(holds) << id << "\n" << r.output;
    }
    EXPECT_NE(r.output.find(id), std::string::npos) << "the table names every law: " << id;
  }
  EXPECT_EQ(r.exit_code, all ? 0 : 1) << r.output;
  if (!all) {
    EXPECT_NE(r.output.find("FAIL"), std::string::npos) << r.output;
  }
}

// Each variant with the laws it must break (cmd_validate.cpp lists them for --help); one test per variant,
// so that ctest spreads them over its jobs.
struct BrokenVariant {
  std::string name;
  std::vector<std::string> must_fail;
};

void PrintTo(const BrokenVariant& v, std::ostream* os) {
  *os << v.name;
}

class ValidateBroken : public ::testing::TestWithParam<BrokenVariant> {};

TEST_P(ValidateBroken, EveryLawFailsOnItsBrokenVariant) {
  const BrokenVariant& v = GetParam();
  TempDir dir("lagoon_validate_broken");
  std::string only;
  for (const std::string& id : v.must_fail) only += " --only " + id;
  auto r = lagoon("validate --quick --broken " + v.name + only + " --out " + (dir.path() / "r").string());
  EXPECT_EQ(r.exit_code, 1) << v.name << "\n" << r.output;
  const auto laws = verdicts(dir.path() / "r" / "report.json");
  for (const std::string& id : v.must_fail) {
    ASSERT_TRUE(laws.count(id)) << v.name << ": " << id;
    EXPECT_FALSE(laws.at(id)) << v.name << " must break " << id;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Variants, ValidateBroken,
    ::testing::Values(
        BrokenVariant{"uncapped-fetch", {"sea-state.pm-hs", "sea-state.fetch-cap"}},
        BrokenVariant{"deep-tma", {"sea-state.tma-depth"}},
        BrokenVariant{"regular-sea", {"sea-state.rayleigh"}},
        BrokenVariant{"vertex-buoyancy", {"bodies.box-heave", "bodies.tessellation"}},
        BrokenVariant{"no-floor", {"bodies.floor"}}, BrokenVariant{"no-refraction", {"light.snell-window"}},
        BrokenVariant{"seed-kd", {"light.kd-jerlov"}},
        BrokenVariant{"sharp-caustics", {"light.caustics-contrast"}},
        BrokenVariant{"resolved-slopes", {"slopes.cox-munk-upwind", "slopes.cox-munk-crosswind"}},
        BrokenVariant{"scale",
                      {"sea-state.pm-hs",
                       "sea-state.pm-tp",
                       "sea-state.jonswap-hs",
                       "sea-state.tma-depth",
                       "bodies.archimedes",
                       "bodies.box-heave",
                       "bodies.tessellation",
                       "bodies.floor",
                       "light.snell-window",
                       "light.kd-jerlov",
                       "sea-state.fetch-cap",
                       "sea-state.rayleigh",
                       "light.caustics-mean-above",
                       "light.caustics-mean-below",
                       "light.caustics-contrast",
                       "wakes.narrowing",
                       "bodies.sphere-stiffness",
                       "bodies.sphere-rao",
                       "shore.wavelength",
                       "shore.snell",
                       "shore.shoaling",
                       "shore.breaking-onset",
                       "shore.lattice-wavelength",
                       "shore.lattice-snell",
                       "shore.lattice-shoaling"}},
        BrokenVariant{"seed-foam", {"foam.whitecap-coverage"}},
        BrokenVariant{"fleeting-foam", {"foam.lifetime"}},
        BrokenVariant{"no-radiation", {"bodies.sphere-decay"}},
        BrokenVariant{"quasi-static", {"bodies.sphere-rao"}},
        BrokenVariant{"shallow-wakes", {"wakes.kelvin-angle", "wakes.transverse-wavelength"}},
        BrokenVariant{"no-shoaling",
                      {"shore.wavelength", "shore.snell", "shore.shoaling", "shore.breaking-onset",
                       "shore.lattice-wavelength", "shore.lattice-snell", "shore.lattice-shoaling"}}),
    [](const ::testing::TestParamInfo<BrokenVariant>& info) {
      std::string name = info.param.name;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

TEST(ValidateCli, UnknownVariantsAndLawsAreUsageErrors) {
  TempDir dir("lagoon_validate_usage");
  EXPECT_EQ(lagoon("validate --broken nonsense --out " + dir.path().string()).exit_code, 2);
  EXPECT_EQ(lagoon("validate --only no-such-law --out " + (dir.path() / "x").string()).exit_code, 2);
}

}  // namespace
}  // namespace lagoon::test
