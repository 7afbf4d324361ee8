#version 450
// Reflection test: storage buffers, a uniform buffer, an array of storage buffers and two descriptor sets,
// with a fixed workgroup size. Set 1 is declared first so the test sees the bindings get sorted.
layout(local_size_x = 64, local_size_y = 2, local_size_z = 1) in;

layout(set = 1, binding = 0) buffer Counters {
  uint hits;
} counters[2];

layout(set = 0, binding = 1) writeonly buffer Output {
  float values[];
} dst;

layout(set = 0, binding = 0) readonly buffer Input {
  float values[];
} src;

layout(set = 0, binding = 2) uniform Params {
  uint count;
  float scale;
} params;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.count) return;
  dst.values[i] = src.values[i] * params.scale;
  atomicAdd(counters[i & 1u].hits, 1u);
}
