#include "render/mesh_material.h"

namespace lagoon::render {
namespace {

void set_transform(gpu::MaterialGpu& out, int slot, const gltf::TextureRef& ref) {
  const glm::mat3& t = ref.transform;  // column-major: t[column][row]
  out.uv_rows[2 * slot] = glm::vec4(t[0][0], t[1][0], t[2][0], 0.0f);
  out.uv_rows[2 * slot + 1] = glm::vec4(t[0][1], t[1][1], t[2][1], 0.0f);
  if (ref.texcoord == 1) out.flags.z |= 1u << slot;
}

}  // namespace

gpu::MaterialGpu material_gpu(const gltf::Material& m) {
  gpu::MaterialGpu out{};
  out.base_colour = m.base_color_factor;
  out.emissive = glm::vec4(m.emissive_factor, m.alpha_cutoff);
  out.pbr = glm::vec4(m.metallic, m.roughness, m.normal_scale, m.occlusion_strength);
  out.flags = glm::uvec4(m.alpha_mode == gltf::Material::AlphaMode::Mask    ? LAGOON_ALPHA_MASK
                         : m.alpha_mode == gltf::Material::AlphaMode::Blend ? LAGOON_ALPHA_BLEND
                                                                            : LAGOON_ALPHA_OPAQUE,
                         0u, 0u, m.double_sided ? 1u : 0u);
  const auto slots = texture_slots(m);
  for (int i = 0; i < LAGOON_TEX_COUNT; ++i) set_transform(out, i, *slots[size_t(i)]);
  return out;
}

std::array<const gltf::TextureRef*, LAGOON_TEX_COUNT> texture_slots(const gltf::Material& m) {
  return {&m.base_color, &m.metallic_roughness, &m.normal, &m.occlusion, &m.emissive};
}

gpu::MaterialGpu default_material_gpu() {
  gltf::Material m;
  m.metallic = 0.0f;
  m.double_sided = true;  // models without materials were drawn from both sides before materials
  return material_gpu(m);
}

vk::SamplerDesc sampler_desc(const gltf::Sampler& s) {
  auto address = [](gltf::Sampler::Wrap w) {
    return w == gltf::Sampler::Wrap::ClampToEdge      ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
           : w == gltf::Sampler::Wrap::MirroredRepeat ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                                      : VK_SAMPLER_ADDRESS_MODE_REPEAT;
  };
  auto filter = [](gltf::Sampler::Filter f) {
    return f == gltf::Sampler::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  };
  return {.filter = filter(s.mag),
          .mipmap = s.mip == gltf::Sampler::Filter::Nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                            : VK_SAMPLER_MIPMAP_MODE_LINEAR,
          .address = address(s.wrap_s),
          .address_v = address(s.wrap_t),
          .min_filter = filter(s.min),
          .mip_levels = s.mipmaps};
}

}  // namespace lagoon::render
