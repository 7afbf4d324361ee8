// Light shafts: the sun's beams, focused by the waves, seen in the water (a cheap volumetric estimate).
// The mean in-scattered light is already in the underwater tables; what the caustics add or take away
// along the view ray is marched here in 4 steps (jittered per pixel): at each point the beam's
// irradiance there, seen through the water between it and the camera (target(s, z), relative to the light
// above the water), times the caustic map's gain minus 1, scattered towards the camera by σ·p(θ) with a
// Henyey–Greenstein phase function. Needs, declared by the includer: `frame`, `caustic_map` and the
// underwater tables (common/caustics.glsl and common/underwater.glsl included first).
#ifndef LAGOON_COMMON_LIGHT_SHAFTS_GLSL
#define LAGOON_COMMON_LIGHT_SHAFTS_GLSL

// Off: the march is compiled out, not skipped at run time (a CPU device paid ~100 ms a 720p frame for the
// skipped loop).
layout(constant_id = LAGOON_UNDERWATER_SPEC_SHAFTS) const bool kLightShafts = true;

float henyey_greenstein(float cos_theta, float g) {
  float g2 = g * g;
  return (1.0 - g2) / (4.0 * 3.14159265 * pow(max(1.0 + g2 - 2.0 * g * cos_theta, 1e-4), 1.5));
}

// Radiance in white units relative to the light above the water (the caller scales by frame.lut.w) added
// along `length_m` metres of the ray from `eye` in `dir`.
vec3 light_shafts(vec3 eye, vec3 dir, float length_m, ivec2 pixel) {
  if (!kLightShafts || frame.water_volume.w < 0.5 || frame.caustics.w < 0.5) return vec3(0.0);
  vec3 beam = refract(-frame.sun_dir.xyz, vec3(0.0, 1.0, 0.0), 1.0 / frame.sun_dir.w);
  if (beam.y > -1e-3) return vec3(0.0);
  const int steps = 4;
  float ds = min(length_m, 30.0) / float(steps);
  float jitter = fract(52.9829189 * fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715))));  // interleaved gradient noise
  vec3 sum = vec3(0.0);
  for (int k = 0; k < steps; ++k) {
    float s = (float(k) + jitter) * ds;
    vec3 q = eye + dir * s;
    if (q.y >= 0.0) continue;
    sum += underwater_target(s, -q.y).rgb * (caustic_gain(q.xz, -q.y) - 1.0);
  }
  // White units are radiance per E_white/π: hence π. The beam's irradiance across itself is the horizontal
  // one over cos of its angle from the vertical.
  float scatter = 3.14159265 * frame.water_volume.x * henyey_greenstein(dot(beam, -dir), frame.water_volume.y);
  return sum * ds * scatter / max(-beam.y, 0.1);
}

#endif
