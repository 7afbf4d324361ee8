// Looking through the water from below: the underwater tables (compute/optics/underwater.h, docs/optics.md),
// white units relative to the light above the water. Needs, declared by the includer: `frame`
// (FrameUniforms) and the samplers `uw_target`, `uw_down`, `uw_up` over (u, v) = (sqrt(d/d_max), sqrt(z/z_max)).
#ifndef LAGOON_COMMON_UNDERWATER_GLSL
#define LAGOON_COMMON_UNDERWATER_GLSL

vec2 underwater_uv(float d, float z) {
  return vec2(sqrt(clamp(d / frame.underwater.x, 0.0, 1.0)), sqrt(clamp(max(z, 0.0) / frame.underwater.y, 0.0, 1.0)));
}

// A white Lambertian horizontal target at depth z seen from d metres (rgb), and the share of its light that
// arrives forward-scattered (a).
vec4 underwater_target(float d, float z) {
  return texture(uw_target, underwater_uv(d, z));
}

// The light the water adds along a ray of d metres around depth z whose direction has vertical component
// dir_y: looking down it is the up-welling water, looking up the scattered down-welling light.
vec3 underwater_added(float d, float z, float dir_y) {
  vec2 uv = underwater_uv(d, z);
  return mix(texture(uw_down, uv).rgb, texture(uw_up, uv).rgb, clamp(0.5 + 0.5 * dir_y, 0.0, 1.0));
}

// The share of light leaving a point just below the surface with the spectrum of the light above that still
// arrives after d metres: the target's fall-off with distance at depth 0 (its value at d = 0 is constant,
// so it comes with the frame instead of a lookup per call).
vec3 underwater_transmittance(float d) {
  vec3 far_rgb = texture(uw_target, underwater_uv(d, 0.0)).rgb;
  return far_rgb / max(frame.underwater_top.rgb, vec3(1e-6));
}

#endif
