// URIs of buffers and images. A model may embed data (data: URIs) or name files next to it; anything that
// reaches elsewhere (absolute paths, other schemes, "..") is refused, so opening a downloaded model cannot
// read /etc/passwd or ~/.ssh into a texture.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "core/result.h"

namespace lagoon::gltf::detail {

bool is_data_uri(std::string_view uri);

// tinygltf 2.7 decodes only base64 data: URIs of a fixed list of media types; any other data: URI it would
// try to open as a file, so those are refused up front with a clear reason.
bool is_supported_data_uri(std::string_view uri);

// Percent-decoding exactly as tinygltf 2.7 does it ('+' becomes a space too), so the path checked here is
// the path tinygltf asks to open.
std::string url_decode(std::string_view uri);

// The file a relative URI names inside `folder` (canonical, absolute), or why it may not be read. The
// result is canonical (symbolic links resolved) and lies inside `folder`; it need not exist. The error is a
// reason only ("'../a.bin' leads outside the model's folder"); the caller names the object.
Result<std::filesystem::path> resolve_uri(std::string_view uri, const std::filesystem::path& folder);

}  // namespace lagoon::gltf::detail
