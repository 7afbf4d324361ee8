// lagoon sky: the angle-resolved spectral sky of Belyaev's §5 (Fig. 2) for the scene's sun, with its
// irradiance checked against the model the LUTs use and a tone map fitted to it (docs/optics.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "commands.h"
#include "io/atomic_file.h"
#include "io/npy.h"
#include "io/staged_output.h"
#include "optics/cie.h"
#include "optics/sky_radiance.h"
#include "scene_args.h"
#include "sky_image.h"

namespace lagoon::cli {
namespace {

constexpr int kSpectralStepDeg = 2;  // sky_spectral.npy: one sample every 2° in φ and θ

int sky_failure(const std::string& message) {
  std::fprintf(stderr, "lagoon sky: %s\n", message.c_str());
  return kExitFailure;
}

double band_integral(const optics::Spectrum& s) {
  double sum = 0;
  for (double v : s) sum += v * optics::kLambdaStepNm;
  return sum;
}

// L(λ) on a (θ, φ) grid every 2°, φ from the sun as in the PNG: float32 [θ][φ][λ].
std::vector<float> spectral_grid(const optics::SkyRadiance& sky, int rows, int columns) {
  std::vector<float> out;
  out.reserve(size_t(rows) * columns * optics::kSamples);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x) {
      const double theta = (y + 0.5) * kSpectralStepDeg * std::numbers::pi / 180;
      const double phi = (x + 0.5) * kSpectralStepDeg * std::numbers::pi / 180 -
                         std::numbers::pi;  // sun at azimuth 0 in SkyRadiance
      const optics::Spectrum l =
          sky.radiance({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
      for (double v : l) out.push_back(float(v));
    }
  return out;
}

nlohmann::json irradiance_json(const optics::SkyRadiance& sky, const SkyImage& image,
                               const render::SkyLight& light) {
  const optics::Spectrum model = sky.irradiance().sky;
  const optics::Spectrum from_image = optics::sky_image_irradiance(sky, image.height);
  double worst = 0;
  for (int i = 0; i < optics::kSamples; ++i)
    if (model[i] > 0) worst = std::max(worst, std::abs(from_image[i] / model[i] - 1));
  glm::dvec3 rgb(0.0);
  const double d_theta = std::numbers::pi / 2 / image.height;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t i = size_t(y) * image.width + x;
      rgb += glm::dvec3(image.rgb[i * 3], image.rgb[i * 3 + 1], image.rgb[i * 3 + 2]) *
             (std::cos((y + 0.5) * d_theta) * image.solid_angle[i] / std::numbers::pi);
    }
  return {
      {"e_sky_model_w_m2", band_integral(model)},
      {"e_sky_image_w_m2", band_integral(from_image)},
      {"e_sky_worst_wavelength_relative_error", worst},
      {"e_sun_horizontal_w_m2", band_integral(sky.irradiance().sun)},
      {"sky_rgb_from_image", {rgb.x, rgb.y, rgb.z}},
      {"sky_rgb_of_e_sky", {light.sky_radiance.x, light.sky_radiance.y, light.sky_radiance.z}},
      {"about",
       "E_sky integrated over the 380-780 nm band (W m^-2) from the irradiance model (optics/sky.h, what the "
       "LUTs use) and from this image's spectral radiance (cos-weighted, one cell per pixel row and 2x as "
       "many columns); sky_rgb_*: the same in white units, (1/pi) sum L cos dw of sky_rgb.npy against Phi of "
       "the model's E_sky"}};
}

nlohmann::json sky_meta(const scene::Scene& scene, const optics::SkyRadiance& sky, const SkyImage& image,
                        const render::SkyLight& light, const optics::ToneMapParams& fit) {
  const optics::ToneMapParams defaults;
  const gpu::SkyModelGpu& m = sky.coefficients();
  return {
      {"format_version", 1},
      {"generator", "lagoon sky"},
      {"sun_elevation_deg", scene.sun.elevation_deg},
      {"turbidity", sky.turbidity()},
      {"model",
       "Preetham, Shirley & Smits (1999) angular shape and chromaticity, CIE daylight basis spectra, scaled "
       "per wavelength to Bird & Riordan (1986) E_sky (docs/optics.md)"},
      {"perez_luminance", {m.perez_lum.x, m.perez_lum.y, m.perez_lum.z, m.perez_lum.w, m.perez_e.x}},
      {"perez_x", {m.perez_x.x, m.perez_x.y, m.perez_x.z, m.perez_x.w, m.perez_e.y}},
      {"perez_y", {m.perez_y.x, m.perez_y.y, m.perez_y.z, m.perez_y.w, m.perez_e.z}},
      {"image",
       {{"width", image.width},
        {"height", image.height},
        {"axes",
         "sky.png and sky_rgb.npy (float32 [theta][phi][3], linear sRGB in white units: a white "
         "Lambertian surface under sun and sky = 1): column x is the azimuth from the sun phi = (x + "
         "0.5)/width*360 - 180 deg (sun in the middle), row y the zenith angle theta = (y + 0.5)/height*90 "
         "deg. sky_spectral.npy: float32 [theta][phi][81], W m^-2 sr^-1 nm^-1 at 380..780 nm every 5 nm, one "
         "sample every 2 deg on the same axes. The sun's disc is drawn in the PNG only."}}},
      {"irradiance", irradiance_json(sky, image, light)},
      {"tone_map_fit",
       {{"world_adaptation_luminance", fit.world_adaptation_luminance},
        {"white_luminance", fit.white_luminance},
        {"default_world_adaptation_luminance", defaults.world_adaptation_luminance},
        {"default_white_luminance", defaults.white_luminance},
        {"use", "--set render.tone_map_adaptation=" + std::to_string(fit.world_adaptation_luminance) +
                    " --set render.tone_map_white=" + std::to_string(fit.white_luminance)},
        {"how",
         "L_wa: the solid-angle weighted log-average of the sky's luminance; L_white: the L_d of eq. 18 at "
         "which the brightest 1 % of the sky reaches display white (sky.png is drawn with these)"}}}};
}

int run_sky(const ParsedArgs& args) {
  std::vector<std::string> overrides;
  if (auto e = args.get("sun-elevation")) {
    if (!parse_number(*e)) {
      std::fprintf(stderr, "lagoon sky: --sun-elevation %s is not a number of degrees\n", e->c_str());
      return kExitUsage;
    }
    overrides.push_back("sun.elevation_deg=" + *e);
  }
  int width = 720;
  if (auto w = args.get("width")) {
    const auto n = parse_number(*w);
    if (!n || *n < 64 || *n > 8192 || std::fmod(*n, 4.0) != 0) {
      std::fprintf(stderr, "lagoon sky: --width %s must be a multiple of 4 from 64 to 8192 pixels\n",
                   w->c_str());
      return kExitUsage;
    }
    width = int(*n);
  }
  const auto out = args.get("out");
  if (!out) {
    std::fprintf(stderr, "lagoon sky: give --out DIR (where sky.png, sky.json and the .npy files go)\n");
    return kExitUsage;
  }
  auto scene = load_scene_from_args(args, "sky", overrides);
  if (!scene) return kExitFailure;
  if (scene->sun.elevation_deg < 1.0f)
    return sky_failure("sun.elevation_deg " + std::to_string(scene->sun.elevation_deg) +
                       " is below 1 degree: the clear-sky model has no twilight; give --sun-elevation 1..90");
  const render::SkyLight light = render::sky_light(scene->sun);
  const optics::SkyRadiance sky(scene->sun.elevation_deg);
  const SkyImage image = sky_image(light, width);
  const optics::ToneMapParams fit = fit_tone_map(image);
  auto staged = io::StagedOutput::create(*out);
  if (!staged) return sky_failure(staged.error().message);
  const std::vector<size_t> rgb_shape{size_t(image.height), size_t(image.width), 3};
  if (auto w = io::write_npy(staged->file("sky_rgb.npy"), image.rgb, rgb_shape); !w)
    return sky_failure(w.error().message);
  const int rows = 90 / kSpectralStepDeg, columns = 360 / kSpectralStepDeg;
  const std::vector<size_t> spectral_shape{size_t(rows), size_t(columns), size_t(optics::kSamples)};
  if (auto w =
          io::write_npy(staged->file("sky_spectral.npy"), spectral_grid(sky, rows, columns), spectral_shape);
      !w)
    return sky_failure(w.error().message);
  if (auto w = io::write_png(staged->file("sky.png"), sky_png(image, light, fit)); !w)
    return sky_failure(w.error().message);
  const std::string text = sky_meta(*scene, sky, image, light, fit).dump(2) + "\n";
  if (auto w = io::write_text_atomic(staged->file("sky.json"), text); !w)
    return sky_failure(w.error().message);
  if (auto c = staged->commit(); !c) return sky_failure(c.error().message);
  std::printf(
      "wrote %s: %dx%d sky for the sun %.1f deg up, turbidity %.2f; tone map fitted: L_wa %.3f, "
      "L_white %.3f\n",
      out->c_str(), image.width, image.height, double(scene->sun.elevation_deg), sky.turbidity(),
      fit.world_adaptation_luminance, fit.white_luminance);
  return kExitOk;
}

}  // namespace

const Command& sky_command() {
  static const Command command{
      .spec = {.name = "sky",
               .summary =
                   "Writes the angle-resolved spectral clear sky of Belyaev's Fig. 2 for the scene's sun: "
                   "sky.png in (phi, theta) coordinates, sky_rgb.npy, sky_spectral.npy and sky.json "
                   "with its irradiance against the LUTs' E_sky and a tone map fitted to it.",
               .options = {{"scene", "FILE", "take the sun from this scene (default: all defaults)"},
                           {"out", "DIR",
                            "output folder for sky.png, sky.json, sky_rgb.npy, sky_spectral.npy"},
                           {"sun-elevation", "DEG", "sun elevation (same as --set sun.elevation_deg=DEG)"},
                           {"width", "PX",
                            "image width, a multiple of 4 (default 720: 0.5 deg per pixel); "
                            "the height is a quarter of it"},
                           set_option()},
               .details = "example (the seed's Fig. 2, sun 30 deg above the horizon):\n"
                          "  lagoon sky --sun-elevation 30 --out out/sky\n"},
      .run = run_sky};
  return command;
}

}  // namespace lagoon::cli
