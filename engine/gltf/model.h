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
  std::vector<uint32_t> indices;  // generated 0..n-1 when the file has none; every index < positions.size()
  int material = -1;              // index into Model::materials, -1 = default material
};

// Decoded RGBA8, width*height*4 bytes. Base colour textures hold sRGB-encoded values: sample them through
// an _SRGB format.
struct Texture {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

struct Material {
  glm::vec4 base_color_factor{1.0f};  // linear, multiplies the texture
  int base_color_texture = -1;        // index into Model::textures, -1 = none
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
  std::vector<Texture> textures;  // only the images some material uses as base colour, each once
  std::vector<Instance> instances;
  std::vector<Camera> cameras;             // one per camera node of the default scene, in depth-first order
  std::vector<Light> lights;               // one per KHR_lights_punctual light node of the default scene
  glm::vec3 bounds_min{0}, bounds_max{0};  // of all instances in world space; zero when there are none
  // One per unsupported feature kind (e.g. "skins are not supported; drawn in bind pose"), not per
  // occurrence: the model still loads, but looks different from what its author saw.
  std::vector<std::string> warnings;
};

}  // namespace lagoon::gltf
