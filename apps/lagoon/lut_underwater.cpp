#include "lut_underwater.h"

#include <algorithm>
#include <cmath>

#include "io/npy.h"
#include "io/png.h"
#include "optics/colour.h"
#include "optics/underwater.h"

namespace lagoon::cli {
namespace {

// Three panels side by side, columns = distance d (left 0), rows = depth z (top 0) on the tables' squared
// axes: a white target seen through the water, the water looking down, the water looking up. Tone-mapped
// (eq. 18) and sRGB-encoded like the LUT previews.
io::Image8 preview(const optics::UnderwaterTable& t) {
  const uint32_t scale = std::max(1u, 128u / t.d_count), w = t.d_count * scale, h = t.z_count * scale;
  io::Image8 image;
  image.width = 3 * w;
  image.height = h;
  image.rgba.resize(size_t{image.width} * image.height * 4);
  const std::vector<float>* panels[] = {&t.target, &t.water_down, &t.water_up};
  const uint32_t channels[] = {4, 3, 3};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const uint32_t panel = x / w;
      const float* v = t.at(*panels[panel], (x % w) / scale, y / scale, channels[panel]);
      const glm::dvec3 rgb = optics::encode_srgb(optics::tone_map(glm::dvec3(v[0], v[1], v[2]), {}));
      uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround(std::clamp(rgb[c], 0.0, 1.0) * 255));
      p[3] = 255;
    }
  return image;
}

nlohmann::json describe(const optics::UnderwaterTable& t) {
  return {{"d_m", t.d_m},
          {"z_m", t.z_m},
          {"kd_luminance_per_m", t.kd_luminance_per_m},
          {"build_ms", t.build_ms},
          {"axes",
           "underwater_target.npy is float32 [d][z][4] = (RGB of a white Lambertian target at depth z seen "
           "from d metres, share of its light that arrives forward-scattered (blurred)); "
           "underwater_water_down.npy and underwater_water_up.npy are float32 [d][z][3]: the light the water "
           "adds along d metres at depth z, looking down and looking up. d_m[i] = d_max (i/(D-1))^2, "
           "z_m[j] = z_max (j/(Z-1))^2 (docs/optics.md, Under the surface)."},
          {"preview",
           "underwater.png: target | water looking down | water looking up; columns = d (left 0), rows = z "
           "(top 0)"}};
}

}  // namespace

Result<nlohmann::json> write_underwater_tables(const optics::LutInputs& inputs,
                                               const io::StagedOutput& staged) {
  auto built = optics::build_underwater_table(inputs);
  if (!built) return built.error();
  const optics::UnderwaterTable& t = *built;
  const std::vector<size_t> rgba{t.d_count, t.z_count, 4}, rgb{t.d_count, t.z_count, 3};
  if (auto w = io::write_npy(staged.file("underwater_target.npy"), t.target, rgba); !w) return w.error();
  if (auto w = io::write_npy(staged.file("underwater_water_down.npy"), t.water_down, rgb); !w)
    return w.error();
  if (auto w = io::write_npy(staged.file("underwater_water_up.npy"), t.water_up, rgb); !w) return w.error();
  if (auto w = io::write_png(staged.file("underwater.png"), preview(t)); !w) return w.error();
  return describe(t);
}

}  // namespace lagoon::cli
