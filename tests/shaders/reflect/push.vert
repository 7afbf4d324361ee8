#version 450
// Reflection test: vertex stage with a uniform buffer and a push-constant block (std430 layout).
layout(push_constant) uniform Push {
  mat4 model;    // offset 0, 64 bytes
  vec4 tint;     // offset 64, 16 bytes
  float time;    // offset 80, 4 bytes
  vec2 wind[3];  // offset 88 (vec2 aligns to 8), ArrayStride 8: ends at 112
} pc;

layout(set = 0, binding = 0) uniform Camera {
  mat4 view_proj;
} camera;

layout(location = 0) in vec3 position;
layout(location = 0) out vec4 color;

void main() {
  vec3 p = position + vec3(pc.wind[0] + pc.wind[1] + pc.wind[2], 0.0) * pc.time;
  gl_Position = camera.view_proj * pc.model * vec4(p, 1.0);
  color = pc.tint;
}
