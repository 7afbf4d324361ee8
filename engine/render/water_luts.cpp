#include "render/water_luts.h"

#include <tuple>
#include <vector>

#include "optics/lut.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

Result<WaterLuts> upload_water_luts(vk::Context& ctx, const scene::Scene& scene) {
  auto inputs = optics::lut_inputs(scene.water, scene.sun.elevation_deg);
  if (!inputs) return inputs.error();
  auto lut = optics::build_water_lut(*inputs);
  if (!lut) return lut.error();
  WaterLuts out{.deep_colour = glm::vec3(lut->deep_colour),
                .r_max_m = scene.water.lut_r_max_m,
                .h_max_m = scene.water.lut_h_max_m};
  const uint32_t rn = lut->r_count, hn = lut->h_count;
  std::vector<float> t0(size_t{rn} * hn * 4), t1(size_t{rn} * hn * 4);
  for (uint32_t j = 0; j < hn; ++j)
    for (uint32_t i = 0; i < rn; ++i) {
      const size_t texel = (size_t{j} * rn + i) * 4,
                   src = size_t{i} * hn + j;  // LUT is [r][h]; image rows are h
      for (int c = 0; c < 4; ++c) t0[texel + c] = lut->t0[src * 4 + c];
      for (int c = 0; c < 3; ++c) t1[texel + c] = lut->t1[src * 3 + c];
      t1[texel + 3] = 1.0f;
    }
  for (auto [image, data, name] : {std::tuple{&out.t0, &t0, "lut T0"}, {&out.t1, &t1, "lut T1"}}) {
    *image = vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                     .extent = {rn, hn},
                                     .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     .debug_name = name});
    vk::upload_image(ctx, *image, vk::as_bytes_of(*data), VK_IMAGE_LAYOUT_GENERAL,
                     vk::access::kGraphicsSampled);
  }
  return out;
}

}  // namespace lagoon::render
