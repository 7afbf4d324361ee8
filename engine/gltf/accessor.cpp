#include "gltf/accessor.h"

#include <algorithm>
#include <cstring>

#include "gltf/checks.h"

namespace lagoon::gltf::detail {
namespace {

size_t component_size(int type) {
  switch (type) {
    case kByte:
    case kUnsignedByte:
      return 1;
    case kShort:
    case kUnsignedShort:
      return 2;
    case kUnsignedInt:
    case kFloat:
      return 4;
    default:
      return 0;  // INT (5124) and DOUBLE exist in tinygltf but not in glTF 2.0
  }
}

const char* component_name(int type) {
  switch (type) {
    case kByte:
      return "BYTE";
    case kUnsignedByte:
      return "UNSIGNED_BYTE";
    case kShort:
      return "SHORT";
    case kUnsignedShort:
      return "UNSIGNED_SHORT";
    case kUnsignedInt:
      return "UNSIGNED_INT";
    case 5124:
      return "INT (not allowed in glTF 2.0)";
    case kFloat:
      return "FLOAT";
    default:
      return "invalid componentType";
  }
}

template <typename T>
T load(const uint8_t* p) {  // glTF data is little-endian, like every machine Lagoon runs on
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

float to_float(const uint8_t* p, int type, bool normalized) {
  switch (type) {
    case kByte:
      return normalized ? std::max(load<int8_t>(p) / 127.0f, -1.0f) : load<int8_t>(p);
    case kUnsignedByte:
      return normalized ? load<uint8_t>(p) / 255.0f : load<uint8_t>(p);
    case kShort:
      return normalized ? std::max(load<int16_t>(p) / 32767.0f, -1.0f) : load<int16_t>(p);
    case kUnsignedShort:
      return normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
    case kUnsignedInt:
      return static_cast<float>(load<uint32_t>(p));
    default:
      return load<float>(p);
  }
}

uint32_t to_uint(const uint8_t* p, int type) {
  switch (type) {
    case kUnsignedByte:
      return load<uint8_t>(p);
    case kUnsignedShort:
      return load<uint16_t>(p);
    default:
      return load<uint32_t>(p);
  }
}

std::string bytes(size_t n) {
  return std::to_string(n) + " bytes";
}

// The bytes [offset, offset + length) of bufferView `index`, checked; `what` names the user for messages.
Result<const uint8_t*> view_range(const Accessors& a, int64_t index, int64_t offset, size_t length,
                                  const std::string& what) {
  if (!valid_index(index, a.views.size())) {
    return make_error(what + ": bufferView " + std::to_string(index) + " does not exist");
  }
  const View& view = a.views[static_cast<size_t>(index)];
  size_t end = 0;
  if (offset < 0 || !mul_add(1, static_cast<size_t>(offset), length, &end) || end > view.size) {
    return make_error(what + ": byteOffset " + std::to_string(offset) + " + " + bytes(length) +
                      " is past the end of " + at("bufferViews", index) + " (" + bytes(view.size) + ")");
  }
  return view.data + offset;
}

// Applies the sparse substitution of accessor `d` to `out` (count * components values).
template <typename T, typename Convert>
Result<void> apply_sparse(const Accessors& a, const AccessorDesc& d, const std::string& where, size_t element,
                          Convert convert, std::vector<T>& out) {
  const Sparse& s = *d.sparse;
  const std::string sw = where + ".sparse";
  if (s.count < 0 || static_cast<uint64_t>(s.count) > d.count) {
    return make_error(sw + ": count " + std::to_string(s.count) + " is not within 0.." +
                      std::to_string(d.count));
  }
  const auto count = static_cast<size_t>(s.count);
  const int itype = s.indices_component_type;
  if (itype != kUnsignedByte && itype != kUnsignedShort && itype != kUnsignedInt) {
    return make_error(sw + ".indices: componentType " + std::to_string(itype) +
                      " must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
  const size_t isize = component_size(itype);
  size_t indices_length = 0, values_length = 0;
  if (!mul_add(count, isize, 0, &indices_length) || !mul_add(count, element, 0, &values_length)) {
    return make_error(sw + ": count " + std::to_string(count) + " is too large");
  }
  Result<const uint8_t*> indices =
      view_range(a, s.indices_view, s.indices_offset, indices_length, sw + ".indices");
  if (!indices) return indices.error();
  Result<const uint8_t*> values =
      view_range(a, s.values_view, s.values_offset, values_length, sw + ".values");
  if (!values) return values.error();
  const size_t csize = component_size(d.component_type);
  for (size_t k = 0; k < count; ++k) {
    const uint32_t target = to_uint(*indices + k * isize, itype);
    if (target >= d.count) {
      return make_error(sw + ".indices[" + std::to_string(k) + "] = " + std::to_string(target) +
                        " is out of range (count " + std::to_string(d.count) + ")");
    }
    for (int c = 0; c < d.components; ++c) {
      out[size_t{target} * d.components + c] = convert(*values + k * element + c * csize);
    }
  }
  return {};
}

template <typename T, typename Convert>
Result<std::vector<T>> read(const Accessors& a, int index, Convert convert) {
  const std::string where = at("accessors", index);
  if (!valid_index(index, a.accessors.size())) {
    return make_error(where + " does not exist (the file has " + std::to_string(a.accessors.size()) + ")");
  }
  const AccessorDesc& d = a.accessors[static_cast<size_t>(index)];
  const size_t csize = component_size(d.component_type);
  if (csize == 0) {
    return make_error(where + ": componentType " + std::to_string(d.component_type) +
                      " is not allowed in glTF 2.0");
  }
  if (d.count == 0) return make_error(where + ": count is 0");
  if (d.components < 1 || d.components > 16) return make_error(where + ": invalid type");
  const size_t element = csize * static_cast<size_t>(d.components);
  size_t total = 0;
  if (!mul_add(d.count, static_cast<size_t>(d.components), 0, &total)) {
    return make_error(where + ": count " + std::to_string(d.count) + " is too large");
  }
  std::vector<T> out(total, T{0});
  if (d.view >= 0) {
    if (!valid_index(d.view, a.views.size())) {
      return make_error(where + ": bufferViews[" + std::to_string(d.view) + "] does not exist");
    }
    const View& view = a.views[static_cast<size_t>(d.view)];
    if (view.stride != 0 && view.stride < element) {
      return make_error(where + ": byteStride " + std::to_string(view.stride) + " of " +
                        at("bufferViews", d.view) + " is smaller than the element (" + describe(d) + ", " +
                        bytes(element) + ")");
    }
    const size_t stride = view.stride != 0 ? view.stride : element;
    size_t end = 0;
    if (!mul_add(stride, d.count - 1, element, &end) || !mul_add(1, end, d.byte_offset, &end) ||
        end > view.size) {
      return make_error(where + ": byteOffset " + std::to_string(d.byte_offset) + " + byteStride " +
                        std::to_string(stride) + " * (count " + std::to_string(d.count) + " - 1) + element " +
                        bytes(element) + " is past the end of " + at("bufferViews", d.view) + " (" +
                        bytes(view.size) + ")");
    }
    const uint8_t* base = view.data + d.byte_offset;
    for (size_t i = 0; i < d.count; ++i) {
      for (int c = 0; c < d.components; ++c)
        out[i * d.components + c] = convert(base + i * stride + c * csize);
    }
  }
  if (d.sparse) {
    if (Result<void> r = apply_sparse(a, d, where, element, convert, out); !r) return r.error();
  }
  return out;
}

}  // namespace

std::string describe(const AccessorDesc& d) {
  const char* type = "MAT4";
  switch (d.components) {
    case 1:
      type = "SCALAR";
      break;
    case 2:
      type = "VEC2";
      break;
    case 3:
      type = "VEC3";
      break;
    case 4:
      type = "VEC4";  // or MAT2: the messages only need to say it is not what was expected
      break;
    case 9:
      type = "MAT3";
      break;
    default:
      break;
  }
  return std::string(type) + (d.normalized ? " normalized " : " ") + component_name(d.component_type);
}

Result<std::vector<float>> read_floats(const Accessors& a, int index) {
  const bool normalized =
      valid_index(index, a.accessors.size()) && a.accessors[static_cast<size_t>(index)].normalized;
  const int type =
      valid_index(index, a.accessors.size()) ? a.accessors[static_cast<size_t>(index)].component_type : 0;
  return read<float>(a, index, [&](const uint8_t* p) { return to_float(p, type, normalized); });
}

Result<std::vector<uint32_t>> read_uints(const Accessors& a, int index) {
  const int type =
      valid_index(index, a.accessors.size()) ? a.accessors[static_cast<size_t>(index)].component_type : 0;
  return read<uint32_t>(a, index, [&](const uint8_t* p) { return to_uint(p, type); });
}

}  // namespace lagoon::gltf::detail
