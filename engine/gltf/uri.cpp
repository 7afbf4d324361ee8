#include "gltf/uri.h"

#include <array>
#include <cctype>
#include <system_error>
#include <vector>

namespace lagoon::gltf::detail {
namespace {

namespace fs = std::filesystem;

// RFC 3986 scheme: ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":". Also matches a Windows drive ("C:").
bool has_scheme(std::string_view uri) {
  if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
  for (size_t i = 1; i < uri.size(); ++i) {
    const auto c = static_cast<unsigned char>(uri[i]);
    if (c == ':') return true;
    if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return false;
  }
  return false;
}

bool is_absolute_path(std::string_view path) {
  return !path.empty() && (path[0] == '/' || path[0] == '\\' || has_scheme(path));
}

// Both separators count: a backslash is a plain character on Linux, but the same file must not become an
// escape when opened on Windows.
std::vector<std::string_view> segments(std::string_view path) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/' || path[i] == '\\') {
      out.push_back(path.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

bool is_inside(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // trailing separator of the folder
    if (p == path.end() || *p != *f) return false;
  }
  return p != path.end();
}

unsigned char from_hex(unsigned char c) {
  if (c >= '0' && c <= '9') return static_cast<unsigned char>(c - '0');
  if (c >= 'a' && c <= 'f') return static_cast<unsigned char>(c - 'a' + 10);
  if (c >= 'A' && c <= 'F') return static_cast<unsigned char>(c - 'A' + 10);
  return 0;  // tinygltf's choice for a malformed escape
}

std::string quote_uri(std::string_view uri) {
  constexpr size_t kMax = 120;  // a hostile URI may be megabytes long
  std::string s(uri.substr(0, kMax));
  if (uri.size() > kMax) s += "...";
  return "'" + s + "'";
}

}  // namespace

bool is_data_uri(std::string_view uri) {
  return uri.size() >= 5 && (uri.substr(0, 5) == "data:" || uri.substr(0, 5) == "DATA:");
}

bool is_supported_data_uri(std::string_view uri) {
  static constexpr std::array<std::string_view, 7> kPrefixes = {"data:application/octet-stream;base64,",
                                                                "data:image/jpeg;base64,",
                                                                "data:image/png;base64,",
                                                                "data:image/bmp;base64,",
                                                                "data:image/gif;base64,",
                                                                "data:text/plain;base64,",
                                                                "data:application/gltf-buffer;base64,"};
  for (std::string_view prefix : kPrefixes) {
    if (uri.substr(0, prefix.size()) == prefix) return true;
  }
  return false;
}

std::string url_decode(std::string_view uri) {
  std::string out;
  out.reserve(uri.size());
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      const unsigned char hi = from_hex(static_cast<unsigned char>(uri[i + 1]));
      const unsigned char lo = from_hex(static_cast<unsigned char>(uri[i + 2]));
      out += static_cast<char>((hi << 4) | lo);
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

Result<fs::path> resolve_uri(std::string_view uri, const fs::path& folder) {
  if (uri.empty()) return make_error("the URI is empty");
  if (is_absolute_path(uri)) {
    return make_error(quote_uri(uri) +
                      " is an absolute URI; only data: URIs and paths relative to the model's folder are "
                      "allowed");
  }
  const std::string decoded = url_decode(uri);
  const std::string shown =
      decoded == uri ? quote_uri(uri) : quote_uri(uri) + " (decoded " + quote_uri(decoded) + ")";
  for (char c : decoded) {
    // A NUL would cut the path short inside the OS; no real file name needs control characters.
    if (static_cast<unsigned char>(c) < 0x20) return make_error(shown + " contains control characters");
  }
  if (is_absolute_path(decoded)) {
    return make_error(shown + " is an absolute path; only paths relative to the model's folder are allowed");
  }
  int depth = 0;
  for (std::string_view segment : segments(decoded)) {
    if (segment.empty() || segment == ".") continue;
    if (segment != "..") {
      ++depth;
    } else if (--depth < 0) {
      return make_error(shown + " leads outside the model's folder");
    }
  }
  if (depth == 0) return make_error(shown + " names the model's folder, not a file");
  // The OS resolves ".." after following links, so the target is checked the same way: with links
  // followed, a link inside the folder must not reach out.
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(folder / fs::path(decoded), ec);
  if (ec) return make_error(shown + " cannot be resolved: " + ec.message());
  if (!is_inside(resolved, folder)) {
    return make_error(shown + " resolves to " + resolved.string() + ", outside the model's folder");
  }
  return resolved;
}

}  // namespace lagoon::gltf::detail
