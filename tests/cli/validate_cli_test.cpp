// lagoon validate (issue 33): the quick conformance run writes its report (table, report.md, report.json, a
// plot per law), the laws hold except those the report documents as open findings, and every law fails on
// the deliberately broken variant named for it: the laws can tell a broken Lagoon from a working one.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

namespace fs = std::filesystem;

// Laws Lagoon does not meet yet, each a finding of the report (docs/validation.md, "Open findings"): they
// are measured and reported, and must be taken off this list when fixed.
const std::set<std::string> kOpenFindings{"light.secchi", "light.caustics-contrast"};

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
  EXPECT_GE(laws.size(), 20u);
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

// Each variant with the laws it must break (cmd_validate.cpp lists them for --help).
TEST(ValidateCli, EveryLawFailsOnItsBrokenVariant) {
  const std::map<std::string, std::vector<std::string>> variants{
      {"uncapped-fetch", {"sea-state.pm-hs", "sea-state.fetch-cap"}},
      {"deep-tma", {"sea-state.tma-depth"}},
      {"regular-sea", {"sea-state.rayleigh"}},
      {"vertex-buoyancy", {"bodies.box-heave", "bodies.tessellation"}},
      {"no-floor", {"bodies.floor"}},
      {"no-refraction", {"light.snell-window"}},
      {"seed-kd", {"light.kd-jerlov"}},
      {"resolved-slopes", {"slopes.cox-munk-upwind", "slopes.cox-munk-crosswind"}},
      {"scale",
       {"sea-state.pm-hs", "sea-state.pm-tp", "sea-state.jonswap-hs", "sea-state.tma-depth",
        "bodies.archimedes", "bodies.box-heave", "bodies.tessellation", "bodies.floor", "light.snell-window",
        "light.kd-jerlov", "sea-state.fetch-cap", "sea-state.rayleigh", "light.caustics-mean-above",
        "light.caustics-mean-below"}},
      {"seed-foam", {"foam.whitecap-coverage"}}};
  for (const auto& [variant, must_fail] : variants) {
    TempDir dir("lagoon_validate_broken");
    std::string only;
    for (const std::string& id : must_fail) only += " --only " + id;
    auto r = lagoon("validate --quick --broken " + variant + only + " --out " + (dir.path() / "r").string());
    EXPECT_EQ(r.exit_code, 1) << variant << "\n" << r.output;
    const auto laws = verdicts(dir.path() / "r" / "report.json");
    for (const std::string& id : must_fail) {
      ASSERT_TRUE(laws.count(id)) << variant << ": " << id;
      EXPECT_FALSE(laws.at(id)) << variant << " must break " << id;
    }
  }
}

TEST(ValidateCli, UnknownVariantsAndLawsAreUsageErrors) {
  TempDir dir("lagoon_validate_usage");
  EXPECT_EQ(lagoon("validate --broken nonsense --out " + dir.path().string()).exit_code, 2);
  EXPECT_EQ(lagoon("validate --only no-such-law --out " + (dir.path() / "x").string()).exit_code, 2);
}

}  // namespace
}  // namespace lagoon::test
