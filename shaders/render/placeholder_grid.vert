#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/placeholder_frame.h"
#include "common/placeholder_waves.glsl"

// A camera-centred grid whose spacing grows with distance (u -> sign(u)·u²), so triangles stay roughly
// the same size on screen and the grid reaches the horizon with few vertices. Vertex pulling: the vertex
// index alone gives the position, no vertex buffer.
layout(std140, binding = 0) uniform Frame { PlaceholderFrame frame; };
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;

void main() {
  int n = int(frame.grid.y);          // vertices per side
  int quad = gl_VertexIndex / 6;
  int corner = gl_VertexIndex % 6;
  const ivec2 offsets[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  ivec2 cell = ivec2(quad % (n - 1), quad / (n - 1)) + offsets[corner];
  vec2 uv = vec2(cell) / float(n - 1) * 2.0 - 1.0;
  vec2 xz = frame.camera_pos.xz + sign(uv) * uv * uv * frame.grid.x;
  vec3 position, normal;
  gerstner(xz, frame.grid.z, position, normal);
  v_world = position;
  v_normal = normal;
  gl_Position = frame.view_proj * vec4(position, 1.0);
}
