#version 450
#extension GL_GOOGLE_include_directive : require
// The last Stockham pass along columns (z) for the four packed fields, then assembly of each output texel:
// displacement (λDx, h, λDz) and foam, the normal from the slopes and the Jacobian of the horizontal map
// x -> x + λD:  J = (1 + λ∂Dx/∂x)(1 + λ∂Dz/∂z) - (λ∂Dx/∂z)².  Foam builds where J < threshold and decays:
// foam = max(previous · exp(-decay·dt), clamp(threshold - J, 0, 1)).
// One butterfly of one column per invocation. Two neighbouring columns per invocation (vec4 loads) ran ~3 %
// faster on lavapipe, but the assembly is inlined once per output, and LLVM took ~1.6 s to compile the 32
// of them: a cold start's largest single cost. With 16 it takes ~0.6 s (docs/building.md).
#include "shared/ocean.h"
#include "common/fft.glsl"

layout(local_size_x_id = LAGOON_FFT_SPEC_GROUP_X, local_size_y_id = LAGOON_FFT_SPEC_GROUP_Y) in;

layout(std430, binding = LAGOON_OCEAN_BIND_FIELDS) readonly buffer Src { vec2 src[]; };
layout(std430, binding = LAGOON_OCEAN_BIND_TWIDDLES) readonly buffer Twiddles { vec2 twiddles[]; };
layout(rgba32f, binding = LAGOON_OCEAN_BIND_DISPLACEMENT) uniform image2DArray displacement;  // (λDx, h, λDz, foam); foam read back
layout(rgba32f, binding = LAGOON_OCEAN_BIND_NORMAL_JACOBIAN) writeonly uniform image2DArray normal_jacobian;  // (nx, ny, nz, J)
// (λ∂Dx/∂x, λ∂Dz/∂z, λ∂Dx/∂z, foam): the renderer sums the terms over cascades for the whole sea's
// Jacobian; foam is repeated here so that the surface shader needs this texture and the normals only.
layout(rgba16f, binding = LAGOON_OCEAN_BIND_JACOBIAN_TERMS) writeonly uniform image2DArray jacobian_terms;
layout(push_constant) uniform Push { OceanPush p; };
#include "common/ocean_assemble.glsl"
layout(constant_id = LAGOON_OCEAN_SPEC_FOAM_ONLY) const bool kFoamOnly = false;

// A foam-only step's last pass (warm-ups): F2 and F3, fields 0 and 1 of two per cascade; the foam alone.
void assemble_foam(int column, int j, int cascade) {
  const int n = FFT_N;
  int plane = n * n;
  int base = cascade * 2 * plane + column;
  vec2 w[FFT_RADIX];
  FFT_LOAD_TWIDDLES(twiddles, j, w);
  vec2 a2[FFT_RADIX], a3[FFT_RADIX];
  for (int r = 0; r < FFT_RADIX; ++r) {
    int at = base + fft_source_index(j, r) * n;
    a2[r] = cmul(src[at], w[r]);
    a3[r] = cmul(src[at + plane], w[r]);
  }
  fft_radix(a2);
  fft_radix(a3);
  for (int r = 0; r < FFT_RADIX; ++r)
    ocean_assemble_foam(ivec3(column, fft_dest_index(j, r), cascade), a2[r], a3[r]);
}

void main() {
  const int n = FFT_N;
  int column = int(gl_GlobalInvocationID.x);
  int j = int(gl_GlobalInvocationID.y);
  int cascade = int(gl_GlobalInvocationID.z);
  if (j >= n / FFT_RADIX || column >= n || cascade >= int(p.cascades)) return;
  if (kFoamOnly) {
    assemble_foam(column, j, cascade);
    return;
  }
  int plane = n * n;
  int base = cascade * 4 * plane + column;
  vec2 w[FFT_RADIX];
  FFT_LOAD_TWIDDLES(twiddles, j, w);
  vec2 a0[FFT_RADIX], a1[FFT_RADIX], a2[FFT_RADIX], a3[FFT_RADIX];
  for (int r = 0; r < FFT_RADIX; ++r) {
    int at = base + fft_source_index(j, r) * n;
    a0[r] = cmul(src[at], w[r]);
    a1[r] = cmul(src[at + plane], w[r]);
    a2[r] = cmul(src[at + 2 * plane], w[r]);
    a3[r] = cmul(src[at + 3 * plane], w[r]);
  }
  fft_radix(a0);
  fft_radix(a1);
  fft_radix(a2);
  fft_radix(a3);
  for (int r = 0; r < FFT_RADIX; ++r)
    ocean_assemble(ivec3(column, fft_dest_index(j, r), cascade), a0[r], a1[r], a2[r], a3[r]);
}
