#version 450
// Reflection test: push constants with nested structs, an array of structs and a row-major matrix last.
layout(local_size_x = 1) in;

struct Wave {
  vec2 dir;   // offset 0
  float amp;  // offset 8; the struct covers 12 bytes (std430 pads its stride to 16)
};
struct Group {
  uint id;    // offset 0
  Wave wave;  // offset 8: ends at 20
};

layout(push_constant) uniform Push {
  Wave waves[2];               // offset 0, ArrayStride 16: 32 bytes
  Group group;                 // offset 32, covers 20 bytes (std430 size 24)
  layout(row_major) mat2x3 m;  // offset 56: 3 rows of vec2, MatrixStride 8: ends at 80
} pc;

layout(set = 0, binding = 0) writeonly buffer Out {
  vec4 v;
} result;

void main() {
  result.v = vec4(pc.waves[0].dir + pc.waves[1].dir + pc.group.wave.dir, pc.group.wave.amp, float(pc.group.id));
  result.v.xyz += pc.m * vec2(1.0);
}
