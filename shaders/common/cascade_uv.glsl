// Where a rest position (m) lies in cascade c's textures. Texel i holds the field at x = i·L/N (the FFT's
// grid), and a sampler puts texel i's value at coordinate (i + 0.5)/N, so the coordinate of x is
// x/L + 0.5/N: without the half texel every cascade would be drawn shifted by L/(2N), which decorrelates
// the short waves of a coarse cascade from the ocean WaveQuery and the exports describe.
// Needs `frame` (FrameUniforms) declared by the includer.
#ifndef LAGOON_COMMON_CASCADE_UV_GLSL
#define LAGOON_COMMON_CASCADE_UV_GLSL
#include "shared/limits.h"

layout(constant_id = LAGOON_SPEC_CASCADE_COUNT) const int kCascadeCount = LAGOON_MAX_CASCADES;

vec3 cascade_uvw(vec2 rest, int c) {
  return vec3((rest + 0.5 * frame.cascade_texel[c]) / frame.cascade_patch[c], frame.cascade_layer[c]);
}

#endif
