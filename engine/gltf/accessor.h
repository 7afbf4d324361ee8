// Reading glTF accessors out of buffers, with every offset, stride and count checked first: accessors are
// where a malformed or hostile file points outside its data.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"

namespace lagoon::gltf::detail {

// glTF componentType values.
enum ComponentType : int {
  kByte = 5120,
  kUnsignedByte = 5121,
  kShort = 5122,
  kUnsignedShort = 5123,
  kUnsignedInt = 5125,
  kFloat = 5126,
};

// A bufferView whose range has been checked against its buffer.
struct View {
  const uint8_t* data = nullptr;
  size_t size = 0;
  size_t stride = 0;  // 0 = elements tightly packed
};

struct Sparse {  // signed: tinygltf keeps these as ints, so the file can make them negative
  int64_t count = 0;
  int64_t indices_view = -1;
  int64_t indices_offset = 0;
  int indices_component_type = 0;
  int64_t values_view = -1;
  int64_t values_offset = 0;
};

struct AccessorDesc {
  int view = -1;  // -1: every element is zero (then usually sparse)
  size_t byte_offset = 0;
  size_t count = 0;
  int component_type = 0;
  int components = 0;  // 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4 or MAT2, 9 MAT3, 16 MAT4
  bool normalized = false;
  std::optional<Sparse> sparse;
};

struct Accessors {
  std::vector<View> views;  // one per glTF bufferView, all checked
  std::vector<AccessorDesc> accessors;
};

// "VEC3 FLOAT", "VEC2 normalized UNSIGNED_BYTE": for messages.
std::string describe(const AccessorDesc& accessor);

// Matrices of 1- and 2-byte components have padded columns and are not read here; the caller checks the
// type before reading.
//
// Element i, component c of every element, as floats: normalized integers are mapped to [0,1] / [-1,1] as
// the glTF spec says, others converted as they are. Fails (naming "accessors[index]") when the accessor, its
// bufferView range, its stride or its sparse part is invalid.
Result<std::vector<float>> read_floats(const Accessors& accessors, int index);

// An unsigned integer SCALAR accessor (indices): the caller checks the types first.
Result<std::vector<uint32_t>> read_uints(const Accessors& accessors, int index);

}  // namespace lagoon::gltf::detail
