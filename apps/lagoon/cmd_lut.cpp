// lagoon lut: the water-colour LUTs T0/T1 of one water type and sun (docs/optics.md), or the whole
// computation behind one of their entries (--explain).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "io/atomic_file.h"
#include "io/npy.h"
#include "io/png.h"
#include "io/staged_output.h"
#include "kd_plot.h"
#include "lut_error_map.h"
#include "lut_underwater.h"
#include "optics/bottom_spectra.h"
#include "optics/colour.h"
#include "optics/lut.h"
#include "optics/surface.h"
#include "render/water_luts.h"
#include "scene_args.h"

namespace lagoon::cli {
namespace {

// Preview: columns = r (left r = 0), rows = h (top h = 0), tone-mapped with eq. 18 and sRGB-encoded,
// each LUT sample drawn as a block so 64 samples make a 256-pixel image.
io::Image8 preview(const optics::WaterLut& lut, const std::vector<float>& data, int stride, bool times_a) {
  const uint32_t scale = std::max(1u, 256u / lut.r_count);
  io::Image8 image;
  image.width = lut.r_count * scale;
  image.height = lut.h_count * scale;
  image.rgba.resize(size_t{image.width} * image.height * 4);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const float* v = &data[(size_t{x / scale} * lut.h_count + y / scale) * stride];
      const double weight = times_a ? v[3] : 1.0;
      const glm::dvec3 rgb = optics::encode_srgb(optics::tone_map(weight * glm::dvec3(v[0], v[1], v[2]), {}));
      uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround(std::clamp(rgb[c], 0.0, 1.0) * 255));
      p[3] = 255;
    }
  return image;
}

// The surface coefficients the tables were built with: the wavy sea's (eq. 10) or the flat surface's.
nlohmann::json surface_json(const optics::LutInputs& in) {
  const optics::SurfaceCoefficients c = optics::lut_surface(in);
  return {{"wavy", in.surface.has_value()},
          {"r_dd", c.r_dd},
          {"t_dd", c.t_dd},
          {"r_ff", c.r_ff},
          {"t_ff", c.t_ff},
          {"rw_dd", c.rw_dd},
          {"rw_ff", c.rw_ff},
          {"tw_ff", c.tw_ff}};
}

nlohmann::json params_json(const optics::LutInputs& in) {
  const optics::WaterParams& w = in.params;
  return {{"water_type", w.type},
          {"table", w.table},
          {"bottom_albedo", w.bottom_albedo},
          {"phase", w.phase},
          {"phase_x1", w.phase_x1},
          {"lut_gamma", w.lut_gamma},
          {"ior", w.ior},
          {"sun_elevation_deg", in.sky.sun_elevation_deg},
          {"surface", surface_json(in)}};
}

std::optional<std::pair<double, double>> parse_pair(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  auto a = parse_number(text.substr(0, comma)), b = parse_number(text.substr(comma + 1));
  if (!a || !b) return std::nullopt;
  return std::pair{*a, *b};
}

int explain(const optics::LutInputs& in, const std::string& at) {
  auto point = parse_pair(at);
  if (!point || point->first < 0 || point->second < 0) {
    std::fprintf(stderr, "lagoon lut: --explain %s must be R,H: two distances >= 0 in metres\n", at.c_str());
    return kExitUsage;
  }
  auto e = optics::explain_lut_point(in, point->first, point->second);
  if (!e) {
    std::fprintf(stderr, "lagoon lut: %s\n", e.error().message.c_str());
    return kExitFailure;
  }
  const optics::SurfaceCoefficients s = optics::lut_surface(in);  // the wavy sea's, as the tables used
  const optics::BottomCoefficients b = optics::lambertian_bottom(in.params.bottom_albedo);
  const nlohmann::json surface{{"t_dd", s.t_dd},   {"r_dd", s.r_dd},  {"t_df", s.t_df},   {"r_df", s.r_df},
                               {"t_ff", s.t_ff},   {"r_ff", s.r_ff},  {"rw_dd", s.rw_dd}, {"rw_df", s.rw_df},
                               {"rw_ff", s.rw_ff}, {"tw_ff", s.tw_ff}};
  const nlohmann::json bottom{{"r_dd", b.r_dd}, {"r_df", b.r_df}, {"r_ff", b.r_ff}};
  nlohmann::json spectral = nlohmann::json::array();
  for (const auto& w : e->spectral) {
    auto flows = [](const double f[4]) {
      return nlohmann::json{{"G_plus", f[0]}, {"G_minus", f[1]}, {"F_plus", f[2]}, {"F_minus", f[3]}};
    };
    spectral.push_back({{"wavelength_nm", w.wavelength_nm},
                        {"chi", w.chi},
                        {"sigma", w.sigma},
                        {"X1", w.x1},
                        {"k", w.k},
                        {"S", w.s},
                        {"S1", w.s1},
                        {"S2", w.s2},
                        {"E_sun", w.e_sun},
                        {"E_sky", w.e_sky},
                        {"surface_coefficients", surface},
                        {"bottom_coefficients", bottom},
                        {"flows_at_surface", flows(w.surface_flows)},
                        {"flows_at_bottom", flows(w.bottom_flows)},
                        {"alpha_l", w.alpha_l},
                        {"l_m", e->path_m}});
  }
  const nlohmann::json out{
      {"r_m", e->r_m},
      {"h_m", e->h_m},
      {"l_m", e->path_m},
      {"parameters", params_json(in)},
      {"spectral", spectral},
      {"T0_rgb", {e->t0.x, e->t0.y, e->t0.z}},
      {"a", e->a},
      {"T1_rgb", {e->t1.x, e->t1.y, e->t1.z}},
      {"units", "linear sRGB relative to the downwelling light above the water (white = 1)"}};
  std::printf("%s\n", out.dump(2).c_str());
  return kExitOk;
}

// --water and --sun-elevation are shorthands for --set; nullopt (after printing why) when the elevation is
// not a number.
std::optional<std::vector<std::string>> lut_overrides(const ParsedArgs& args) {
  std::vector<std::string> overrides;
  if (auto w = args.get("water")) overrides.push_back("water.type=" + *w);
  if (auto e = args.get("sun-elevation")) {
    if (!parse_number(*e)) {
      std::fprintf(stderr, "lagoon lut: --sun-elevation %s is not a number of degrees\n", e->c_str());
      return std::nullopt;
    }
    overrides.push_back("sun.elevation_deg=" + *e);
  }
  return overrides;
}

// lut.json: the parameters, the axes and how a shader looks the tables up, what the previews show.
nlohmann::json lut_meta(const optics::WaterLut& lut, const optics::LutInputs& inputs) {
  return {
      {"format_version", 1},
      {"generator", "lagoon lut"},
      {"parameters", params_json(inputs)},
      {"r_m", lut.r_m},
      {"h_m", lut.h_m},
      {"axes",
       "T0.npy is float32 [r][h][4] = (T0 RGB, a), T1.npy is float32 [r][h][3]; r_m[i] = r_max (i/(R-1))^2, "
       "h_m[j] = h_max (j/(H-1))^2, so a shader looks up u = sqrt(r/r_max), v = sqrt(h/h_max). r: horizontal "
       "distance travelled by the refracted view ray under water; h: depth of the bottom where it ends; path "
       "length l = sqrt(r^2 + h^2) (docs/optics.md)."},
      {"previews",
       "T0.png shows a*T0 (a white bottom seen through the water), T1.png shows T1 (the water's own colour). "
       "Columns = r (left r = 0, right r_max), rows = h (top h = 0, bottom h_max), on the same squared axes; "
       "tone-mapped (eq. 18) and sRGB-encoded."},
      {"units",
       "linear sRGB relative to the downwelling light above the water: a white Lambertian surface "
       "above the water has RGB (1, 1, 1)"},
      {"deep_colour_rgb", {lut.deep_colour.x, lut.deep_colour.y, lut.deep_colour.z}},
      {"build_ms", lut.build_ms}};
}

int lut_failure(const std::string& message) {
  std::fprintf(stderr, "lagoon lut: %s\n", message.c_str());
  return kExitFailure;
}

// Builds the LUTs and writes T0/T1 (.npy and PNG previews) and lut.json into a staged folder `out`, moved
// into place only when every file is written.
int write_luts(const optics::LutInputs& inputs, const std::string& out) {
  auto built = optics::build_water_lut(inputs);
  if (!built) return lut_failure(built.error().message);
  const optics::WaterLut& lut = *built;
  auto staged = io::StagedOutput::create(out);
  if (!staged) return lut_failure(staged.error().message);
  const size_t r = lut.r_count, h = lut.h_count;
  const std::vector<size_t> t0_shape{r, h, 4}, t1_shape{r, h, 3};
  if (auto w = io::write_npy(staged->file("T0.npy"), lut.t0, t0_shape); !w)
    return lut_failure(w.error().message);
  if (auto w = io::write_npy(staged->file("T1.npy"), lut.t1, t1_shape); !w)
    return lut_failure(w.error().message);
  if (auto w = io::write_png(staged->file("T0.png"), preview(lut, lut.t0, 4, true)); !w)
    return lut_failure(w.error().message);
  if (auto w = io::write_png(staged->file("T1.png"), preview(lut, lut.t1, 3, false)); !w)
    return lut_failure(w.error().message);
  auto underwater = write_underwater_tables(inputs, *staged);
  if (!underwater) return lut_failure(underwater.error().message);
  nlohmann::json meta = lut_meta(lut, inputs);
  meta["underwater"] = *underwater;
  const std::string text = meta.dump(2) + "\n";
  if (auto w = io::write_text_atomic(staged->file("lut.json"), text); !w)
    return lut_failure(w.error().message);
  if (auto c = staged->commit(); !c) return lut_failure(c.error().message);
  std::printf(
      "wrote %s: %zux%zu LUTs for %s, sun %.1f deg, built in %.1f ms; deep colour (%.3f, %.3f, %.3f)\n",
      out.c_str(), r, h, inputs.params.type.c_str(), inputs.sky.sun_elevation_deg, lut.build_ms,
      lut.deep_colour.x, lut.deep_colour.y, lut.deep_colour.z);
  return kExitOk;
}

// K_d of every Jerlov type, the model with D = 1 and D = 2 against the measurements (kd_plot.h).
int write_kd_plot(const std::string& path) {
  if (path.size() < 4 || path.substr(path.size() - 4) != ".png") {
    std::fprintf(stderr, "lagoon lut: --kd-plot %s must name a .png file\n", path.c_str());
    return kExitUsage;
  }
  auto image = kd_plot();
  if (!image) return lut_failure(image.error().message);
  if (auto written = io::write_png(path, *image); !written) return lut_failure(written.error().message);
  std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

int run_lut(const ParsedArgs& args) {
  const auto overrides = lut_overrides(args);
  if (!overrides) return kExitUsage;
  if (auto plot = args.get("kd-plot")) return write_kd_plot(*plot);
  if (!args.has("out") && !args.has("explain") && !args.has("error-map")) {
    std::fprintf(
        stderr,
        "lagoon lut: give --out DIR (write the LUTs), --explain R,H (print one entry), --error-map DIR "
        "(eqs. 21, 22, 24 against eq. 20) or --kd-plot FILE.png (K_d against Jerlov)\n");
    return kExitUsage;
  }
  auto scene = load_scene_from_args(args, "lut", *overrides);
  if (!scene) return kExitFailure;
  auto inputs = render::scene_lut_inputs(*scene);
  if (!inputs) {
    std::fprintf(stderr, "lagoon lut: %s\n", inputs.error().message.c_str());
    return kExitFailure;
  }
  if (auto at = args.get("explain")) return explain(*inputs, *at);
  if (auto dir = args.get("error-map")) {
    std::printf("lagoon lut: measuring eqs. 21, 22 and 24 against eq. 20 for %zu bottoms, two Phi...\n",
                optics::bottom_spectra().size() + 1);
    if (auto written = write_error_maps(*inputs, *dir); !written) return lut_failure(written.error().message);
    std::printf(
        "wrote %s: error_maps_linear.png, error_maps_seed.png, error_summary.csv, error_summary.md, "
        "error.json\n",
        dir->c_str());
    return kExitOk;
  }
  return write_luts(*inputs, *args.get("out"));
}

}  // namespace

const Command& lut_command() {
  static const Command command{
      .spec =
          {.name = "lut",
           .summary =
               "Builds the water-colour look-up tables T0 (RGB + a) and T1 of Belyaev's model for a "
               "water type and sun (eq. 22: T_refr = a·T0·T_bottom + (1 - a)·T1) and writes "
               "T0.npy, T1.npy, lut.json and PNG previews, with the tables a camera under water needs "
               "(underwater_*.npy: what a view ray transmits and adds); or prints every quantity behind one "
               "entry with --explain.",
           .options =
               {{"scene", "FILE", "take water and sun from this scene (default: all defaults)"},
                {"water", "TYPE", "water type, e.g. jerlov-IB (same as --set water.type=TYPE)"},
                {"out", "DIR",
                 "output folder for T0.npy, T1.npy, lut.json, T0.png, T1.png and the underwater "
                 "tables underwater_*.npy, underwater.png"},
                {"sun-elevation", "DEG", "sun elevation (same as --set sun.elevation_deg=DEG)"},
                {"explain", "R,H", "print JSON for the entry at distance R and depth H (metres)"},
                {"error-map", "DIR",
                 "measure eqs. 21, 22 and 24 against the spectral eq. 20 over measured bottoms: CIEDE2000 "
                 "maps "
                 "over (r, h) as PNG, error_summary.csv/.md and error.json (docs/optics.md)"},
                {"kd-plot", "FILE.png",
                 "draw the model's K_d (D = 1 and D = 2) against Jerlov's for every type (docs/optics.md)"},
                set_option()},
           .details = "water types: jerlov-I, jerlov-IA, jerlov-IB, jerlov-II, jerlov-III, jerlov-1C, "
                      "jerlov-3C, jerlov-5C, jerlov-7C, jerlov-9C, custom (with water.table)\n"
                      "example:\n  lagoon lut --water jerlov-IA --out out/lut-IA --sun-elevation 45\n"},
      .run = run_lut};
  return command;
}

}  // namespace lagoon::cli
