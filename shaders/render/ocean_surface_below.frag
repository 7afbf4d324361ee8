#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"
#include "common/light.glsl"
#include "common/tonemap.glsl"

// The water surface seen from below. Exact Fresnel from the water side: inside Snell's window (incidence
// below asin(1/n), 48.6° for n = 1.333) the sky and sun come through, refracted and compressed, their radiance
// raised by n² (radiance/n² is invariant across the boundary), and the objects above the water
// (common/snell_window.glsl) in front of the sky; beyond it total internal reflection mirrors
// the water below. Then the water between the surface and the camera (common/underwater.glsl) and the
// sediment clouds in it (common/sediment.glsl).
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_NORMAL_JACOBIAN) uniform sampler2DArray normal_jacobian[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_SURFACE_BIND_JACOBIAN_TERMS) uniform sampler2DArray jacobian_terms[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_SURFACE_BIND_UW_TARGET) uniform sampler2D uw_target;
layout(binding = LAGOON_SURFACE_BIND_UW_DOWN) uniform sampler2D uw_down;
layout(binding = LAGOON_SURFACE_BIND_UW_UP) uniform sampler2D uw_up;
layout(binding = LAGOON_SURFACE_BIND_CAUSTICS) uniform sampler2DArray caustic_map;
layout(binding = LAGOON_SURFACE_BIND_WINDOW) uniform sampler2D window_map;         // premultiplied, a = coverage

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_rest;
layout(location = 0) out vec4 out_colour;

#include "common/surface_normal.glsl"
#include "common/underwater.glsl"
#include "common/caustics.glsl"
#include "common/light_shafts.glsl"
#include "common/snell_window.glsl"
#include "common/sediment.glsl"

vec3 mirrored_below(vec3 r) {
  float down = max(-r.y, 0.02);
  float floor_depth = frame.floor_below.x;
  // Selects rather than a branch: lavapipe would run both sides' lookups.
  bool floor_seen = floor_depth > 0.0 && floor_depth / down <= frame.underwater.x;
  float d = floor_seen ? floor_depth / down : frame.underwater.x;
  float mean_depth = 0.5 * (floor_seen ? floor_depth : min(frame.underwater.x * down, frame.underwater.y));
  vec3 floor_light = floor_seen ? frame.floor_below.y * underwater_target(d, floor_depth).rgb : vec3(0.0);
  return floor_light + underwater_added(d, mean_depth, r.y);
}

// What a ray leaving the water along t (upward, in the air) meets: the objects above the water from the
// window picture (drawn as a flat surface shows them; the waves bend where it is looked up), over the sky.
vec3 seen_above(vec3 t) {
  vec3 sky = sky_radiance(frame, t, true);
  vec4 clip = frame.view_proj * vec4(frame.camera_pos.xyz + window_flat_direction(t), 1.0);
  if (clip.w <= 0.0) return sky;
  vec2 uv = vec2(0.5, -0.5) * clip.xy / clip.w + 0.5;  // the viewport flips y (vk/rendering.cpp)
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return sky;
  vec4 object = textureLod(window_map, uv, 0.0);  // premultiplied: a = coverage
  return sky * (1.0 - object.a) + object.rgb;
}

void main() {
  vec3 eye = frame.camera_pos.xyz;
  vec3 v = normalize(eye - v_world);  // towards the camera, below
  SurfaceSample ss = surface_sample(-v);
  vec3 n = -ss.normal;  // the surface's normal on the water side, facing the camera
  float ior = frame.sun_dir.w;
  float fresnel = fresnel_dielectric(dot(n, v), 1.0 / ior);  // from water into air: 1 beyond the critical angle
  vec3 t = refract(-v, n, ior);
  vec3 through = fresnel < 1.0 ? ior * ior * seen_above(t) : vec3(0.0);
  // What total internal reflection shows: the floor, taken as flat at its depth under the camera with the
  // water's mean bottom albedo, or the water below where there is no floor.
  vec3 r = reflect(-v, n);
  vec3 mirrored = mirrored_below(r) * frame.lut.w;
  vec3 surface = (1.0 - fresnel) * through + fresnel * mirrored;
  // Foam scatters the light that falls on it back up and some down: from below it is a dim white.
  surface = mix(surface, 0.5 * frame.water_deep.w * frame.lut.w * vec3(1.0), clamp(ss.foam, 0.0, 1.0));
  float d = length(eye - v_world);
  float camera_depth = max(-eye.y, 0.0);
  if (frame.water_volume.w > 0.5)
    surface = max(surface * underwater_transmittance(d) +
                      (underwater_added(d, 0.5 * (camera_depth + max(-v_world.y, 0.0)), -v.y) +
                       light_shafts(eye, -v, d, ivec2(gl_FragCoord.xy))) * frame.lut.w,
                  vec3(0.0));
  surface = sediment_veil(surface, eye, -v, d, frame.water_volume.w > 0.5);
  out_colour = vec4(display_encode(frame, surface), 1.0);
  if (ss.dry) discard;  // a beach's sand above the water (common/shoaling.glsl), after the derivatives
}
