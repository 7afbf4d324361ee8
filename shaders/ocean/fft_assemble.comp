#version 450
#extension GL_GOOGLE_include_directive : require
// The last Stockham pass along columns (z) for the four packed fields, then assembly of each output texel:
// displacement (λDx, h, λDz) and foam, the normal from the slopes and the Jacobian of the horizontal map
// x -> x + λD:  J = (1 + λ∂Dx/∂x)(1 + λ∂Dz/∂z) - (λ∂Dx/∂z)².  Foam builds where J < threshold and decays:
// foam = max(previous · exp(-decay·dt), clamp(threshold - J, 0, 1)).
#include "shared/ocean.h"
#include "common/fft.glsl"

layout(local_size_x_id = 0, local_size_y_id = 1) in;

layout(std430, binding = 0) readonly buffer Src { vec2 src[]; };
layout(std430, binding = 1) readonly buffer Twiddles { vec2 twiddles[]; };
layout(rgba32f, binding = 2) uniform image2DArray displacement;  // (λDx, h, λDz, foam); foam read back
layout(rgba32f, binding = 3) writeonly uniform image2DArray normal_jacobian;  // (nx, ny, nz, J)
layout(push_constant) uniform Push { OceanPush p; };

void main() {
  const int n = FFT_N;
  int column = int(gl_GlobalInvocationID.x);
  int j = int(gl_GlobalInvocationID.y);
  int cascade = int(gl_GlobalInvocationID.z);
  if (j >= n / FFT_RADIX || column >= n || cascade >= int(p.cascades)) return;

  int plane = n * n;
  int base = cascade * 4 * plane + column;
  vec2 f0[FFT_RADIX], f1[FFT_RADIX], f2[FFT_RADIX], f3[FFT_RADIX];
  for (int r = 0; r < FFT_RADIX; ++r) {
    vec2 w = fft_twiddle(twiddles[fft_twiddle_index(j, r)]);
    int at = base + fft_source_index(j, r) * n;
    f0[r] = cmul(src[at], w);
    f1[r] = cmul(src[at + plane], w);
    f2[r] = cmul(src[at + 2 * plane], w);
    f3[r] = cmul(src[at + 3 * plane], w);
  }
  fft_radix(f0);
  fft_radix(f1);
  fft_radix(f2);
  fft_radix(f3);

  float lambda = p.choppiness;
  float decay = exp(-p.foam_decay_per_s * p.dt_s);
  for (int r = 0; r < FFT_RADIX; ++r) {
    ivec3 texel = ivec3(column, fft_dest_index(j, r), cascade);
    float h = f0[r].y, sx = f1[r].y, sz = f2[r].x;
    float jxx = 1.0 + lambda * f2[r].y, jzz = 1.0 + lambda * f3[r].x, jxz = lambda * f3[r].y;
    float jacobian = jxx * jzz - jxz * jxz;
    float previous = p.reset_foam != 0u ? 0.0 : imageLoad(displacement, texel).w;
    float foam = max(previous * decay, clamp(p.foam_threshold - jacobian, 0.0, 1.0));
    imageStore(displacement, texel, vec4(lambda * f0[r].x, h, lambda * f1[r].x, foam));
    imageStore(normal_jacobian, texel, vec4(normalize(vec3(-sx, 1.0, -sz)), jacobian));
  }
}
