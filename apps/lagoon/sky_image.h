// The sky image of Belyaev's Fig. 2 (§5): the clear sky in (φ, θ) coordinates, φ the azimuth from the sun
// (the sun in the middle), θ the zenith angle (0 at the top row, 90° at the bottom). Its pixels are the
// renderer's sky (render/sky_light.h, shared/sky_model.h) in white units, and a tone map fitted to it.
#pragma once
#include <vector>

#include "io/png.h"
#include "optics/colour.h"
#include "render/sky_light.h"

namespace lagoon::cli {

struct SkyImage {
  int width = 0, height = 0;
  std::vector<float> rgb;             // [height][width][3], linear sRGB, white units, without the sun's disc
  std::vector<double> sky_luminance;  // per pixel, white units
  std::vector<double> solid_angle;    // per pixel, sr
};

SkyImage sky_image(const render::SkyLight& light, int width);

// Barladian (2003)-style estimate from the image (docs/optics.md): L_wa the solid-angle weighted log-average
// of the sky's luminance, L_white the L_d at which the brightest 1 % of the sky (by solid angle) reaches
// display white.
optics::ToneMapParams fit_tone_map(const SkyImage& image);

// The image tone-mapped with `params` and sRGB-encoded; the sun's disc drawn where it lies.
io::Image8 sky_png(const SkyImage& image, const render::SkyLight& light, const optics::ToneMapParams& params);

}  // namespace lagoon::cli
