// Meshes and textures on the GPU for the mesh pass (shaders/render/mesh.*): vertex pulling from storage
// buffers, albedo textures in sRGB with mips.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>

#include "io/png.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

struct MeshVertex {  // matches `struct Vertex` in mesh.vert
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec2 uv1{0.0f};                  // TEXCOORD_1
  glm::vec4 tangent{1.0f, 0, 0, 1.0f};  // xyz, w = handedness (gltf/model.h)
};
static_assert(sizeof(MeshVertex) == 56);

struct GpuMesh {
  vk::Buffer vertices, indices;
  uint32_t index_count = 0;
};

GpuMesh upload_mesh(vk::Context& ctx, std::span<const MeshVertex> vertices,
                    std::span<const uint32_t> indices);

// RGBA8 texture with a full mip chain, left in GENERAL layout for sampling: sRGB-encoded colours (base
// colour, emissive) or linear data (normals, metallic-roughness, occlusion).
vk::Image upload_texture(vk::Context& ctx, const io::Image8& image, const char* name, bool srgb = true);

}  // namespace lagoon::render
