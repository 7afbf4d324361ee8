// The sum of directly evaluated waves (shared/direct_waves.h; models gerstner and sines with their own waves)
// at a rest position: what the cascades' textures give for the other models, evaluated where it is drawn, so
// every wave keeps its exact wavelength and its own steepness and nothing tiles. One definition for every
// shader that sums the water's motion (surface vertices and fragments, AOVs, waterline, caustics) and for
// the step that writes the first cascade's layer (ocean/direct_waves.comp).
// Reads the frame's waves (`frame`, FrameUniforms, declared by the includer) unless the includer defines
// `LAGOON_DIRECT_WAVE(i)` (the i-th DirectWaveGpu) and `LAGOON_DIRECT_COUNT` (how many) itself.
#ifndef LAGOON_COMMON_DIRECT_WAVES_GLSL
#define LAGOON_COMMON_DIRECT_WAVES_GLSL
#include "shared/direct_waves.h"
#ifndef LAGOON_DIRECT_WAVE
#define LAGOON_DIRECT_WAVE(i) frame.direct_waves[i]
#define LAGOON_DIRECT_COUNT kDirectWaveCount
// The frame's waves are drawn over the floor (common/shoaling.glsl); the step's layer is the deep sea's.
#define LAGOON_DIRECT_OVER_FLOOR 1
#include "common/shoaling.glsl"
#endif

#define dw_real float
#define dw_real2 vec2
#include "shared/direct_waves_math.h"

// How many waves the frame sums (0: none; the step's shader says 1 and takes its count from its push
// constants). A constant, not the frame's uniform: lavapipe (Mesa 22.3) re-inlines the uniforms a vertex
// shader's loop or branch depends on at every draw and kept each variant (model gerstner's frames grew
// 0.2 MiB each in `lagoon soak`).
layout(constant_id = LAGOON_SPEC_DIRECT_WAVES) const int kDirectWaveCount = 0;
const bool kDirectWaves = kDirectWaveCount > 0;

struct DirectSum {
  vec3 displacement;  // (Dx, h, Dz): where the point resting at the rest position has moved
  vec2 slope;  // (∂h/∂x, ∂h/∂z) of the displaced surface (through the horizontal map, as eq. 11 draws it)
  vec3 terms;  // (∂Dx/∂x0, ∂Dz/∂z0, ∂Dx/∂z0): the Jacobian's terms, as the cascades' jacobian_terms
  float breaking;  // 0..1: foam of waves breaking over the floor, on their crests and in the surf behind
};

// ω t reduced to [-π, π) in float with the product's low bits kept (as common/ocean_fields.glsl's phase).
float dw_turn(float omega, float t) {
  float hi = omega * t;
  float lo = fma(omega, t, -hi);
  float q = round(hi * 0.15915494309189535);
  return fma(-q, -1.7484556000744487e-7, fma(-q, 6.2831854820251465, hi)) + lo;
}

// The waves at `rest` and time `t` (0 where the phases already hold the time, as the frame's do). A wave
// whose shortest harmonic is below four `filter_m` fades out, gone at two: the mips' job for the cascades
// (filter_m = the mesh spacing for vertices, the pixel's footprint for fragments, 0 = every wave).
DirectSum direct_waves_at(vec2 rest, float t, float filter_m) {
  DirectSum s = DirectSum(vec3(0.0), vec2(0.0), vec3(0.0), 0.0);
  if (!kDirectWaves) return s;
  vec2 dy = vec2(0.0);  // ∂h/∂x0
  int count = int(LAGOON_DIRECT_COUNT);
#ifdef LAGOON_DIRECT_OVER_FLOOR
  ShoalPoint floor_here;
  if (kShoaling) floor_here = shoal_point(rest);
  float crest = 0.0, weight = 0.0;  // the waves' crests here, weighted by their heights
#endif
  for (int i = 0; i < count; ++i) {
    DirectWaveGpu w = LAGOON_DIRECT_WAVE(i);
    vec2 kv = w.wave.xy;  // its wavevector, amplitude and phase offset here
    float amplitude = w.wave.w, offset = 0.0, q = w.shape.x;
#ifdef LAGOON_DIRECT_OVER_FLOOR
    if (kShoaling) {
      vec2 u = frame.shoaling_axis.zw;
      vec4 local = shoal_wave(floor_here, i, kv);
      kv = local.z * u + local.w * vec2(-u.y, u.x);
      amplitude = local.y;
      offset = local.x;
      q *= floor_here.ground.z;
    }
#endif
    float k = length(kv);
    float shortest = 6.2831853 / (k * max(w.shape.y, 1.0));
    float a = amplitude * clamp(shortest / (2.0 * max(filter_m, 1e-6)) - 1.0, 0.0, 1.0);
    if (a == 0.0) continue;
    vec2 d = kv / k;
    float theta = dot(w.wave.xy, rest) + w.wave.z + offset - (t != 0.0 ? dw_turn(w.shape.w, t) : 0.0);
    vec2 g = dw_profile(theta, w.shape.y, w.shape.z);
    float qa = q * a, sn = sin(theta), cs = cos(theta);
    s.displacement += vec3(-qa * d.x * sn, a * g.x, -qa * d.y * sn);
    dy += a * g.y * kv;
    s.terms -= qa * k * cs * vec3(d.x * d.x, d.y * d.y, d.x * d.y);
#ifdef LAGOON_DIRECT_OVER_FLOOR
    crest += a * pow(0.5 + 0.5 * cs, 6.0);
    weight += a;
#endif
  }
#ifdef LAGOON_DIRECT_OVER_FLOOR
  // Breaking starts where the summed height reaches γ h (ratio 1): white on the crests as they spill, and the
  // surf behind them churned.
  if (kShoaling) {
    float onset = smoothstep(0.95, 1.4, floor_here.ground.w);
    s.breaking = onset * smoothstep(0.35, 0.85, crest / max(weight, 1e-6)) * step(0.0, floor_here.ground.x);
  }
#endif
  // The displaced surface's slope: ∇h through the inverse of the horizontal map's Jacobian (symmetric).
  float jxx = 1.0 + s.terms.x, jzz = 1.0 + s.terms.y, jxz = s.terms.z;
  float det = max(jxx * jzz - jxz * jxz, 0.05);
  s.slope = vec2(jzz * dy.x - jxz * dy.y, jxx * dy.y - jxz * dy.x) / det;
  return s;
}

#endif
