#version 450
// The dynamic wave layer's step in the Fourier domain (compute/ocean/dynamic_layer.h): each mode k of the
// transformed state h + i dh/dt is split into H(k) and V(k) with the mode -k (h and dh/dt are real), advanced
// exactly toward the sources' depression in `substeps` parts, and packed again, scaled for the unnormalised
// inverse transform that follows.
//
// H(-k) and V(-k) are the conjugates of H(k) and V(k), and the step's coefficients are real, so one
// invocation advances k and writes both k and -k: half the invocations, each load used twice. That holds
// where the bin of -k has the wavevector -k, everywhere but on the Nyquist lines (index n/2, whose
// wavevector is -π/cell on both sides): the pass with DL_NYQUIST set advances those 2n - 1 modes one by
// one. Dispatch: (n, n/2) invocations for the pairs, (2n, 1) for the Nyquist lines.
#extension GL_GOOGLE_include_directive : require
#include "shared/dynamic_layer.h"
#define dl_real float
#define dl_real2 vec2
#define dl_real4 vec4
#include "shared/dynamic_layer_math.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(constant_id = LAGOON_DYNAMIC_SPEC_NYQUIST) const bool DL_NYQUIST = false;

layout(std430, binding = LAGOON_DYNAMIC_BIND_SPECTRUM) readonly buffer Spectrum { vec2 z[]; };
layout(std430, binding = LAGOON_DYNAMIC_BIND_EVOLVED) writeonly buffer Evolved { vec2 evolved[]; };
// A uniform block, not a storage buffer: every invocation reads the same sources, and lavapipe loads a
// uniform block at a uniform offset once for the SIMD vector instead of once per lane.
layout(std140, binding = LAGOON_DYNAMIC_BIND_SOURCES) uniform Sources { DynamicSource sources[LAGOON_DYNAMIC_MAX_SOURCES]; };
layout(push_constant) uniform Push { DynamicPush p; };

vec2 conj2(vec2 a) { return vec2(a.x, -a.y); }

// (H.re, H.im, V.re, V.im) of mode m from its bin and the bin of -m.
vec4 split(vec2 zk, vec2 zminus) {
  vec2 zm = conj2(zminus);
  vec2 h = 0.5 * (zk + zm);
  vec2 d = 0.5 * (zk - zm);  // V = d / i
  return vec4(h, d.y, -d.x);
}

// H + i V, scaled for the unnormalised inverse transform.
vec2 pack(vec4 hv) {
  return (1.0 / (float(p.n) * float(p.n))) * (hv.xy + vec2(-hv.w, hv.z));
}

// Mode m advanced over the step.
vec4 advance(ivec2 m, vec4 hv) {
  vec2 k = dl_wavevector(m.x, m.y, int(p.n), p.cell);
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
    DynamicSource src = sources[i];
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
  return hv;
}

void main() {
  int n = int(p.n), half_n = n >> 1;
  ivec2 m;
  if (DL_NYQUIST) {
    // Column n/2, then row n/2 without the mode already in the column.
    int i = int(gl_GlobalInvocationID.x);
    if (gl_GlobalInvocationID.y != 0u || i >= 2 * n || i == n + half_n) return;
    m = i < n ? ivec2(half_n, i) : ivec2(i - n, half_n);
  } else {
    m = ivec2(gl_GlobalInvocationID.xy);
    // Rows 1 .. n/2 - 1 pair with rows n/2 + 1 .. n - 1; row 0 pairs with itself, its first half with its
    // second. The Nyquist lines are the other pass's.
    if (m.x >= n || m.y >= half_n || m.x == half_n || (m.y == 0 && m.x > half_n)) return;
  }
  ivec2 minus = (n - m) & (n - 1);  // n is a power of two: a mask, not a modulo (scalar on lavapipe)
  int at = m.y * n + m.x, at_minus = minus.y * n + minus.x;
  vec4 hv = advance(m, split(z[at], z[at_minus]));
  evolved[at] = pack(hv);
  if (!DL_NYQUIST && at_minus != at) evolved[at_minus] = pack(vec4(conj2(hv.xy), conj2(hv.zw)));
}
