#version 450
// The dynamic wave layer's step in the Fourier domain (compute/ocean/dynamic_layer.h): each mode k of the
// transformed state h + i dh/dt is split into H(k) and V(k) with the mode -k (h and dh/dt are real), advanced
// exactly toward the sources' depression in `substeps` parts, and packed again, scaled for the unnormalised
// inverse transform that follows.
#extension GL_GOOGLE_include_directive : require
#include "shared/dynamic_layer.h"
#define dl_real float
#define dl_real2 vec2
#define dl_real4 vec4
#include "shared/dynamic_layer_math.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std430, binding = LAGOON_DYNAMIC_BIND_SPECTRUM) readonly buffer Spectrum { vec2 z[]; };
layout(std430, binding = LAGOON_DYNAMIC_BIND_EVOLVED) writeonly buffer Evolved { vec2 evolved[]; };
layout(std430, binding = LAGOON_DYNAMIC_BIND_SOURCES) readonly buffer Sources { DynamicSource sources[]; };
layout(push_constant) uniform Push { DynamicPush p; };

vec2 conj2(vec2 a) { return vec2(a.x, -a.y); }

void main() {
  int n = int(p.n);
  ivec2 m = ivec2(gl_GlobalInvocationID.xy);
  if (m.x >= n || m.y >= n) return;
  ivec2 minus = ivec2((n - m.x) % n, (n - m.y) % n);
  vec2 zk = z[m.y * n + m.x], zm = conj2(z[minus.y * n + minus.x]);
  vec2 h = 0.5 * (zk + zm);
  vec2 d = 0.5 * (zk - zm);  // V = d / i
  vec4 hv = vec4(h, d.y, -d.x);
  vec2 k = dl_wavevector(m.x, m.y, n, p.cell);
  float sub = p.dt / float(p.substeps);
  vec4 turn = dl_turn(dl_omega(length(k), p.gravity, p.depth), sub);
  float decay = exp(-p.decay_per_s * sub);
  // The step is linear in the state and the forcing: the free evolution of the state plus, for each source,
  // the response to it alone from rest. Each source's transform is taken at the first part's middle and
  // shifted from part to part by one complex multiply.
  vec4 free_hv = hv;
  for (uint s = 0u; s < p.substeps; ++s) free_hv = dl_evolve(free_hv, vec2(0.0), turn, decay);
  hv = free_hv;
  for (uint i = 0u; i < p.source_count; ++i) {
    DynamicSource src = sources[p.source_first + i];
    float exponent = dl_source_exponent(k, src.along, src.sigma, src.depth);
    if (exponent < kDlNegligible) continue;
    vec2 e = dl_source_hat(k, src.centre + src.velocity * (0.5 * sub), exponent, src.sigma, src.depression, p.cell);
    vec2 shift = dl_source_shift(k, src.velocity, sub);
    vec4 forced = vec4(0.0);
    for (uint s = 0u; s < p.substeps; ++s) {
      forced = dl_evolve(forced, e, turn, decay);
      e = dl_complex_mul(e, shift);
    }
    hv += forced;
  }
  float scale = 1.0 / (float(n) * float(n));
  evolved[m.y * n + m.x] = scale * (hv.xy + vec2(-hv.w, hv.z));  // H + i V
}
