// A glTF material as the mesh shader reads it (shared/mesh.h MaterialGpu), and the Vulkan sampler of a
// glTF sampler.
#pragma once
#include <array>

#include "gltf/model.h"
#include "shared/mesh.h"
#include "vk/sampler.h"

namespace lagoon::render {

// The material's five texture slots in LAGOON_TEX_* order (the order of MaterialGpu's bits and uv_rows).
std::array<const gltf::TextureRef*, LAGOON_TEX_COUNT> texture_slots(const gltf::Material& material);

// Which textures are present is left to the caller (flags.y): a texture may be missing from the file.
gpu::MaterialGpu material_gpu(const gltf::Material& material);

// The material glTF prescribes for primitives without one (metallic 1, roughness 1, white) would draw
// untextured models as grey metal; Lagoon's default is a white rough dielectric, as before materials.
gpu::MaterialGpu default_material_gpu();

vk::SamplerDesc sampler_desc(const gltf::Sampler& sampler);

}  // namespace lagoon::render
