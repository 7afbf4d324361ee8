// A look at the glTF JSON before tinygltf loads it: tinygltf reads external files and follows offsets
// while it parses, so what it must not do (open files outside the model's folder, recurse through deeply
// nested JSON, point past a buffer) is refused here first.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"

namespace lagoon::gltf::detail {

struct Prescan {
  bool parsed = false;                       // false: not JSON at all; tinygltf then says why
  std::vector<std::filesystem::path> files;  // canonical paths of the files the model may read
  std::vector<std::string> warnings;         // extensions used but not supported
};

// `folder` is the model's folder, canonical. Fails on: JSON nested deeper than tinygltf may safely
// recurse, a glTF version other than 2, an extension the file requires, a refused or missing buffer or
// image file, and an image bufferView outside its buffer. Errors name the glTF object, not the file.
Result<Prescan> prescan(std::string_view json, const std::filesystem::path& folder, size_t max_file_bytes);

}  // namespace lagoon::gltf::detail
