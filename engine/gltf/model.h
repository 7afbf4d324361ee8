// Plain data of a loaded glTF 2.0 model: what the renderer uploads. Nothing here depends on tinygltf, so
// only engine/gltf/gltf_loader.cpp sees the parser.
//
// Conventions are glTF's, which are also Lagoon's: right-handed, +Y up, metres; triangles wind
// counter-clockwise when seen from the front; UV (0,0) is the top-left of the image and Texture rows are
// stored top row first (what Vulkan samples with no flip).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lagoon::gltf {

struct Primitive {                   // triangles only (strips and fans are converted to lists)
  std::vector<glm::vec3> positions;  // model space, metres
  std::vector<glm::vec3> normals;    // generated (area-weighted) when the file has none
  std::vector<glm::vec2> uvs;        // TEXCOORD_0; zero when the file has none
  std::vector<glm::vec2> uvs1;       // TEXCOORD_1; a copy of TEXCOORD_0 when the file has none
  // xyz along +u in the surface, w = ±1 the handedness (bitangent = w · normal × tangent): the file's
  // TANGENT, else generated from TEXCOORD_0 (gltf/tangents.h) when a material has a normal map.
  std::vector<glm::vec4> tangents;
  std::vector<uint32_t> indices;  // generated 0..n-1 when the file has none; every index < positions.size()
  int material = -1;              // index into Model::materials, -1 = default material
};

// Decoded RGBA8, width*height*4 bytes. Base colour textures hold sRGB-encoded values: sample them through
// an _SRGB format.
struct Texture {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

// A glTF sampler: how a texture is filtered and wrapped (defaults as glTF's when the file gives none).
struct Sampler {
  enum class Wrap { Repeat, MirroredRepeat, ClampToEdge };
  enum class Filter { Nearest, Linear };
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  Filter mag = Filter::Linear, min = Filter::Linear;
  bool mipmaps = true;          // false: minFilter NEAREST or LINEAR (no mip levels sampled)
  Filter mip = Filter::Linear;  // between mip levels
  bool operator==(const Sampler&) const = default;
};

// A material's use of a texture: glTF textureInfo with its sampler and KHR_texture_transform.
struct TextureRef {
  int image = -1;    // index into Model::textures, -1 = none
  int texcoord = 0;  // 0 or 1: TEXCOORD_0 or TEXCOORD_1
  Sampler sampler;
  // KHR_texture_transform as uv' = transform · (u, v, 1): translation · rotation · scale, in the
  // extension's order (its rotation turns uv counter-clockwise as the spec's matrix does).
  glm::mat3 transform{1.0f};
};

struct Material {
  enum class AlphaMode { Opaque, Mask, Blend };
  glm::vec4 base_color_factor{1.0f};  // linear, multiplies the texture (sRGB)
  TextureRef base_color;
  float metallic = 1.0f, roughness = 1.0f;  // glTF's defaults
  TextureRef metallic_roughness;            // B = metallic, G = roughness (linear)
  TextureRef normal;                        // tangent-space normal map (linear)
  float normal_scale = 1.0f;
  TextureRef occlusion;  // R = ambient occlusion (linear)
  float occlusion_strength = 1.0f;
  glm::vec3 emissive_factor{0.0f};  // linear; times KHR_materials_emissive_strength
  TextureRef emissive;              // sRGB
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;  // MASK: drawn where alpha >= cutoff
  bool double_sided = false;
  std::string name;
};

struct Mesh {
  std::vector<Primitive> primitives;
  std::string name;
};

struct Instance {  // one node of the default scene that has a mesh; the hierarchy is flattened
  uint32_t mesh = 0;
  glm::mat4 world{1.0f};
};

// A camera node of the default scene (glTF's camera looks down its local −Z with +Y up).
struct Camera {
  std::string name;         // the camera's name, else its node's, else "cameras[i]"
  std::string node_name;    // the node's name ("" if none)
  glm::mat4 world{1.0f};    // the node's world transform
  bool perspective = true;  // false: orthographic
  float yfov_rad = 0.8f;    // perspective: vertical field of view
  float znear = 0.1f;       // perspective: near plane, metres
  float zfar = 0.0f;        // perspective: far plane, metres (0 = infinite)
};

// A KHR_lights_punctual light on a node of the default scene. Units are glTF's: point and spot lights in
// candela (lm/sr), directional lights in lux; colour linear RGB.
struct Light {
  enum class Type { Point, Spot, Directional };
  std::string name;  // the light's name, else its node's, else "lights[i]"
  Type type = Type::Point;
  glm::vec3 colour{1.0f};
  float intensity = 1.0f;
  float range_m = 0.0f;                                      // 0 = infinite
  float inner_cone_rad = 0.0f, outer_cone_rad = 0.7853982f;  // spot lights
  glm::mat4 world{1.0f};  // its node's; the light sits at the origin and shines down −z
};

struct Model {
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;  // only the images some material uses, each once
  std::vector<Instance> instances;
  std::vector<Camera> cameras;             // one per camera node of the default scene, in depth-first order
  std::vector<Light> lights;               // one per KHR_lights_punctual light node of the default scene
  glm::vec3 bounds_min{0}, bounds_max{0};  // of all instances in world space; zero when there are none
  // One per unsupported feature kind (e.g. "skins are not supported; drawn in bind pose"), not per
  // occurrence: the model still loads, but looks different from what its author saw.
  std::vector<std::string> warnings;
};

}  // namespace lagoon::gltf
