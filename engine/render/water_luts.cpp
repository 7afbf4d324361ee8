#include "render/water_luts.h"

#include <vector>

#include "ocean/slope_statistics.h"
#include "optics/lut.h"
#include "optics/underwater.h"
#include "render/passes/caustics_pass.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

namespace {

vk::Image upload_rgba(vk::Context& ctx, uint32_t width, uint32_t height, const std::vector<float>& data,
                      const char* name) {
  vk::Image image =
      vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                              .extent = {width, height},
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              .debug_name = name});
  vk::upload_image(ctx, image, vk::as_bytes_of(data), VK_IMAGE_LAYOUT_GENERAL, vk::access::kGraphicsSampled);
  return image;
}

// A table stored [x][y][channels] as an RGBA image with x along rows (alpha 1 where it has 3 channels).
std::vector<float> as_rgba(const std::vector<float>& table, uint32_t nx, uint32_t ny, uint32_t channels) {
  std::vector<float> out(size_t{nx} * ny * 4, 1.0f);
  for (uint32_t j = 0; j < ny; ++j)
    for (uint32_t i = 0; i < nx; ++i)
      for (uint32_t c = 0; c < channels; ++c)
        out[(size_t{j} * nx + i) * 4 + c] = table[(size_t{i} * ny + j) * channels + c];
  return out;
}

Result<void> upload_underwater(vk::Context& ctx, const optics::LutInputs& inputs, WaterLuts& out) {
  auto table = optics::build_underwater_table(inputs);
  if (!table) return table.error();
  const uint32_t dn = table->d_count, zn = table->z_count;
  out.uw_target = upload_rgba(ctx, dn, zn, as_rgba(table->target, dn, zn, 4), "underwater target");
  out.underwater_top = glm::vec3(table->target[0], table->target[1], table->target[2]);
  out.uw_down = upload_rgba(ctx, dn, zn, as_rgba(table->water_down, dn, zn, 3), "underwater water down");
  out.uw_up = upload_rgba(ctx, dn, zn, as_rgba(table->water_up, dn, zn, 3), "underwater water up");
  const int green = (550 - optics::kLambdaMinNm) / optics::kLambdaStepNm;
  out.scattering_550 = float(inputs.water.scattering_per_m[green]);
  out.phase_g_550 = float(optics::phase_x1_at(inputs, green) / 3.0);
  out.d_max_m = table->d_m.back();
  out.z_max_m = table->z_m.back();
  const glm::vec4 depths = CausticsWindow{}.depths;
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    auto s = optics::underwater_sample(inputs, 0.0, depths[k]);
    if (!s) return s.error();
    out.caustic_share[k] = float(s->direct_share);
  }
  return {};
}

}  // namespace

Result<optics::LutInputs> scene_lut_inputs(const scene::Scene& scene,
                                           const std::vector<ocean::CascadeSpectrum>* spectra) {
  const ocean::SlopeMoments m =
      spectra ? ocean::sea_slope_moments(scene.ocean, *spectra) : ocean::sea_slope_moments(scene.ocean);
  return optics::lut_inputs(scene.water, scene.sun.elevation_deg, {}, {.xx = m.xx, .zz = m.zz, .xz = m.xz});
}

Result<WaterLuts> upload_water_luts(vk::Context& ctx, const scene::Scene& scene,
                                    const std::vector<ocean::CascadeSpectrum>* spectra) {
  auto inputs = scene_lut_inputs(scene, spectra);
  if (!inputs) return inputs.error();
  auto lut = optics::build_water_lut(*inputs);
  if (!lut) return lut.error();
  WaterLuts out{.deep_colour = glm::vec3(lut->deep_colour),
                .r_max_m = scene.water.lut_r_max_m,
                .h_max_m = scene.water.lut_h_max_m};
  const uint32_t rn = lut->r_count, hn = lut->h_count;
  out.t0 = upload_rgba(ctx, rn, hn, as_rgba(lut->t0, rn, hn, 4), "lut T0");
  out.t1 = upload_rgba(ctx, rn, hn, as_rgba(lut->t1, rn, hn, 3), "lut T1");
  if (auto uw = upload_underwater(ctx, *inputs, out); !uw) return uw.error();
  return out;
}

}  // namespace lagoon::render
