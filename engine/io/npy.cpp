#include "io/npy.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "io/atomic_file.h"

namespace lagoon::io {
namespace {

constexpr char kMagic[6] = {'\x93', 'N', 'U', 'M', 'P', 'Y'};
constexpr size_t kAlignment = 64;  // the spec pads magic + version + length + header to this

std::optional<size_t> element_count(std::span<const size_t> shape) {
  size_t count = 1;
  for (size_t dim : shape) {
    if (dim != 0 && count > SIZE_MAX / dim) return std::nullopt;
    count *= dim;
  }
  return count;
}

// Python's repr of a tuple: "()", "(5,)", "(2, 3, 4)".
std::string shape_string(std::span<const size_t> shape) {
  std::string s = "(";
  for (size_t i = 0; i < shape.size(); ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(shape[i]);
  }
  if (shape.size() == 1) s += ',';
  return s + ")";
}

uint32_t to_little_endian(uint32_t v) {
  if constexpr (std::endian::native == std::endian::little) {
    return v;
  } else {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
  }
}

// Reads the header dict, a Python literal such as {'descr': '<f4', 'fortran_order': False, 'shape': (3,), }.
// Only the subset numpy writes is understood; anything else is reported as malformed.
class HeaderParser {
 public:
  explicit HeaderParser(std::string_view text) : s_(text) {}

  std::optional<std::string> descr;
  std::optional<bool> fortran_order;
  std::optional<std::vector<size_t>> shape;

  bool parse() {
    if (!eat('{')) return false;
    while (!eat('}')) {
      std::optional<std::string> key = string();
      if (!key || !eat(':')) return false;
      if (*key == "descr") {
        if (!(descr = string())) return false;
      } else if (*key == "fortran_order") {
        if (!(fortran_order = boolean())) return false;
      } else if (*key == "shape") {
        if (!(shape = tuple())) return false;
      } else {
        return false;
      }
      if (!eat(',') && !peek('}')) return false;
    }
    skip_space();
    return pos_ == s_.size();
  }

 private:
  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n')) ++pos_;
  }
  bool peek(char c) {
    skip_space();
    return pos_ < s_.size() && s_[pos_] == c;
  }
  bool eat(char c) {
    if (!peek(c)) return false;
    ++pos_;
    return true;
  }
  bool eat_word(std::string_view word) {
    skip_space();
    if (s_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }
  std::optional<std::string> string() {
    skip_space();
    if (pos_ >= s_.size() || (s_[pos_] != '\'' && s_[pos_] != '"')) return std::nullopt;
    const char quote = s_[pos_++];
    const size_t end = s_.find(quote, pos_);
    if (end == std::string_view::npos) return std::nullopt;
    std::string value(s_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return value;
  }
  std::optional<bool> boolean() {
    if (eat_word("True")) return true;
    if (eat_word("False")) return false;
    return std::nullopt;
  }
  std::optional<size_t> integer() {
    skip_space();
    const size_t start = pos_;
    size_t value = 0;
    for (; pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9'; ++pos_) {
      const size_t digit = static_cast<size_t>(s_[pos_] - '0');
      if (value > (SIZE_MAX - digit) / 10) return std::nullopt;
      value = value * 10 + digit;
    }
    if (pos_ == start) return std::nullopt;
    if (pos_ < s_.size() && s_[pos_] == 'L') ++pos_;  // Python 2 wrote long integers as "3L"
    return value;
  }
  std::optional<std::vector<size_t>> tuple() {
    if (!eat('(')) return std::nullopt;
    std::vector<size_t> values;
    while (!eat(')')) {
      std::optional<size_t> v = integer();
      if (!v) return std::nullopt;
      values.push_back(*v);
      if (!eat(',') && !peek(')')) return std::nullopt;
    }
    return values;
  }

  std::string_view s_;
  size_t pos_ = 0;
};

}  // namespace

Result<std::string> npy_header(std::span<const size_t> shape) {
  const std::optional<size_t> count = element_count(shape);
  if (!count || *count > SIZE_MAX / 4) return make_error("shape " + shape_string(shape) + " overflows");
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': " + shape_string(shape) + ", }";
  const size_t unpadded = sizeof kMagic + 2 + 2 + header.size() + 1;  // + 1 for the final '\n'
  header.append((kAlignment - unpadded % kAlignment) % kAlignment, ' ');
  header += '\n';
  if (header.size() > UINT16_MAX) return make_error("shape too long for a version 1.0 header");

  std::string prefix(kMagic, sizeof kMagic);
  prefix += '\x01';  // version 1.0
  prefix += '\x00';
  prefix += static_cast<char>(header.size() & 0xff);  // header length, little-endian uint16
  prefix += static_cast<char>(header.size() >> 8);
  return prefix + header;
}

Result<void> write_npy_values(AtomicFile& file, std::span<const float> data) {
  if constexpr (std::endian::native == std::endian::little) {
    return file.write(std::as_bytes(data));
  } else {
    std::vector<uint32_t> swapped(data.size());
    for (size_t i = 0; i < data.size(); ++i) swapped[i] = to_little_endian(std::bit_cast<uint32_t>(data[i]));
    return file.write(std::as_bytes(std::span(swapped)));
  }
}

Result<void> write_npy(const std::filesystem::path& path, std::span<const float> data,
                       std::span<const size_t> shape) {
  const std::string where = "cannot write NPY " + path.string() + ": ";
  Result<std::string> prefix = npy_header(shape);
  if (!prefix) return make_error(where + prefix.error().message);
  if (const size_t count = *element_count(shape); count != data.size()) {
    return make_error(where + "shape " + shape_string(shape) + " holds " + std::to_string(count) +
                      " values but data has " + std::to_string(data.size()));
  }
  Result<AtomicFile> file = AtomicFile::create(path);
  if (!file) return file.error();
  if (Result<void> r = file->write(std::as_bytes(std::span(*prefix))); !r) return r;
  if (Result<void> r = write_npy_values(*file, data); !r) return r;
  return file->commit();
}

Result<NpyArray> read_npy(const std::filesystem::path& path) {
  Result<std::vector<std::byte>> file = read_file_bytes(path);
  if (!file) return file.error();
  const std::vector<std::byte>& bytes = *file;
  const auto u8 = [&](size_t i) { return static_cast<uint32_t>(bytes[i]); };
  const std::string where = "cannot read NPY " + path.string() + ": ";

  if (bytes.size() < 10 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    return make_error(where + "not a .npy file (wrong magic)");
  }
  const uint32_t major = u8(6), minor = u8(7);
  size_t header_start = 0, header_len = 0;
  if (major == 1) {
    header_start = 10;
    header_len = u8(8) | u8(9) << 8;
  } else if ((major == 2 || major == 3) && bytes.size() >= 12) {
    header_start = 12;
    header_len = u8(8) | u8(9) << 8 | u8(10) << 16 | u8(11) << 24;
  } else {
    return make_error(where + "unsupported .npy version " + std::to_string(major) + "." +
                      std::to_string(minor));
  }
  if (header_len > bytes.size() - header_start) return make_error(where + "header is truncated");
  const std::string_view header(reinterpret_cast<const char*>(bytes.data()) + header_start, header_len);

  HeaderParser parser(header);
  if (!parser.parse() || !parser.descr || !parser.fortran_order || !parser.shape) {
    return make_error(where + "malformed header " + std::string(header));
  }
  if (*parser.descr != "<f4") {
    return make_error(where + "dtype '" + *parser.descr +
                      "' is not supported, only little-endian float32 '<f4'");
  }
  if (*parser.fortran_order)
    return make_error(where + "fortran_order arrays are not supported, only C order");

  NpyArray array;
  array.shape = std::move(*parser.shape);
  const std::optional<size_t> count = element_count(array.shape);
  const size_t data_bytes = bytes.size() - header_start - header_len;
  if (!count || *count > SIZE_MAX / 4 || *count * 4 != data_bytes) {
    return make_error(where + "shape " + shape_string(array.shape) + " of float32 does not match the " +
                      std::to_string(data_bytes) + " data bytes in the file");
  }
  array.data.resize(*count);
  if (data_bytes > 0) {  // memcpy from/to an empty vector's null data() is undefined
    std::memcpy(array.data.data(), bytes.data() + header_start + header_len, data_bytes);
  }
  if constexpr (std::endian::native != std::endian::little) {
    for (float& v : array.data) v = std::bit_cast<float>(to_little_endian(std::bit_cast<uint32_t>(v)));
  }
  return array;
}

}  // namespace lagoon::io
