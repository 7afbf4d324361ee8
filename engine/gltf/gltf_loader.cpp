#include "gltf/gltf_loader.h"

// The one translation unit that compiles tinygltf and the only one that sees its types. Images are decoded
// by gltf/image_decode.cpp (PNG/JPEG only, size-limited) and files are read through the sandbox below, so
// tinygltf's own stb and file system code are left out.
//
// tinygltf's (unused) writer needs <fstream> but includes it only along with its file system code.
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_FS
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <new>
#include <span>
#include <string>
#include <system_error>
#include <utility>

#include "gltf/accessor.h"
#include "gltf/checks.h"
#include "gltf/geometry.h"
#include "gltf/glb.h"
#include "gltf/image_decode.h"
#include "gltf/nodes.h"
#include "gltf/prescan.h"
#include "gltf/primitive.h"
#include "gltf/read_file.h"

namespace lagoon::gltf {
namespace {

namespace fs = std::filesystem;
using detail::at;
using detail::valid_index;
using detail::warn_once;

// ---- Sandboxed file access for tinygltf ------------------------------------------------------------------

// tinygltf may open exactly the files the prescan resolved inside the model's folder, nothing else (it
// also tries every URI relative to the working directory, which this shuts off too).
struct Sandbox {
  std::vector<fs::path> allowed;
  size_t max_bytes = 0;

  bool allows(const std::string& path) const {
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(path, ec);
    return !ec && std::find(allowed.begin(), allowed.end(), resolved) != allowed.end();
  }
};

bool sandbox_exists(const std::string& path, void* user) {
  return static_cast<Sandbox*>(user)->allows(path);
}

std::string sandbox_expand(const std::string& path, void*) {
  return path;
}  // no ~ or $VAR expansion

bool sandbox_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* sandbox = static_cast<Sandbox*>(user);
  if (!sandbox->allows(path)) {
    if (err) *err = "outside the files the model may read";
    return false;
  }
  Result<std::vector<uint8_t>> bytes = detail::read_file(path, sandbox->max_bytes);
  if (!bytes) {
    if (err) *err = bytes.error().message;
    return false;
  }
  *out = std::move(*bytes);
  return true;
}

bool sandbox_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err = "the loader never writes files";
  return false;
}

// Encoded image bytes are kept for decode_image, which only runs for images a material uses. Images in a
// bufferView are read later from the checked bufferView, not through the pointer tinygltf passes here.
bool keep_encoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void*) {
  if (image->bufferView == -1 && bytes && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// tinygltf's messages end in newlines and may quote a whole data: URI; keep them readable.
std::string tidy(const std::string& message) {
  constexpr size_t kMaxLine = 300;
  std::string out, line;
  auto flush = [&] {
    if (line.empty()) return;
    if (line.size() > kMaxLine) line = line.substr(0, kMaxLine) + "...";
    out += (out.empty() ? "" : "; ") + line;
    line.clear();
  };
  for (char c : message) {
    if (c == '\n' || c == '\r') {
      flush();
    } else {
      line += c;
    }
  }
  flush();
  return out.empty() ? "tinygltf gave no reason" : out;
}

// ---- tinygltf model to plain structs ---------------------------------------------------------------------

void warn_extensions(const tinygltf::ExtensionMap& extensions, std::vector<std::string>& warnings) {
  for (const auto& [name, value] : extensions) {
    if (!detail::supported_extension(name))
      warn_once(warnings, "extension '" + name + "' is not supported; ignored");
  }
}

void warn_unsupported(const tinygltf::Model& g, std::vector<std::string>& warnings) {
  bool skins = !g.skins.empty(), morphs = false;
  for (const tinygltf::Node& n : g.nodes) {
    skins |= n.skin != -1;
    morphs |= !n.weights.empty();
    warn_extensions(n.extensions, warnings);
  }
  for (const tinygltf::Mesh& m : g.meshes) morphs |= !m.weights.empty();
  if (skins) warn_once(warnings, "skins are not supported; drawn in bind pose");
  if (!g.animations.empty()) warn_once(warnings, "animations are not supported; drawn in the rest pose");
  if (morphs) warn_once(warnings, "morph targets are not supported; drawn with the base geometry");
  warn_extensions(g.extensions, warnings);
}

// bufferViews checked against their buffers, accessors copied as plain descriptions.
Result<detail::Accessors> build_accessors(const tinygltf::Model& g) {
  detail::Accessors a;
  for (size_t i = 0; i < g.bufferViews.size(); ++i) {
    const tinygltf::BufferView& v = g.bufferViews[i];
    const std::string where = at("bufferViews", static_cast<int64_t>(i));
    if (!valid_index(v.buffer, g.buffers.size())) {
      return make_error(where + ".buffer: buffers[" + std::to_string(v.buffer) + "] does not exist");
    }
    const tinygltf::Buffer& b = g.buffers[static_cast<size_t>(v.buffer)];
    size_t end = 0;
    if (!detail::mul_add(1, v.byteOffset, v.byteLength, &end) || end > b.data.size()) {
      return make_error(where + ": byteOffset " + std::to_string(v.byteOffset) + " + byteLength " +
                        std::to_string(v.byteLength) + " is past the end of " + at("buffers", v.buffer) +
                        " (" + std::to_string(b.data.size()) + " bytes)");
    }
    a.views.push_back({b.data.data() + v.byteOffset, v.byteLength, v.byteStride});
  }
  for (const tinygltf::Accessor& t : g.accessors) {
    detail::AccessorDesc d;
    d.view = t.bufferView;
    d.byte_offset = t.byteOffset;
    d.count = t.count;
    d.component_type = t.componentType;
    d.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(t.type));
    d.normalized = t.normalized;
    if (t.sparse.isSparse) {
      d.sparse = detail::Sparse{t.sparse.count,
                                t.sparse.indices.bufferView,
                                t.sparse.indices.byteOffset,
                                t.sparse.indices.componentType,
                                t.sparse.values.bufferView,
                                t.sparse.values.byteOffset};
    }
    a.accessors.push_back(d);
  }
  return a;
}

// ---- Materials -------------------------------------------------------------------------------------------

bool finite_all(const std::vector<double>& v, size_t n) {
  return v.size() == n && std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// A number of an extension object, `fallback` when absent; an error when present but not a finite number.
Result<double> ext_number(const tinygltf::Value& object, const char* key, double fallback,
                          const std::string& where) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
    return make_error(where + "." + key + ": expected a finite number");
  return v.GetNumberAsDouble();
}

Result<glm::vec2> ext_vec2(const tinygltf::Value& object, const char* key, glm::vec2 fallback,
                           const std::string& where) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber() ||
      !std::isfinite(v.Get(0).GetNumberAsDouble()) || !std::isfinite(v.Get(1).GetNumberAsDouble()))
    return make_error(where + "." + key + ": expected 2 finite numbers");
  return glm::vec2(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
}

Sampler::Filter filter_of(int gl) {
  return gl == 9728 || gl == 9984 || gl == 9986 ? Sampler::Filter::Nearest : Sampler::Filter::Linear;
}

Sampler::Wrap wrap_of(int gl) {
  if (gl == 33071) return Sampler::Wrap::ClampToEdge;
  if (gl == 33648) return Sampler::Wrap::MirroredRepeat;
  return Sampler::Wrap::Repeat;
}

// glTF sampler (GL enums) to ours; absent filters are linear with mipmaps, as most viewers do.
Result<Sampler> convert_sampler(const tinygltf::Sampler& s, const std::string& where) {
  auto known = [](int v, std::initializer_list<int> allowed) {
    return v == -1 || std::find(allowed.begin(), allowed.end(), v) != allowed.end();
  };
  if (!known(s.magFilter, {9728, 9729})) return make_error(where + ".magFilter: must be 9728 or 9729");
  if (!known(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}))
    return make_error(where + ".minFilter: must be 9728, 9729 or 9984-9987");
  if (!known(s.wrapS, {10497, 33071, 33648}) || !known(s.wrapT, {10497, 33071, 33648}))
    return make_error(where + ".wrapS/wrapT: must be 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648");
  Sampler out;
  out.wrap_s = wrap_of(s.wrapS);
  out.wrap_t = wrap_of(s.wrapT);
  out.mag = filter_of(s.magFilter);
  out.min = filter_of(s.minFilter);
  out.mipmaps = s.minFilter == -1 || s.minFilter >= 9984;
  out.mip = s.minFilter == 9984 || s.minFilter == 9985 ? Sampler::Filter::Nearest : Sampler::Filter::Linear;
  return out;
}

// KHR_texture_transform of a textureInfo into ref.transform (and its texCoord override).
Result<void> texture_transform(const tinygltf::ExtensionMap& extensions, const std::string& where,
                               TextureRef& ref) {
  const auto it = extensions.find("KHR_texture_transform");
  if (it == extensions.end()) return {};
  const tinygltf::Value& t = it->second;
  const std::string at_ext = where + ".extensions.KHR_texture_transform";
  if (!t.IsObject()) return make_error(at_ext + ": expected an object");
  Result<glm::vec2> offset = ext_vec2(t, "offset", glm::vec2(0), at_ext);
  Result<glm::vec2> scale = ext_vec2(t, "scale", glm::vec2(1), at_ext);
  Result<double> rotation = ext_number(t, "rotation", 0, at_ext);
  Result<double> texcoord = ext_number(t, "texCoord", ref.texcoord, at_ext);
  if (!offset) return offset.error();
  if (!scale) return scale.error();
  if (!rotation) return rotation.error();
  if (!texcoord) return texcoord.error();
  const float c = float(std::cos(*rotation)), s = float(std::sin(*rotation));
  ref.transform = glm::mat3(glm::vec3(scale->x * c, -scale->x * s, 0),
                            glm::vec3(scale->y * s, scale->y * c, 0), glm::vec3(offset->x, offset->y, 1));
  ref.texcoord = int(*texcoord);
  return {};
}

// The image a texture shows: EXT_texture_webp's source when the texture has one (Lagoon decodes WebP, so the
// PNG or JPEG a file may give as texture.source for other viewers is its fallback), else texture.source.
Result<int> texture_source(const tinygltf::Texture& texture, const std::string& where) {
  const auto it = texture.extensions.find("EXT_texture_webp");
  if (it == texture.extensions.end()) return texture.source;
  const tinygltf::Value& source = it->second.Get("source");
  if (!source.IsInt() && !source.IsNumber())
    return make_error(where + ".extensions.EXT_texture_webp.source: missing or not an image index");
  const double value = source.GetNumberAsDouble();
  if (!(value >= 0.0 && value <= 2147483647.0) || value != static_cast<double>(static_cast<int>(value)))
    return make_error(where + ".extensions.EXT_texture_webp.source: " + std::to_string(value) +
                      " is not an image index");
  return static_cast<int>(value);
}

// One textureInfo (`where` names it, e.g. "materials[0].normalTexture") into a TextureRef; the image it
// uses is given a slot in `image_slots` (image index -> Model::textures index).
Result<TextureRef> texture_ref(const tinygltf::Model& g, int index, int texcoord,
                               const tinygltf::ExtensionMap& extensions, const std::string& where,
                               std::map<int, int>& image_slots, std::vector<std::string>& warnings) {
  TextureRef ref;
  if (index == -1) return ref;
  if (!valid_index(index, g.textures.size())) {
    return make_error(where + ".index: textures[" + std::to_string(index) +
                      "] does not exist (the file has " + std::to_string(g.textures.size()) + ")");
  }
  const tinygltf::Texture& texture = g.textures[static_cast<size_t>(index)];
  warn_extensions(texture.extensions, warnings);
  warn_extensions(extensions, warnings);
  ref.texcoord = texcoord;
  if (Result<void> r = texture_transform(extensions, where, ref); !r) return r.error();
  if (ref.texcoord < 0 || ref.texcoord > 1) {
    warn_once(warnings, "texture coordinate sets above TEXCOORD_1 are not supported; TEXCOORD_0 is used");
    ref.texcoord = 0;
  }
  if (texture.sampler != -1) {
    if (!valid_index(texture.sampler, g.samplers.size()))
      return make_error(at("textures", index) + ".sampler: samplers[" + std::to_string(texture.sampler) +
                        "] does not exist");
    Result<Sampler> sampler =
        convert_sampler(g.samplers[size_t(texture.sampler)], at("samplers", texture.sampler));
    if (!sampler) return sampler.error();
    ref.sampler = *sampler;
  }
  Result<int> source = texture_source(texture, at("textures", index));
  if (!source) return source.error();
  if (*source == -1) {
    warn_once(warnings, "textures without an image are not supported; drawn untextured");
  } else if (!valid_index(*source, g.images.size())) {
    return make_error(at("textures", index) +
                      (*source == texture.source ? "" : ".extensions.EXT_texture_webp") + ".source: images[" +
                      std::to_string(*source) + "] does not exist");
  } else {
    auto [slot, added] = image_slots.try_emplace(*source, static_cast<int>(image_slots.size()));
    ref.image = slot->second;
  }
  return ref;
}

// The scalar factors of a material, checked against the ranges the spec gives.
Result<void> material_factors(const tinygltf::Material& m, const std::string& where, Material& out) {
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  if (!finite_all(pbr.baseColorFactor, 4))
    return make_error(where + ".pbrMetallicRoughness.baseColorFactor: expected 4 finite numbers");
  out.base_color_factor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2],
                                    pbr.baseColorFactor[3]);
  auto unit = [&](double v, const std::string& field) -> Result<float> {
    if (!(v >= 0.0 && v <= 1.0)) return make_error(where + "." + field + ": must be between 0 and 1");
    return float(v);
  };
  Result<float> metallic = unit(pbr.metallicFactor, "pbrMetallicRoughness.metallicFactor");
  Result<float> roughness = unit(pbr.roughnessFactor, "pbrMetallicRoughness.roughnessFactor");
  Result<float> strength = unit(m.occlusionTexture.strength, "occlusionTexture.strength");
  if (!metallic) return metallic.error();
  if (!roughness) return roughness.error();
  if (!strength) return strength.error();
  out.metallic = *metallic;
  out.roughness = *roughness;
  out.occlusion_strength = *strength;
  if (!std::isfinite(m.normalTexture.scale))
    return make_error(where + ".normalTexture.scale: expected a finite number");
  out.normal_scale = float(m.normalTexture.scale);
  if (!finite_all(m.emissiveFactor, 3) ||
      std::any_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), [](double v) { return v < 0; }))
    return make_error(where + ".emissiveFactor: expected 3 numbers >= 0");
  float emissive_strength = 1.0f;
  if (auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
    const std::string at_ext = where + ".extensions.KHR_materials_emissive_strength";
    Result<double> e = ext_number(it->second, "emissiveStrength", 1.0, at_ext);
    if (!e) return e.error();
    if (*e < 0) return make_error(at_ext + ".emissiveStrength: must be >= 0");
    emissive_strength = float(*e);
  }
  out.emissive_factor =
      glm::vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]) * emissive_strength;
  if (m.alphaMode == "MASK") {
    out.alpha_mode = Material::AlphaMode::Mask;
  } else if (m.alphaMode == "BLEND") {
    out.alpha_mode = Material::AlphaMode::Blend;
  } else if (m.alphaMode != "OPAQUE") {
    return make_error(where + ".alphaMode: '" + m.alphaMode + "' is not OPAQUE, MASK or BLEND");
  }
  if (!(m.alphaCutoff >= 0.0) || !std::isfinite(m.alphaCutoff))
    return make_error(where + ".alphaCutoff: must be a number >= 0");
  out.alpha_cutoff = float(m.alphaCutoff);
  out.double_sided = m.doubleSided;
  return {};
}

// Materials, and the images their textures use (image index -> Model::textures index).
Result<std::vector<Material>> convert_materials(const tinygltf::Model& g, std::map<int, int>& image_slots,
                                                std::vector<std::string>& warnings) {
  std::vector<Material> materials;
  for (size_t i = 0; i < g.materials.size(); ++i) {
    const tinygltf::Material& m = g.materials[i];
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    const std::string where = at("materials", static_cast<int64_t>(i));
    Material out;
    out.name = m.name;
    if (Result<void> r = material_factors(m, where, out); !r) return r.error();
    struct Slot {
      TextureRef* ref;
      int index, texcoord;
      const tinygltf::ExtensionMap* extensions;
      const char* field;
    };
    for (const Slot& t :
         {Slot{&out.base_color, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
               &pbr.baseColorTexture.extensions, ".pbrMetallicRoughness.baseColorTexture"},
          Slot{&out.metallic_roughness, pbr.metallicRoughnessTexture.index,
               pbr.metallicRoughnessTexture.texCoord, &pbr.metallicRoughnessTexture.extensions,
               ".pbrMetallicRoughness.metallicRoughnessTexture"},
          Slot{&out.normal, m.normalTexture.index, m.normalTexture.texCoord, &m.normalTexture.extensions,
               ".normalTexture"},
          Slot{&out.occlusion, m.occlusionTexture.index, m.occlusionTexture.texCoord,
               &m.occlusionTexture.extensions, ".occlusionTexture"},
          Slot{&out.emissive, m.emissiveTexture.index, m.emissiveTexture.texCoord,
               &m.emissiveTexture.extensions, ".emissiveTexture"}}) {
      Result<TextureRef> ref =
          texture_ref(g, t.index, t.texcoord, *t.extensions, where + t.field, image_slots, warnings);
      if (!ref) return ref.error();
      *t.ref = *ref;
    }
    warn_extensions(m.extensions, warnings);
    materials.push_back(std::move(out));
  }
  return materials;
}

Result<std::vector<Texture>> decode_textures(const tinygltf::Model& g, const detail::Accessors& a,
                                             const std::map<int, int>& image_slots, const Limits& limits) {
  if (image_slots.size() > limits.max_textures) {
    return make_error("materials: " + std::to_string(image_slots.size()) +
                      " images is more than the limit of " + std::to_string(limits.max_textures) +
                      " textures");
  }
  std::vector<Texture> textures(image_slots.size());
  for (const auto& [image_index, slot] : image_slots) {
    const tinygltf::Image& image = g.images[static_cast<size_t>(image_index)];
    std::string where = at("images", image_index);
    if (!image.name.empty()) where += " '" + image.name + "'";
    std::span<const uint8_t> bytes;
    if (image.bufferView != -1) {
      if (!valid_index(image.bufferView, a.views.size())) {
        return make_error(where + ".bufferView: bufferViews[" + std::to_string(image.bufferView) +
                          "] does not exist");
      }
      const detail::View& view = a.views[static_cast<size_t>(image.bufferView)];
      bytes = {view.data, view.size};
    } else if (!image.image.empty()) {
      bytes = image.image;
    } else {
      return make_error(where + ": the image '" + image.uri + "' could not be read");
    }
    Result<Texture> texture = detail::decode_image(bytes, where, limits.max_texture_size);
    if (!texture) return texture.error();
    textures[static_cast<size_t>(slot)] = std::move(*texture);
  }
  return textures;
}

Result<std::vector<Mesh>> convert_meshes(const tinygltf::Model& g, const detail::Accessors& a,
                                         size_t material_count, const Limits& limits,
                                         std::vector<std::string>& warnings) {
  detail::Budget budget{limits.max_vertices, limits.max_indices};
  const bool quantized = std::find(g.extensionsUsed.begin(), g.extensionsUsed.end(),
                                   "KHR_mesh_quantization") != g.extensionsUsed.end();
  std::vector<Mesh> meshes;
  for (size_t m = 0; m < g.meshes.size(); ++m) {
    Mesh mesh;
    mesh.name = g.meshes[m].name;
    for (size_t p = 0; p < g.meshes[m].primitives.size(); ++p) {
      const tinygltf::Primitive& t = g.meshes[m].primitives[p];
      warn_extensions(t.extensions, warnings);
      const detail::PrimitiveDesc desc{t.attributes, t.indices,          t.mode,
                                       t.material,   !t.targets.empty(), quantized};
      const std::string where =
          at("meshes", static_cast<int64_t>(m)) + at(".primitives", static_cast<int64_t>(p));
      Result<std::optional<Primitive>> prim =
          detail::convert_primitive(desc, where, a, material_count, budget, warnings);
      if (!prim) return prim.error();
      if (*prim) mesh.primitives.push_back(std::move(**prim));
    }
    meshes.push_back(std::move(mesh));
  }
  return meshes;
}

// The light a node carries through KHR_lights_punctual, -1 for none; a malformed reference is an error.
Result<int> node_light(const tinygltf::Node& n, const std::string& where) {
  const auto ext = n.extensions.find("KHR_lights_punctual");
  if (ext == n.extensions.end()) return -1;
  if (!ext->second.IsObject() || !ext->second.Has("light") || !ext->second.Get("light").IsNumber()) {
    return make_error(where + ".extensions.KHR_lights_punctual: needs a \"light\" index");
  }
  const double index = ext->second.Get("light").GetNumberAsDouble();
  if (!(index >= 0 && index < 1e9) || index != std::floor(index)) {
    return make_error(where + ".extensions.KHR_lights_punctual.light: " + std::to_string(index) +
                      " is not an index");
  }
  return static_cast<int>(index);
}

Result<std::vector<Instance>> convert_nodes(const tinygltf::Model& g, const Limits& limits,
                                            detail::Attachments& attached) {
  if (g.nodes.size() > limits.max_nodes) {
    return make_error("nodes: " + std::to_string(g.nodes.size()) + " nodes is more than the limit of " +
                      std::to_string(limits.max_nodes));
  }
  std::vector<detail::NodeDesc> nodes;
  nodes.reserve(g.nodes.size());
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    const tinygltf::Node& n = g.nodes[i];
    Result<int> light = node_light(n, at("nodes", static_cast<int64_t>(i)));
    if (!light) return light.error();
    nodes.push_back({n.children, n.mesh, n.matrix, n.translation, n.rotation, n.scale, n.camera, *light});
  }
  attached.camera_count = g.cameras.size();
  attached.light_count = g.lights.size();
  if (g.scenes.empty())
    return detail::flatten_nodes(nodes, std::nullopt, "nodes", g.meshes.size(), &attached);
  const int scene = g.defaultScene == -1 ? 0 : g.defaultScene;
  if (!valid_index(scene, g.scenes.size())) {
    return make_error("scene: scenes[" + std::to_string(scene) + "] does not exist");
  }
  return detail::flatten_nodes(nodes, g.scenes[static_cast<size_t>(scene)].nodes,
                               at("scenes", scene) + ".nodes", g.meshes.size(), &attached);
}

// The camera nodes as Model::cameras; a perspective camera's numbers are checked as the spec requires.
Result<std::vector<Camera>> convert_cameras(const tinygltf::Model& g,
                                            const std::vector<detail::AttachedNode>& nodes) {
  std::vector<Camera> cameras;
  for (const detail::AttachedNode& c : nodes) {
    const tinygltf::Camera& t = g.cameras[static_cast<size_t>(c.index)];
    const std::string where = at("cameras", c.index);
    Camera out;
    out.node_name = g.nodes[static_cast<size_t>(c.node)].name;
    out.name = !t.name.empty() ? t.name : !out.node_name.empty() ? out.node_name : where;
    out.world = glm::mat4(c.world);
    out.perspective = t.type != "orthographic";
    if (out.perspective) {
      const tinygltf::PerspectiveCamera& pc = t.perspective;
      if (!(pc.yfov > 0.0 && pc.yfov < 3.14159265358979)) {
        return make_error(where + ".perspective.yfov: " + std::to_string(pc.yfov) +
                          " is not an angle between 0 and pi radians");
      }
      if (!(pc.znear > 0.0)) {
        return make_error(where + ".perspective.znear: " + std::to_string(pc.znear) + " must be above 0");
      }
      if (pc.zfar != 0.0 && !(pc.zfar > pc.znear)) {
        return make_error(where + ".perspective.zfar: " + std::to_string(pc.zfar) + " must exceed znear " +
                          std::to_string(pc.znear));
      }
      out.yfov_rad = float(pc.yfov);
      out.znear = float(pc.znear);
      out.zfar = float(pc.zfar);
    }
    cameras.push_back(std::move(out));
  }
  return cameras;
}

// The light nodes as Model::lights, their numbers checked as KHR_lights_punctual requires.
Result<std::vector<Light>> convert_lights(const tinygltf::Model& g,
                                          const std::vector<detail::AttachedNode>& nodes) {
  std::vector<Light> lights;
  for (const detail::AttachedNode& l : nodes) {
    const tinygltf::Light& t = g.lights[static_cast<size_t>(l.index)];
    const std::string where = "extensions.KHR_lights_punctual.lights[" + std::to_string(l.index) + "]";
    Light out;
    const std::string& node_name = g.nodes[static_cast<size_t>(l.node)].name;
    out.name = !t.name.empty()      ? t.name
               : !node_name.empty() ? node_name
                                    : "lights[" + std::to_string(l.index) + "]";
    if (t.type == "point") {
      out.type = Light::Type::Point;
    } else if (t.type == "spot") {
      out.type = Light::Type::Spot;
    } else if (t.type == "directional") {
      out.type = Light::Type::Directional;
    } else {
      return make_error(where + ".type: '" + t.type + "' is not point, spot or directional");
    }
    if (!t.color.empty()) {
      if (t.color.size() != 3 ||
          !std::all_of(t.color.begin(), t.color.end(), [](double c) { return c >= 0 && c <= 1e6; }))
        return make_error(where + ".color: expected three numbers from 0 up");
      out.colour = glm::vec3(float(t.color[0]), float(t.color[1]), float(t.color[2]));
    }
    if (!(t.intensity >= 0 && t.intensity <= 1e12))
      return make_error(where + ".intensity: must be 0 or more");
    if (!(t.range >= 0 && t.range <= 1e9)) return make_error(where + ".range: must be above 0 (or absent)");
    out.intensity = float(t.intensity);
    out.range_m = float(t.range);
    if (out.type == Light::Type::Spot) {
      const double inner = t.spot.innerConeAngle, outer = t.spot.outerConeAngle;
      if (!(inner >= 0 && inner < outer && outer <= 1.5707963268)) {
        return make_error(where + ".spot: needs 0 <= innerConeAngle < outerConeAngle <= pi/2");
      }
      out.inner_cone_rad = float(inner);
      out.outer_cone_rad = float(outer);
    }
    out.world = glm::mat4(l.world);
    lights.push_back(std::move(out));
  }
  return lights;
}

Result<Model> convert(const tinygltf::Model& g, const Limits& limits, std::vector<std::string> warnings,
                      Content content) {
  Model model;
  warn_unsupported(g, warnings);
  // Cheap structural checks first, so a broken file fails before images are decoded.
  detail::Attachments attached;
  Result<std::vector<Instance>> instances = convert_nodes(g, limits, attached);
  if (!instances) return instances.error();
  Result<std::vector<Camera>> cameras = convert_cameras(g, attached.cameras);
  if (!cameras) return cameras.error();
  Result<std::vector<Light>> lights = convert_lights(g, attached.lights);
  if (!lights) return lights.error();
  model.instances = std::move(*instances);
  model.cameras = std::move(*cameras);
  model.lights = std::move(*lights);
  if (content == Content::Nodes) {
    model.instances.clear();  // they would name meshes that are not read
    model.warnings = std::move(warnings);
    return model;
  }
  Result<detail::Accessors> accessors = build_accessors(g);
  if (!accessors) return accessors.error();
  std::map<int, int> image_slots;
  Result<std::vector<Material>> materials = convert_materials(g, image_slots, warnings);
  if (!materials) return materials.error();
  Result<std::vector<Mesh>> meshes = convert_meshes(g, *accessors, materials->size(), limits, warnings);
  if (!meshes) return meshes.error();
  Result<std::vector<Texture>> textures = decode_textures(g, *accessors, image_slots, limits);
  if (!textures) return textures.error();
  model.meshes = std::move(*meshes);
  model.materials = std::move(*materials);
  model.textures = std::move(*textures);
  model.warnings = std::move(warnings);
  detail::compute_bounds(model);
  return model;
}

// ---- Loading ---------------------------------------------------------------------------------------------

Result<Model> load(const fs::path& file, const Limits& limits, Content content) {
  Result<std::vector<uint8_t>> bytes = detail::read_file(file, limits.max_file_bytes);
  if (!bytes) return bytes.error();
  if (bytes->size() > UINT32_MAX) return make_error("files of 4 GiB or more are not supported");
  const auto size = static_cast<unsigned int>(bytes->size());
  std::error_code ec;
  const fs::path folder = fs::canonical(fs::absolute(file, ec).parent_path(), ec);
  if (ec) return make_error("cannot resolve the model's folder: " + ec.message());

  const bool glb = detail::is_glb(*bytes);
  std::string_view json(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  if (glb) {
    Result<std::string_view> chunk = detail::glb_json_chunk(*bytes);
    if (!chunk) return chunk.error();
    json = *chunk;
  }
  Result<detail::Prescan> pre = detail::prescan(json, folder, limits.max_file_bytes);
  if (!pre) return pre.error();

  Sandbox sandbox{pre->files, limits.max_file_bytes};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&sandbox_exists, &sandbox_expand, &sandbox_read, &sandbox_write, &sandbox});
  loader.SetImageLoader(&keep_encoded, nullptr);
  tinygltf::Model g;
  std::string err, warn;
  const bool ok =
      glb ? loader.LoadBinaryFromMemory(&g, &err, &warn, bytes->data(), size, folder.string())
          : loader.LoadASCIIFromString(&g, &err, &warn, reinterpret_cast<const char*>(bytes->data()), size,
                                       folder.string());
  if (!ok) return make_error("not a valid glTF file: " + tidy(err));
  std::vector<uint8_t>().swap(*bytes);  // released: tinygltf copied the GLB's BIN chunk into g.buffers
  return convert(g, limits, std::move(pre->warnings), content);
}

}  // namespace

Result<Model> load_gltf(const fs::path& file, const Limits& limits, Content content) {
  // Errors below carry the glTF object and the reason; the file is named once, here.
  try {
    Result<Model> model = load(file, limits, content);
    if (!model) return make_error(file.string() + ": " + model.error().message);
    return model;
  } catch (const std::bad_alloc&) {
    return make_error(file.string() + ": out of memory while loading");
  } catch (const std::exception& e) {
    return make_error(file.string() + ": " + e.what());
  }
}

}  // namespace lagoon::gltf
