#version 450
#extension GL_GOOGLE_include_directive : require
// Transforms the four packed fields along columns (z), all stages, then assembles each output texel:
// displacement (λDx, h, λDz) and foam, the normal from the slopes and the Jacobian of the horizontal map
// x -> x + λD:  J = (1 + λ∂Dx/∂x)(1 + λ∂Dz/∂z) - (λ∂Dx/∂z)².  Foam builds where J < threshold and decays:
// foam = max(previous · exp(-decay·dt), clamp(threshold - J, 0, 1)).
// Workgroup: (FFT_LINES columns) x (FFT_N/16 work items), so neighbouring lanes read neighbouring columns;
// groups (N / FFT_LINES, 1, cascades).
#include "shared/ocean.h"
#include "common/fft_line.glsl"

layout(local_size_x_id = LAGOON_FFT_SPEC_GROUP_X, local_size_y_id = LAGOON_FFT_SPEC_GROUP_Y) in;
layout(constant_id = LAGOON_FFT_SPEC_LINES) const int FFT_LINES = 4;

layout(std430, binding = LAGOON_OCEAN_BIND_FIELDS) readonly buffer Src { vec2 src[]; };
layout(std430, binding = LAGOON_OCEAN_BIND_TWIDDLES) readonly buffer Twiddles { vec2 twiddles[]; };
layout(rgba32f, binding = LAGOON_OCEAN_BIND_DISPLACEMENT) uniform image2DArray displacement;  // (λDx, h, λDz, foam); foam read back
layout(rgba32f, binding = LAGOON_OCEAN_BIND_NORMAL_JACOBIAN) writeonly uniform image2DArray normal_jacobian;  // (nx, ny, nz, J)
// (λ∂Dx/∂x, λ∂Dz/∂z, λ∂Dx/∂z, foam): the renderer sums the terms over cascades for the whole sea's
// Jacobian; foam is repeated here so that the surface shader needs this texture and the normals only.
layout(rgba16f, binding = LAGOON_OCEAN_BIND_JACOBIAN_TERMS) writeonly uniform image2DArray jacobian_terms;
layout(push_constant) uniform Push { OceanPush p; };
#include "common/ocean_assemble.glsl"

shared vec2 exchange[FFT_LINES * 4 * FFT_N];  // [line][field][element]

void main() {
  const int n = FFT_N;
  int line = int(gl_LocalInvocationID.x);
  int w = int(gl_LocalInvocationID.y);
  int column = int(gl_WorkGroupID.x) * FFT_LINES + line;
  int cascade = int(gl_WorkGroupID.z);
  int plane = n * n, in_base = cascade * 4 * plane + column;

  vec2 f0[16], f1[16], f2[16], f3[16];
  int radix = fft_stage_radix(0);
  for (int b = 0; b < 16 / radix; ++b) {
    for (int r = 0; r < radix; ++r) {
      int at = in_base + fft_read_index(fft_butterfly(w, b, radix), r, radix) * n, q = b * radix + r;
      f0[q] = src[at];
      f1[q] = src[at + plane];
      f2[q] = src[at + 2 * plane];
      f3[q] = src[at + 3 * plane];
    }
  }
  int base = line * 4 * n;
  for (int stage = 0; stage < FFT_STAGES; ++stage) {
    radix = fft_stage_radix(stage);
    int ns = fft_stage_stride(stage);
    if (stage > 0) {
      barrier();
      for (int b = 0; b < 16 / radix; ++b) {
        for (int r = 0; r < radix; ++r) {
          int j = fft_butterfly(w, b, radix), at = base + fft_read_index(j, r, radix), q = b * radix + r;
          vec2 tw = fft_twiddle(twiddles[fft_twiddle_index(j, r, radix, ns)]);
          f0[q] = cmul(exchange[at], tw);
          f1[q] = cmul(exchange[at + n], tw);
          f2[q] = cmul(exchange[at + 2 * n], tw);
          f3[q] = cmul(exchange[at + 3 * n], tw);
        }
      }
      if (stage + 1 < FFT_STAGES) barrier();
    }
    fft_stage_registers(f0, radix);
    fft_stage_registers(f1, radix);
    fft_stage_registers(f2, radix);
    fft_stage_registers(f3, radix);
    if (stage + 1 < FFT_STAGES) {
      for (int b = 0; b < 16 / radix; ++b) {
        for (int r = 0; r < radix; ++r) {
          int at = base + fft_write_index(fft_butterfly(w, b, radix), r, radix, ns), q = b * radix + r;
          exchange[at] = f0[q];
          exchange[at + n] = f1[q];
          exchange[at + 2 * n] = f2[q];
          exchange[at + 3 * n] = f3[q];
        }
      }
    }
  }

  int ns = fft_stage_stride(FFT_STAGES - 1);
  for (int b = 0; b < 16 / radix; ++b) {
    for (int r = 0; r < radix; ++r) {
      int q = b * radix + r;
      ivec3 texel = ivec3(column, fft_write_index(fft_butterfly(w, b, radix), r, radix, ns), cascade);
      ocean_assemble(texel, f0[q], f1[q], f2[q], f3[q]);
    }
  }
}
