// glTF 2.0 loader (.gltf with data: or relative URIs, and .glb) into the plain structs of gltf/model.h.
// Built for files from anywhere: every index, size and range is checked, external files must lie in the
// model's folder, and limits bound the memory a file can make us allocate. Errors name the file, the glTF
// object (e.g. "accessors[3]") and the reason; the loader never throws.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "core/result.h"
#include "gltf/model.h"

namespace lagoon::gltf {

struct Limits {
  size_t max_vertices = 5'000'000;       // summed over all primitives
  size_t max_indices = 15'000'000;       // summed over all primitives, generated ones included
  size_t max_textures = 64;              // decoded images (any material texture)
  uint32_t max_texture_size = 8192;      // width and height, pixels
  size_t max_file_bytes = 512ull << 20;  // each of the .gltf/.glb, .bin and image files
  size_t max_nodes = 100'000;
};

// What to read. Nodes: only the cameras and lights of the node tree (Model::cameras, lights), for a scene
// that takes its camera from the file: meshes, materials and images are not converted or decoded, so
// they cost nothing and a broken image does not stop the camera from loading (Model::instances is empty).
enum class Content { Everything, Nodes };

// The default scene (or the first, or every root node when the file has no scenes) flattened into
// Model::instances. Unsupported features are skipped with one warning per kind (Model::warnings).
Result<Model> load_gltf(const std::filesystem::path& file, const Limits& limits = {},
                        Content content = Content::Everything);

}  // namespace lagoon::gltf
