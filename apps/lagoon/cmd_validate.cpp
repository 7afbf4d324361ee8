// lagoon validate: the conformance report (issue 33, docs/validation.md). Every law runs on the chosen
// device where it has a GPU side; the table goes to stdout, report.md, report.json and the plots to --out.
#include <chrono>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "gpu_session.h"
#include "io/staged_output.h"
#include "validate_bodies.h"
#include "validate_foam.h"
#include "validate_light.h"
#include "validate_report.h"
#include "validate_sea.h"
#include "validate_shore.h"
#include "validate_wakes.h"

namespace lagoon::cli {
namespace {

// The broken variants --broken accepts, each with the laws it must make fail (docs/validation.md).
const std::vector<std::pair<std::string, std::string>>& broken_variants() {
  static const std::vector<std::pair<std::string, std::string>> variants{
      {"scale",
       "every measurement ×√2 (heights, slopes, draughts, angles...): every law but "
       "foam.whitecap-coverage and foam.lifetime (their bands are factors of 2 and 4)"},
      {"uncapped-fetch", "JONSWAP's fetch laws beyond full development: sea-state.pm-*, sea-state.fetch-cap"},
      {"deep-tma", "TMA without its depth factor: sea-state.tma-depth"},
      {"regular-sea", "one wave instead of the spectrum: sea-state.rayleigh"},
      {"seed-foam", "foam by the seed's threshold rule instead of the coverage rule: foam.whitecap-coverage"},
      {"fleeting-foam", "foam that fades within a step (decay 30/s): foam.lifetime"},
      {"resolved-slopes", "the glint's unresolved slopes left out: slopes.cox-munk-*"},
      {"vertex-buoyancy",
       "the water's height only at the hull's vertices: bodies.box-heave, bodies.tessellation"},
      {"no-floor", "no floor contact: bodies.floor"},
      {"no-refraction", "water of index 1: light.snell-window"},
      {"seed-kd", "the seed's diffuse path-length factor D = 1: light.kd-jerlov"},
      {"beam-secchi", "Secchi depth from the beam attenuation alone: light.secchi"},
      {"sharp-caustics",
       "caustics without the blur of the waves shorter than a cell and of the solar disc: "
       "light.caustics-contrast"},
      {"no-radiation", "the heave added mass and radiation damping left out: bodies.sphere-decay"},
      {"quasi-static",
       "the sphere feels the height above each point, not linear theory's pressure under the wave: "
       "bodies.sphere-rao"},
      {"no-shoaling",
       "waves that do not feel the floor: shore.wavelength, shore.snell, shore.shoaling, "
       "shore.breaking-onset, shore.lattice-wavelength, shore.lattice-snell, shore.lattice-shoaling"},
      {"shallow-wakes",
       "the wakes in water of depth Froude number 0.9 instead of deep water: wakes.kelvin-angle, "
       "wakes.transverse-wavelength"}};
  return variants;
}

int run_validate(const ParsedArgs& args) {
  ValidateOptions options{
      .quick = args.has("quick"), .broken = args.get("broken").value_or(""), .only = args.all("only")};
  if (!options.broken.empty()) {
    bool known = false;
    for (const auto& [name, what] : broken_variants()) known = known || name == options.broken;
    if (!known) {
      std::fprintf(stderr, "lagoon validate: --broken %s is not a variant; see lagoon validate --help\n",
                   options.broken.c_str());
      return kExitUsage;
    }
  }
  const std::string out_dir = args.get("out").value_or("validation");
  auto staged = io::StagedOutput::create(out_dir);
  if (!staged) {
    std::fprintf(stderr, "lagoon validate: --out %s: %s\n", out_dir.c_str(), staged.error().message.c_str());
    return kExitFailure;
  }
  std::unique_ptr<vk::Context> ctx = open_context();
  if (!ctx) return kExitFailure;
  const auto start = std::chrono::steady_clock::now();
  std::vector<Law> laws;
  auto add = [&](std::vector<Law> more) {
    for (Law& law : more)
      if (options.wants(law.id)) laws.push_back(std::move(law));
  };
  add(sea_state_laws(*ctx, options));
  add(body_laws(options));
  add(light_laws(*ctx, options));
  add(wake_laws(options));
  add(shore_laws(options));
  add(foam_laws(*ctx, options));
  if (laws.empty()) {
    std::fprintf(stderr,
                 "lagoon validate: --only matches no law (the ids are listed in docs/validation.md)\n");
    return kExitUsage;
  }
  if (int status = validation_status(*ctx); status != kExitOk) return status;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_table(laws);
  const ReportContext context{ctx->device_info().name, options.quick ? "quick" : "full", options.broken,
                              seconds};
  if (auto r = write_report(*staged, laws, context); !r) {
    std::fprintf(stderr, "lagoon validate: %s\n", r.error().message.c_str());
    return kExitFailure;
  }
  if (auto r = staged->commit(); !r) {
    std::fprintf(stderr, "lagoon validate: %s\n", r.error().message.c_str());
    return kExitFailure;
  }
  std::vector<std::string> failed;
  for (const Law& law : laws)
    if (!law.holds()) failed.push_back(law.id);
  std::printf("report: %s/report.md (%.0f s)\n", out_dir.c_str(), seconds);
  if (failed.empty()) {
    std::printf("every law holds (%zu)\n", laws.size());
    return kExitOk;
  }
  std::string names;
  for (const std::string& f : failed) names += (names.empty() ? "" : ", ") + f;
  std::printf("%zu of %zu laws FAIL: %s\n", failed.size(), laws.size(), names.c_str());
  return kExitFailure;
}

std::string variants_help() {
  std::string text = "Broken variants (--broken), each a deliberate bug the named laws must catch:\n";
  for (const auto& [name, what] : broken_variants()) text += "  " + name + ": " + what + "\n";
  return text;
}

}  // namespace

const Command& validate_command() {
  static const Command command{
      .spec = {.name = "validate",
               .summary = "Conformance report: Lagoon's sea, bodies and light against published laws "
                          "(Pierson-Moskowitz, JONSWAP, TMA, Rayleigh, Cox-Munk, Archimedes, Froude-Krylov, "
                          "Snell, Jerlov, Secchi), with a plot per law.",
               .options = {{"quick", "", "the short ranges (a few minutes on lavapipe; what make test runs)"},
                           {"out", "DIR",
                            "where report.md, report.json and the plots go (default validation)"},
                           {"only", "PREFIX", "only the laws whose id starts with PREFIX (repeatable)", false,
                            true},
                           {"broken", "VARIANT", "run against a deliberately broken variant (below)"}},
               .details = "Exit 0 when every law holds, 1 when one does not (the failing ones are named).\n"
                          "docs/validation.md gives each law's source, conditions and measurement.\n" +
                          variants_help() + "example:\n  lagoon validate --quick --out /tmp/validation\n"},
      .run = run_validate};
  return command;
}

}  // namespace lagoon::cli
