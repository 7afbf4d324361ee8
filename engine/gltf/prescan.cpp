#include "gltf/prescan.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdint>
#include <optional>
#include <system_error>

#include "gltf/checks.h"
#include "gltf/uri.h"
#include "io/json_limits.h"

namespace lagoon::gltf::detail {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// tinygltf converts "extras" and "extensions" recursively; a few kB of "[[[[..." would overflow the stack.
// Real files nest about 10 levels.
// glTF arrays (nodes, accessors) and strings (base64 data URIs) can be large: only the nesting is bounded
// here; the file size bounds the rest.
constexpr io::JsonLimits kGltfJsonLimits{
    .max_depth = 64, .max_array_length = size_t{1} << 24, .max_string_bytes = SIZE_MAX};

const json* member(const json& object, const char* name) {
  if (!object.is_object()) return nullptr;
  auto it = object.find(name);
  return it == object.end() ? nullptr : &*it;
}

const json& array_member(const json& object, const char* name) {
  static const json kEmpty = json::array();
  const json* value = member(object, name);
  return value && value->is_array() ? *value : kEmpty;
}

// An integer property that decides where tinygltf reads: anything but a plain non-negative integer is
// refused, so this check and tinygltf cannot disagree about its value. Absent gives `fallback`.
Result<uint64_t> offset_property(const json& object, const char* name, std::optional<uint64_t> fallback,
                                 const std::string& where) {
  const json* value = member(object, name);
  if (!value) {
    if (fallback) return *fallback;
    return make_error(where + ": '" + name + "' is missing");
  }
  if (!value->is_number_unsigned() || value->get<uint64_t>() > INT32_MAX) {
    return make_error(where + "." + name + ": " + value->dump() + " is not a valid index or size");
  }
  return value->get<uint64_t>();
}

Result<void> check_version(const json& root) {
  const json* asset = member(root, "asset");
  const json* version = asset ? member(*asset, "version") : nullptr;
  if (!version || !version->is_string()) return {};  // tinygltf reports the missing version
  const std::string v = version->get<std::string>();
  if (v.substr(0, 2) != "2.") {
    return make_error("asset.version: '" + v + "'; only glTF 2.0 is supported");
  }
  return {};
}

// A required extension the loader does not read means the file cannot be drawn correctly.
Result<void> check_extensions(const json& root, std::vector<std::string>& warnings) {
  std::string required;
  for (const json& name : array_member(root, "extensionsRequired")) {
    if (name.is_string() && !supported_extension(name.get<std::string>()))
      required += (required.empty() ? "'" : ", '") + name.get<std::string>() + "'";
  }
  if (!required.empty()) {
    return make_error("extensionsRequired: " + required +
                      " not supported by Lagoon (the file cannot be shown without it)");
  }
  for (const json& name : array_member(root, "extensionsUsed")) {
    if (name.is_string() && !supported_extension(name.get<std::string>())) {
      warn_once(warnings, "extension '" + name.get<std::string>() + "' is not supported; ignored");
    }
  }
  return {};
}

// Bytes a base64 payload decodes to, counted the way tinygltf decodes: up to the first '=' or other
// non-base64 character.
size_t base64_size(std::string_view payload) {
  size_t n = 0;
  while (n < payload.size() &&
         (std::isalnum(static_cast<unsigned char>(payload[n])) || payload[n] == '+' || payload[n] == '/')) {
    ++n;
  }
  return n / 4 * 3 + (n % 4 > 1 ? n % 4 - 1 : 0);
}

// tinygltf refuses a buffer whose data: URI does not decode to exactly byteLength bytes, but its message
// quotes the whole URI without saying which buffer; this one says which and by how much.
Result<void> check_buffer_data_size(const json& buffer, const std::string& where, std::string_view uri) {
  const json* length = member(buffer, "byteLength");
  if (!length || !length->is_number_unsigned()) return {};  // tinygltf reports it
  const size_t decoded = base64_size(uri.substr(uri.find(',') + 1));
  if (decoded != length->get<uint64_t>()) {
    return make_error(where + ".uri: the data URI holds " + std::to_string(decoded) +
                      " bytes but byteLength is " + std::to_string(length->get<uint64_t>()));
  }
  return {};
}

// A buffer or image URI: data: URIs tinygltf decodes itself; files must resolve inside the folder, exist,
// and fit the size limit. Returns the file to allow, if any.
Result<std::optional<fs::path>> check_uri(const json& object, const std::string& where,
                                          const fs::path& folder, size_t max_file_bytes) {
  const json* uri = member(object, "uri");
  if (!uri || !uri->is_string()) return std::optional<fs::path>();
  const std::string text = uri->get<std::string>();
  if (is_data_uri(text)) {
    if (is_supported_data_uri(text)) {
      if (where.starts_with("buffers")) {
        if (Result<void> r = check_buffer_data_size(object, where, text); !r) return r.error();
      }
      return std::optional<fs::path>();
    }
    const size_t comma = text.find_first_of(",");
    return make_error(where + ".uri: unsupported data URI '" + text.substr(0, std::min<size_t>(comma, 60)) +
                      ",...'; expected base64 data of type application/octet-stream, "
                      "application/gltf-buffer, image/png or image/jpeg");
  }
  Result<fs::path> path = resolve_uri(text, folder);
  if (!path) return make_error(where + ".uri: " + path.error().message);
  std::error_code ec;
  const fs::file_status status = fs::status(*path, ec);
  if (!fs::exists(status)) return make_error(where + ": file " + path->string() + " does not exist");
  if (!fs::is_regular_file(status))
    return make_error(where + ": " + path->string() + " is not a regular file");
  const uintmax_t size = fs::file_size(*path, ec);
  if (ec) return make_error(where + ": cannot read " + path->string() + ": " + ec.message());
  if (size > max_file_bytes) {
    return make_error(where + ": " + path->string() + " has " + std::to_string(size) +
                      " bytes, more than the limit of " + std::to_string(max_file_bytes));
  }
  return std::optional<fs::path>(*path);
}

// tinygltf hands images stored in a bufferView to the image loader as &buffer.data[byteOffset] without a
// range check, so the range is checked here, against the declared buffer sizes (tinygltf makes every
// buffer exactly its byteLength or fails).
Result<void> check_image_buffer_view(const json& root, const json& image, const std::string& where) {
  if (!member(image, "bufferView") || member(image, "uri")) return {};  // tinygltf rejects both
  Result<uint64_t> view_index = offset_property(image, "bufferView", std::nullopt, where);
  if (!view_index) return view_index.error();
  const json& views = array_member(root, "bufferViews");
  if (*view_index >= views.size()) {
    return make_error(where + ".bufferView: bufferViews[" + std::to_string(*view_index) + "] does not exist");
  }
  const std::string view_where = at("bufferViews", static_cast<int64_t>(*view_index));
  const json& view = views[*view_index];
  Result<uint64_t> buffer_index = offset_property(view, "buffer", std::nullopt, view_where);
  if (!buffer_index) return buffer_index.error();
  Result<uint64_t> offset = offset_property(view, "byteOffset", 0, view_where);
  if (!offset) return offset.error();
  Result<uint64_t> length = offset_property(view, "byteLength", std::nullopt, view_where);
  if (!length) return length.error();
  const json& buffers = array_member(root, "buffers");
  if (*buffer_index >= buffers.size()) {
    return make_error(view_where + ".buffer: buffers[" + std::to_string(*buffer_index) + "] does not exist");
  }
  const std::string buffer_where = at("buffers", static_cast<int64_t>(*buffer_index));
  Result<uint64_t> buffer_length =
      offset_property(buffers[*buffer_index], "byteLength", std::nullopt, buffer_where);
  if (!buffer_length) return buffer_length.error();
  if (*length == 0 || *offset + *length > *buffer_length) {
    return make_error(where + ": " + view_where + " (byteOffset " + std::to_string(*offset) +
                      ", byteLength " + std::to_string(*length) + ") does not fit in " + buffer_where + " (" +
                      std::to_string(*buffer_length) + " bytes)");
  }
  return {};
}

}  // namespace

Result<Prescan> prescan(std::string_view text, const fs::path& folder, size_t max_file_bytes) {
  Prescan out;
  if (const auto exceeded = io::json_limit_exceeded(text, kGltfJsonLimits))
    return make_error("JSON: " + *exceeded);
  const json root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) return out;
  out.parsed = true;
  if (Result<void> r = check_version(root); !r) return r.error();
  if (Result<void> r = check_extensions(root, out.warnings); !r) return r.error();
  for (const char* kind : {"buffers", "images"}) {
    const json& objects = array_member(root, kind);
    for (size_t i = 0; i < objects.size(); ++i) {
      const std::string where = at(kind, static_cast<int64_t>(i));
      Result<std::optional<fs::path>> file = check_uri(objects[i], where, folder, max_file_bytes);
      if (!file) return file.error();
      if (*file) out.files.push_back(**file);
      if (std::string(kind) == "images") {
        if (Result<void> r = check_image_buffer_view(root, objects[i], where); !r) return r.error();
      }
    }
  }
  return out;
}

}  // namespace lagoon::gltf::detail
