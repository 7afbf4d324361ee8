// Lets one header declare a struct for both GLSL and C++ (std430 / std140-compatible when members are
// vec4/mat4 first, then 4-byte scalars). C++ sees the types in namespace lagoon::gpu.
#ifndef LAGOON_SHARED_INTEROP_H
#define LAGOON_SHARED_INTEROP_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#define LAGOON_GPU_BEGIN namespace lagoon::gpu {
#define LAGOON_GPU_END }
LAGOON_GPU_BEGIN
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec2 = glm::ivec2;
using ivec4 = glm::ivec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
// GLSL's built-ins, for the functions shared headers define for both languages (e.g. shared/clipmap.h).
using glm::abs;
using glm::acos;
using glm::atan;
using glm::clamp;
using glm::cos;
using glm::dot;
using glm::exp;
using glm::exp2;
using glm::floor;
using glm::fract;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::sin;
using glm::sqrt;
LAGOON_GPU_END
#define LAGOON_FN inline
// Use inside #ifdef __cplusplus: the layout GLSL assumes, checked by the C++ compiler.
#define LAGOON_CHECK_SIZE(type, bytes) static_assert(sizeof(lagoon::gpu::type) == (bytes), #type " size")
#define LAGOON_CHECK_OFFSET(type, member, bytes) \
  static_assert(offsetof(lagoon::gpu::type, member) == (bytes), #type "." #member " offset")
#else
#define LAGOON_GPU_BEGIN
#define LAGOON_GPU_END
#define LAGOON_FN
#endif

#endif
