#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"

// A camera-centred grid whose spacing grows with distance (u -> sign(u)·u²), so triangles keep roughly
// the same size on screen and the grid reaches the horizon. Each vertex rests at xz and is displaced by
// the sum of the cascades' displacement (λDx, h, λDz), sampled at a mip matching the grid spacing so
// waves shorter than the spacing fade instead of aliasing.
layout(std140, binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2DArray displacement[4];

layout(location = 0) out vec3 v_world;
layout(location = 1) out vec2 v_rest;

void main() {
  int n = int(frame.grid.y);
  int quad = gl_VertexIndex / 6;
  int corner = gl_VertexIndex % 6;
  const ivec2 offsets[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  ivec2 cell = ivec2(quad % (n - 1), quad / (n - 1)) + offsets[corner];
  vec2 uv = vec2(cell) / float(n - 1) * 2.0 - 1.0;
  vec2 xz = frame.camera_pos.xz + sign(uv) * uv * uv * frame.grid.x;
  // Local spacing of the grid at this vertex (derivative of the u² map).
  float spacing = 2.0 * max(abs(uv.x), abs(uv.y)) * frame.grid.x * 2.0 / float(n - 1) + 1e-3;
  // Constant indices into the sampler array (a loop index would be dynamic descriptor indexing).
  vec3 d = vec3(0.0);
  int count = int(frame.grid.w);
#define LAGOON_CASCADE(c)                                                                              \
  if (count > c) {                                                                                     \
    float lod = max(0.0, log2(spacing / frame.cascade_texel[c]));                                      \
    d += textureLod(displacement[c], vec3(xz / frame.cascade_patch[c], frame.cascade_layer[c]), lod).xyz; \
  }
  LAGOON_CASCADE(0)
  LAGOON_CASCADE(1)
  LAGOON_CASCADE(2)
  LAGOON_CASCADE(3)
  v_world = vec3(xz.x + d.x, d.y, xz.y + d.z);
  v_rest = xz;
  gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
