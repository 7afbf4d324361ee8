// lagoon compare: the surface models side by side (issue 15, docs/models.md). Every model is rendered with
// the scene's camera, time and light, its step timed on the device, and its height field measured
// (model_comparison.h); out come a labelled contact sheet, a table (Markdown and JSON) and each model's
// directional spectrum plot, all or nothing (io/staged_output.h).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "compare_sheet.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "io/staged_output.h"
#include "model_comparison.h"
#include "ocean/model_constraints.h"
#include "ocean/ocean_params.h"
#include "report_text.h"
#include "scene/json_fields.h"
#include "scene_args.h"

namespace lagoon::cli {
namespace {

constexpr const char* kAllModels = "fft,gerstner,sines,perlin,springs";

// The model names, checked; nullopt after printing the unknown one.
std::optional<std::vector<std::string>> parse_models(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    ocean::SurfaceModel m;
    if (!ocean::from_string(name, m)) {
      std::fprintf(stderr, "lagoon compare: --models: \"%s\" is no model; use some of %s\n", name.c_str(),
                   kAllModels);
      return std::nullopt;
    }
    out.push_back(name);
  }
  if (out.empty()) std::fprintf(stderr, "lagoon compare: --models is empty; use some of %s\n", kAllModels);
  return out.empty() ? std::nullopt : std::optional(out);
}

// What compare sets for a model beyond its name: what the model needs of the other fields.
std::vector<std::string> overrides_for(const std::string& model, std::string& note) {
  std::vector<std::string> out{"ocean.model=" + model};
  ocean::SurfaceModel m;
  if (!ocean::from_string(model, m)) return out;
  for (const ocean::ModelConstraint& c : ocean::model_constraints(m)) {
    out.push_back(std::string("ocean.") + c.field + "=" + scene::format_number(c.value));
    note += (note.empty() ? "" : ", ") + std::string(c.field) + " " + scene::format_number(c.value) +
            " (the model needs it)";
  }
  return out;
}

std::string markdown(const std::vector<ModelMeasure>& rows, const std::string& device, int rounds) {
  const double fft_ms = [&] {
    for (const ModelMeasure& m : rows)
      if (m.model == "fft") return m.step_ms;
    return 0.0;
  }();
  std::string md = "# lagoon compare\n\nDevice: " + device + ". Step: GPU timestamps, median of " +
                   std::to_string(rounds) +
                   " steps (springs: one step of its grid; the others: one frame at 60 Hz; gerstner and "
                   "sines with their own waves: their sum at the first cascade's texels, for export and "
                   "read-backs, since the surface sums them where it draws them). Surface: the surface "
                   "pass's GPU time in the render, where those sums are evaluated. The field is measured at "
                   "the render's time.\n\n";
  md +=
      "| model | step (ms) | step / fft | surface (ms) | Hs (m) | peak wavelength (m) | peak period (s) | "
      "spectrum error | tiling rho(L0) | note |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ModelMeasure& m : rows)
    md += "| " + m.model + " | " + fixed(m.step_ms, 3) + " | " +
          (fft_ms > 0 ? fixed(m.step_ms / fft_ms, 2) : "-") + " | " + fixed(m.surface_ms, 2) + " | " +
          fixed(m.hs_m, 3) + " | " + fixed(m.peak_wavelength_m, 2) + " | " + fixed(m.peak_period_s, 2) +
          " | " + (m.spectrum_error ? fixed(*m.spectrum_error, 3) : "-") + " | " + fixed(m.tiling, 3) +
          " | " + m.note + " |\n";
  md +=
      "\nSpectrum error: relative L2 of the first cascade's energy in 12 log-spaced bands of |k| against the "
      "scene's spectrum (only where the model draws from it). Tiling: the correlation of h(x) and "
      "h(x + L0), L0 the first cascade's patch; 1 = the field repeats there.\n";
  return md;
}

nlohmann::json json_row(const ModelMeasure& m) {
  return {{"model", m.model},
          {"step_ms", m.step_ms},
          {"step_wall_ms", m.step_wall_ms},
          {"surface_ms", m.surface_ms},
          {"hs_m", m.hs_m},
          {"peak_wavelength_m", m.peak_wavelength_m},
          {"peak_period_s", m.peak_period_s},
          {"spectrum_error", m.spectrum_error ? nlohmann::json(*m.spectrum_error) : nlohmann::json(nullptr)},
          {"tiling_correlation", m.tiling},
          {"note", m.note}};
}

bool write_image(const std::filesystem::path& path, const io::Image8& image) {
  auto written = io::write_png(path, image);
  if (!written) std::fprintf(stderr, "lagoon compare: %s\n", written.error().message.c_str());
  return bool(written);
}

int run_compare_models(const ParsedArgs& args) {
  const auto models = parse_models(args.get("models").value_or(kAllModels));
  if (!models) return kExitUsage;
  const auto rounds = integer_option(args, "rounds", 10, 1, 1000);
  if (!rounds) {
    std::fprintf(stderr, "lagoon compare: %s\n", rounds.error().message.c_str());
    return kExitUsage;
  }
  // The scene as given, then every model's: a scene or a model that cannot run stops the command before any
  // work, each with its own message.
  if (!load_scene_from_args(args, "compare")) return kExitFailure;
  std::vector<scene::Scene> scenes;
  std::vector<std::string> notes;
  for (const std::string& model : *models) {
    std::string note;
    auto scene = load_scene_from_args(args, "compare", overrides_for(model, note));
    if (!scene) {
      std::fprintf(stderr,
                   "lagoon compare: model %s cannot run this scene (above); fix it with --set, or leave "
                   "the model out of --models\n",
                   model.c_str());
      return kExitFailure;
    }
    scenes.push_back(*scene);
    notes.push_back(note);
  }
  auto staged = io::StagedOutput::create(*args.get("out"));
  if (!staged) {
    std::fprintf(stderr, "lagoon compare: %s\n", staged.error().message.c_str());
    return kExitFailure;
  }
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  std::vector<ModelMeasure> rows;
  nlohmann::json table = nlohmann::json::array();
  for (size_t i = 0; i < scenes.size(); ++i) {
    std::fprintf(stderr, "lagoon compare: %s (%zu of %zu)\n", (*models)[i].c_str(), i + 1, scenes.size());
    try {
      rows.push_back(measure_model(*ctx, scenes[i], int(*rounds)));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "lagoon compare: model %s: %s\n", (*models)[i].c_str(), e.what());
      return kExitFailure;
    }
    rows.back().note = notes[i];
    table.push_back(json_row(rows.back()));
    if (!write_image(staged->file(rows.back().model + ".png"), rows.back().render) ||
        !write_image(staged->file(rows.back().model + "_spectrum.png"), spectrum_plot(rows.back())))
      return kExitFailure;
  }
  const std::string device = ctx->device_info().name + " (" + ctx->device_info().type + ")";
  const nlohmann::json doc{
      {"device", device}, {"rounds", *rounds}, {"time_s", scenes.front().time_s}, {"models", table}};
  if (!write_image(staged->file("contact_sheet.png"), contact_sheet(rows)) ||
      !write_report_text(staged->file("compare.md"), markdown(rows, device, int(*rounds)),
                         "lagoon compare") ||
      !write_report_text(staged->file("compare.json"), doc.dump(2) + "\n", "lagoon compare"))
    return kExitFailure;
  if (auto committed = staged->commit(); !committed) {
    std::fprintf(stderr, "lagoon compare: %s\n", committed.error().message.c_str());
    return kExitFailure;
  }
  std::printf("%s", markdown(rows, device, int(*rounds)).c_str());
  std::printf("wrote %s: contact_sheet.png, compare.md, compare.json, <model>.png, <model>_spectrum.png\n",
              args.get("out")->c_str());
  return validation_status(*ctx);
}

}  // namespace

const Command& compare_command() {
  static const Command command{
      .spec = {.name = "compare",
               .summary = "Renders the surface models side by side with the scene's camera, time and light, "
                          "times each model's GPU step and measures its height field (Hs, peak wavelength "
                          "and period, spectrum error, tiling); writes a labelled contact sheet, a table "
                          "(compare.md, compare.json) and each model's directional spectrum plot.",
               .options = {scene_option(),
                           {"models", "LIST",
                            std::string("comma-separated models (default ") + kAllModels + ")", false},
                           {"out", "DIR", "output folder (created; its files are replaced together)", true},
                           {"rounds", "N", "steps timed per model (default 10)", false},
                           set_option()},
               .details =
                   "example:\n  lagoon compare --scene scenes/default.json --models fft,gerstner,springs "
                   "--out /tmp/models\n"},
      .run = run_compare_models};
  return command;
}

}  // namespace lagoon::cli
