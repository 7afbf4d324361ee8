#include "validate_light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "optics/cie.h"
#include "optics/csv_table.h"
#include "optics/kd.h"
#include "optics/lut.h"
#include "optics/underwater.h"
#include "render/ocean_renderer.h"
#include "render/passes/caustics_pass.h"
#include "render/water_luts.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "shared/caustics.h"

namespace lagoon::cli {
namespace {

const char* const kJerlovTypes[] = {"I", "IA", "IB", "II", "III", "1C", "3C", "5C", "7C", "9C"};

// Looking straight up from `depth` m under a calm sea with no floor, 200 px and 120° wide: the sky inside
// the window, the dark water mirrored by total internal reflection outside it.
Result<scene::Scene> window_scene(double depth, const ValidateOptions& o) {
  nlohmann::json doc{
      {"camera", {{"position", {0, -depth, 0}}, {"look_at", {0, 10, 0.001}}, {"fov_deg", 120}}},
      {"sun", {{"elevation_deg", 80}}},
      {"ocean", {{"spectrum", {{"wind_speed_mps", 0.5}}}}},
      {"water", {{"type", "jerlov-I"}}},
      {"seafloor", {{"type", "none"}}},
      {"render", {{"width", 200}, {"height", 200}, {"effects", {{"particles", false}}}}}};
  auto s = scene::parse_scene(doc, "lagoon validate (Snell's window)");
  if (s && o.broken == "no-refraction") s->water.ior = 1.0;
  return s;
}

double window_luminance(const io::Image8& image, uint32_t x, uint32_t y) {
  const uint8_t* p = &image.rgba[(size_t{y} * image.width + x) * 4];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// The window's edge: the angle from the zenith where the median luminance of 0.5° rings falls halfway from
// inside (20-40°) to outside (55-62°). NaN when there is no bright window.
double window_edge_deg(const io::Image8& image) {
  const uint32_t size = image.width;
  const double focal = (size / 2.0) / std::tan(60.0 * kPi / 180.0);
  std::vector<std::vector<double>> bins(140);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      const double r = std::hypot(x + 0.5 - size / 2.0, y + 0.5 - size / 2.0);
      const size_t bin = size_t(std::atan(r / focal) * 180.0 / kPi * 2.0);
      if (bin < bins.size()) bins[bin].push_back(window_luminance(image, x, y));
    }
  auto median = [&](double from_deg, double to_deg) {
    std::vector<double> v;
    for (size_t b = size_t(from_deg * 2); b < size_t(to_deg * 2); ++b)
      v.insert(v.end(), bins[b].begin(), bins[b].end());
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const double inside = median(20, 40), outside = median(55, 62);
  if (!(inside > outside + 30)) return std::nan("");
  for (double a = 40; a < 62; a += 0.5)
    if (median(a, a + 0.5) < 0.5 * (inside + outside)) return a + 0.25;
  return std::nan("");
}

Result<Law> snell_window(vk::Context& ctx, const ValidateOptions& o) {
  Law law{
      .id = "light.snell-window",
      .title = "Snell's window",
      .source = "Snell's law, critical angle asin(1/n), n = 1.333",
      .measured_on = "device: renders from under a calm sea looking up",
      .x_label = "camera depth (m)",
      .y_label = "window edge from the zenith (deg)",
      .tolerance = "±1°",
      .note =
          "Wind 0.5 m/s, jerlov-I, no floor, 200x200 px, 120° field of view; the edge is where the median "
          "luminance of 0.5° rings falls halfway from inside the window to outside it."};
  const double critical = std::asin(1.0 / 1.333) * 180.0 / kPi;
  for (double depth : o.quick ? std::vector<double>{4} : std::vector<double>{2, 6, 12}) {
    auto s = window_scene(depth, o);
    if (!s) return s.error();
    auto renderer = render::OceanRenderer::create(ctx, *s);
    if (!renderer) return renderer.error();
    law.points.push_back(
        absolute_point(depth, critical, window_edge_deg((*renderer)->render(*s)) * o.scale(), 1.0));
  }
  return law;
}

// K_d of the model per Jerlov type: the geometric mean over 400-600 nm of model / Jerlov (1976, Table XXVII).
Result<Law> kd_jerlov(const ValidateOptions& o) {
  Law law{
      .id = "light.kd-jerlov",
      .title = "Diffuse attenuation K_d against Jerlov",
      .source = "Jerlov 1976, Marine Optics, Table XXVII",
      .measured_on = "cpu: the four-flow model the water LUTs are made from (optics/kd.h)",
      .x_label = "Jerlov type (1 = I ... 10 = 9C)",
      .y_label = "K_d model / Jerlov",
      .tolerance = "±30 %",
      .note =
          "Deep water, K_d = -d ln(E_d)/dz between 5 and 10 m, sun 60° up; geometric mean of the ratio "
          "over 400-600 nm, where the IOP tables and Jerlov's overlap. Types I-III, 7C and 9C are within 15 "
          "%; 1C-5C are 16-28 % low (docs/optics.md)."};
  auto table = optics::CsvTable::embedded("jerlov1976_kd_table27.csv");
  if (!table) return table.error();
  const auto nm = table->numbers("wavelength_nm");
  if (!nm) return nm.error();
  const double d = o.broken == "seed-kd" ? 1.0 : optics::WaterParams{}.diffuse_path_factor;
  for (size_t t = 0; t < std::size(kJerlovTypes); ++t) {
    optics::WaterParams params;
    params.type = std::string("jerlov-") + kJerlovTypes[t];
    auto in = optics::lut_inputs(params, 60.0);
    if (!in) return in.error();
    const auto measured = table->numbers(kJerlovTypes[t]);
    if (!measured) return measured.error();
    double log_sum = 0;
    int count = 0;
    for (size_t r = 0; r < nm->size(); ++r) {
      if ((*nm)[r] < 400 || (*nm)[r] > 600) continue;
      const int i = int(std::lround(((*nm)[r] - optics::kLambdaMinNm) / optics::kLambdaStepNm));
      log_sum += std::log(optics::model_kd(*in, i, d) / (*measured)[r]), ++count;
    }
    law.points.push_back(relative_point(double(t + 1), 1.0, std::exp(log_sum / count) * o.scale(), 0.30));
  }
  return law;
}

// Secchi depth: where a white disk (reflectance 0.85) lowered into the water disappears to the eye. Seen
// from above, the disk's radiance minus the water's at each wavelength decays as exp(-(c + K_d) z) (down to
// the disk at K_d, back up as a beam at c: Preisendorfer 1986; Tyler 1968); the disk vanishes where the
// luminance contrast, Σ V E_d (0.85 - R) e^{-(c+K_d) z} / Σ V E_d R, falls to the eye's threshold 0.0066. V
// is CIE's photopic y-bar, E_d the sky's irradiance, R the water's irradiance reflectance: all from the
// model. Poole & Atkins (1929): z_SD ≈ 1.7/K_d(490) with Jerlov's K_d.
double model_secchi(const optics::LutInputs& in, double diffuse_path, bool beam_only) {
  std::vector<double> weight(optics::kSamples), rate(optics::kSamples);
  double background = 0;
  for (int i = 0; i < optics::kSamples; ++i) {
    const double ed = (in.sky.sun[i] + in.sky.sky[i]) * optics::cie_y_bar()[i];
    const double r = optics::model_reflectance(in, i, diffuse_path);
    weight[size_t(i)] = ed * (0.85 - r), background += ed * r;
    rate[size_t(i)] = in.water.absorption_per_m[i] + in.water.scattering_per_m[i] +
                      (beam_only ? 0.0 : optics::model_kd(in, i, diffuse_path));
  }
  auto contrast = [&](double z) {
    double sum = 0;
    for (int i = 0; i < optics::kSamples; ++i) sum += weight[size_t(i)] * std::exp(-rate[size_t(i)] * z);
    return sum / background;
  };
  double lo = 0, hi = 1000;
  for (int k = 0; k < 60; ++k) (contrast(0.5 * (lo + hi)) > 0.0066 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

Result<Law> secchi(const ValidateOptions& o) {
  Law law{.id = "light.secchi",
          .title = "Secchi depth",
          .source = "Poole & Atkins 1929 (z = 1.7/K_d(490)), K_d from Jerlov 1976",
          .measured_on = "cpu: the four-flow model's c, K_d and reflectance over the visible",
          .x_label = "Jerlov type (1 = I ... 10 = 9C)",
          .y_label = "Secchi depth (m)",
          .tolerance = "±35 %",
          .log_y = true,
          .note =
              "Lagoon's Secchi depth: where a white disk's luminance contrast against the water, decaying as "
              "exp(-(c + K_d) z) at each wavelength (Preisendorfer 1986), falls to 0.0066; sun 60° up. The "
              "Poole-Atkins coefficient itself ranges 1.4-2.0 in the literature, hence the wide band."};
  auto table = optics::CsvTable::embedded("jerlov1976_kd_table27.csv");
  if (!table) return table.error();
  const auto nm = table->numbers("wavelength_nm");
  if (!nm) return nm.error();
  size_t row = 0;
  while (row < nm->size() && (*nm)[row] < 490) ++row;
  for (size_t t = 0; t < std::size(kJerlovTypes); ++t) {
    optics::WaterParams params;
    params.type = std::string("jerlov-") + kJerlovTypes[t];
    auto in = optics::lut_inputs(params, 60.0);
    if (!in) return in.error();
    const auto jerlov = table->numbers(kJerlovTypes[t]);
    if (!jerlov) return jerlov.error();
    const double z = model_secchi(*in, params.diffuse_path_factor, o.broken == "beam-secchi") * o.scale();
    law.points.push_back(relative_point(double(t + 1), 1.7 / (*jerlov)[row], z, 0.35));
  }
  return law;
}

// Caustics under a 7 m/s sea, jerlov-I, a sloping floor 3-6 m down, the sun 60° up: the caustic map's
// slices (irradiance relative to a flat sea at 1, 2.5, 6 and 15 m) over the inner 80 % of the window, where
// the floor's shading uses them at full weight. The mean is the map's (the sun's direct light, focused);
// the contrast is the floor's light's, as common/caustics.glsl draws it: the direct share s(z) of the
// light focused, the diffuse rest not, gain = 1 + s·(map − 1).
struct CausticSlices {
  std::vector<double> depth, mean, contrast;
};

Result<CausticSlices> caustic_slices(vk::Context& ctx, bool from_above, const ValidateOptions& o) {
  const nlohmann::json camera = from_above
                                    ? nlohmann::json{{"position", {0, 3, 0}}, {"look_at", {0, -3, 6}}}
                                    : nlohmann::json{{"position", {0, -1.5, 0}}, {"look_at", {0, -4, 10}}};
  nlohmann::json doc{
      {"camera", camera},
      {"sun", {{"elevation_deg", 60}, {"azimuth_deg", 20}}},
      // The caustics do not see the foam: fading it at once spares each frame, 3.7 s after
      // the last, the catch-up of 37 foam steps. The slices reach 15 m, below the floor drawn
      // at 3-6 m: the sea is the deep sea's (not shortened by that floor), as at every depth.
      {"ocean",
       {{"spectrum", {{"wind_speed_mps", 7.0}}}, {"foam", {{"decay_per_s", 100}}}, {"shoaling", false}}},
      {"water", {{"type", "jerlov-I"}}},
      {"seafloor", {{"type", "slope"}, {"depth_near_m", 3}, {"depth_far_m", 6}}},
      {"objects", nlohmann::json::array()},
      {"render", {{"width", 64}, {"height", 48}, {"effects", {{"particles", false}}}}},
      {"time_s", 10}};
  auto s = scene::parse_scene(doc, "lagoon validate (caustics)");
  if (!s) return s.error();
  s->render.effects.caustics_blur = o.broken != "sharp-caustics";
  auto renderer = render::OceanRenderer::create(ctx, *s);
  if (!renderer) return renderer.error();
  auto inputs = render::scene_lut_inputs(*s);
  if (!inputs) return inputs.error();
  // Energy is conserved over the whole floor, not over a 25 m window: waves of 40 m focus light across its
  // edges. The window's mean is averaged over frames 3.7 s apart (uncorrelated patterns), the contrast too.
  const glm::vec4 depths = render::CausticsWindow{}.depths;  // the slices' depths (fixed)
  const int frames = o.quick ? 6 : 16;
  const size_t n = LAGOON_CAUSTICS_CELLS, lo = n / 10, hi = n - n / 10;
  std::vector<double> share;  // the sun's direct share of the light at each slice's depth
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    auto sample = optics::underwater_sample(*inputs, 0.0, depths[k]);
    if (!sample) return sample.error();
    share.push_back(sample->direct_share);
  }
  CausticSlices out;
  out.mean.assign(LAGOON_CAUSTICS_SLICES, 0.0), out.contrast.assign(LAGOON_CAUSTICS_SLICES, 0.0);
  for (int f = 0; f < frames; ++f) {
    s->time_s = float(10.0 + 3.7 * f);
    (*renderer)->render(*s);
    const std::vector<float> map = (*renderer)->caustics().read_map(ctx);
    for (size_t k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
      double sum = 0, gain = 0, square = 0, count = 0;
      for (size_t z = lo; z < hi; ++z)
        for (size_t x = lo; x < hi; ++x) {
          const double v = map[(k * n + z) * n + x], g = 1.0 + share[k] * (v - 1.0);
          sum += v, gain += g, square += g * g, ++count;
        }
      out.mean[k] += sum / count / frames;
      const double mean = gain / count;
      out.contrast[k] += std::sqrt(std::max(square / count - mean * mean, 0.0)) / mean / frames;
    }
  }
  for (size_t k = 0; k < LAGOON_CAUSTICS_SLICES; ++k)
    out.depth.push_back(depths[int(k)]), out.mean[k] *= o.scale();
  return out;
}

Result<std::vector<Law>> caustics(vk::Context& ctx, const ValidateOptions& o) {
  Law contrast{.id = "light.caustics-contrast",
               .title = "Caustic contrast fades past the focus",
               .source = "geometric optics of a random surface (focusing, then mixing)",
               .measured_on = "device: the caustic map read back, as the floor's shading applies it",
               .x_label = "depth (m)",
               .y_label = "floor light's contrast std/mean, at most the shallower slice's",
               .tolerance = "≤ previous past the deepest focus",
               .note =
                   "From above; the contrast of the floor's light at 15 m must not exceed that at 6 m. The "
                   "floor's light is the sun's direct share s(z) of it focused by the map, the diffuse rest "
                   "unfocused (common/caustics.glsl: 1 + s (map - 1), s from the optics model): scattering "
                   "takes light out of the focused beam with depth, and the waves shorter than the map's "
                   "cells and the solar disc blur the pattern in proportion to depth "
                   "(render/caustics_window.h)."};
  std::vector<Law> laws;
  for (bool above : {true, false}) {
    auto slices = caustic_slices(ctx, above, o);
    if (!slices) return slices.error();
    Law law{
        .id = above ? "light.caustics-mean-above" : "light.caustics-mean-below",
        .title = above ? "Caustics keep the floor's mean light (from above)"
                       : "Caustics keep the floor's mean light (from below)",
        .source = "conservation of energy",
        .measured_on = "device: the caustic map read back",
        .x_label = "depth (m)",
        .y_label = "mean irradiance / flat sea's",
        .tolerance = "±1 %",
        .note =
            "7 m/s sea, jerlov-I, sloping floor 3-6 m, sun 60° up, 64x48 frame; the map's mean over the "
            "inner 80 % of its 32 m window at each slice depth, averaged over 16 frames 3.7 s apart (6 in "
            "--quick): energy is conserved over the whole floor, and waves longer than the window carry "
            "light across its edges in any one frame."};
    for (size_t k = 0; k < slices->depth.size(); ++k) {
      law.points.push_back(relative_point(slices->depth[k], 1.0, slices->mean[k], 0.01));
      if (above && k + 1 == slices->depth.size())
        contrast.points.push_back(
            at_most_point(slices->depth[k], slices->contrast[k - 1], slices->contrast[k] * o.scale(), 0.0));
    }
    laws.push_back(std::move(law));
  }
  laws.push_back(std::move(contrast));
  return laws;
}

}  // namespace

std::vector<Law> light_laws(vk::Context& ctx, const ValidateOptions& o) {
  std::vector<Law> laws;
  std::vector<Result<Law>> measured;
  if (o.wants("light.snell-window")) measured.push_back(snell_window(ctx, o));
  if (o.wants("light.kd-jerlov")) measured.push_back(kd_jerlov(o));
  if (o.wants("light.secchi")) measured.push_back(secchi(o));
  if (o.wants("light.caustics")) {
    if (auto c = caustics(ctx, o); c) {
      for (Law& law : *c) measured.push_back(std::move(law));
    } else {
      measured.push_back(c.error());
    }
  }
  for (auto& law : measured) {
    if (law) {
      laws.push_back(std::move(*law));
    } else {
      Law failed{.id = "light",
                 .title = "light laws",
                 .source = "-",
                 .measured_on = "-",
                 .tolerance = "-",
                 .note = "could not be measured: " + law.error().message};
      laws.push_back(std::move(failed));
    }
  }
  return laws;
}

}  // namespace lagoon::cli
