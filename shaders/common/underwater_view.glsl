// The underwater pass's view of everything but the surface (underwater_medium.frag draws it;
// underwater_terms.frag writes its terms for the dataset's ground truth, with LAGOON_UNDERWATER_TERMS
// defined): the floor and submerged objects (the refraction pass's albedo and depth) lit by the light that
// reaches their depth and seen through the water between them and the camera, or, where the view ray meets
// nothing, the water itself. Declares the pass's bindings.
#ifndef LAGOON_COMMON_UNDERWATER_VIEW_GLSL
#define LAGOON_COMMON_UNDERWATER_VIEW_GLSL
#include "shared/frame.h"
#include "shared/surface.h"
#include "common/light.glsl"

layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_REFRACTION_ALBEDO) uniform sampler2D refraction_albedo;  // a = coverage
layout(binding = LAGOON_SURFACE_BIND_REFRACTION_DEPTH) uniform sampler2D refraction_depth;
layout(binding = LAGOON_SURFACE_BIND_UW_TARGET) uniform sampler2D uw_target;
layout(binding = LAGOON_SURFACE_BIND_UW_DOWN) uniform sampler2D uw_down;
layout(binding = LAGOON_SURFACE_BIND_UW_UP) uniform sampler2D uw_up;
layout(binding = LAGOON_SURFACE_BIND_CAUSTICS) uniform sampler2DArray caustic_map;
layout(std430, binding = LAGOON_SURFACE_BIND_LIGHTS) readonly buffer Lights { PointLightGpu point_lights[]; };

#include "common/underwater.glsl"
#include "common/caustics.glsl"
#include "common/underwater_lamps.glsl"
#include "common/light_shafts.glsl"
#include "common/sediment.glsl"

// Forward scattering: the light from a target that was scattered into the phase function's forward peak
// arrives spread over a cone around the line of sight. Its share is the table's blur (optics/underwater.h);
// the cone's half-angle, ~2° for ocean particles' forward peak, is fixed here. The albedo seen through it is
// the refraction target's, averaged over 4 taps on a disc of that angular radius (in pixels, constant with
// distance: what grows with distance is the share).
const float kBlurHalfAngleRad = 0.035;

vec3 blurred_albedo(ivec2 pixel, vec3 sharp, float radius_px) {
  vec3 sum = sharp;
  float weight = 1.0;
  for (int k = 0; k < 4; ++k) {
    float r = radius_px * sqrt((float(k) + 0.5) / 4.0), a = 2.3999632 * float(k);  // a Vogel disc
    ivec2 tap = clamp(pixel + ivec2(round(r * vec2(cos(a), sin(a)))), ivec2(0), ivec2(frame.screen.xy) - 1);
    vec4 albedo = texelFetch(refraction_albedo, tap, 0);
    if (albedo.a > 0.5) sum += albedo.rgb, weight += 1.0;
  }
  return sum / weight;
}


struct UnderwaterView {
  vec3 radiance;  // what the pass draws, before the display encoding
  float depth;    // of the geometry, 1 (the far plane) where the ray meets nothing
#ifdef LAGOON_UNDERWATER_TERMS
  // The image formation model radiance = clean * transmission + backscatter (docs/datasets.md): the light
  // leaving what the ray meets (its sharp albedo lit at its depth, caustics and lamps included), the share of
  // it the water and the sediment let through to the camera, and the light they add along the ray (shafts
  // included). Exact but for the forward-scatter blur, which mixes in neighbouring pixels, and the lamps' light,
  // which the pass attenuates with the water's own transmittance.
  vec3 clean, transmission, backscatter;
#endif
};

UnderwaterView underwater_view(ivec2 pixel, vec2 ndc) {
  UnderwaterView view;
  float depth = texelFetch(refraction_depth, pixel, 0).r;
  vec4 albedo = texelFetch(refraction_albedo, pixel, 0);
  vec4 far_point = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
  vec3 eye = frame.camera_pos.xyz;
  vec3 dir = normalize(far_point.xyz / far_point.w - eye);
  float camera_depth = max(-eye.y, 0.0);
  vec4 p = frame.inv_view_proj * vec4(ndc, depth, 1.0);
  vec3 hit = p.xyz / p.w;
  // The refraction target holds no normals: the geometry's own, from the depth of neighbouring pixels
  // (outside any branch, where derivatives are defined).
  vec3 n = normalize(cross(dFdx(hit), dFdy(hit)));
  if (dot(n, dir) > 0.0) n = -n;
  float pixel_angle = max(length(dFdx(dir)), 1e-6);
  bool volume = frame.water_volume.w > 0.5;  // render.effects.underwater
  // Both sides of a branch run on lavapipe, so the water along the ray (two lookups) is looked up once, for
  // the distance and mean depth each case sets.
  bool hit_something = albedo.a > 0.5;
  float d = hit_something ? length(hit - eye) : frame.underwater.x;
  // Nothing within reach: the water to the end of the table (α below 1e-3 there for every Jerlov type).
  float end_depth = hit_something ? -hit.y : max(camera_depth - d * dir.y, 0.0);
  vec3 water = volume ? underwater_added(d, 0.5 * (camera_depth + end_depth), dir.y) + light_shafts(eye, dir, d, pixel)
                      : vec3(0.0);
  vec3 radiance = water * frame.lut.w;
#ifdef LAGOON_UNDERWATER_TERMS
  view.clean = vec3(0.0);
  view.transmission = vec3(1.0);
  view.backscatter = radiance;
#endif
  if (hit_something) {
    vec4 target = underwater_target(volume ? d : 0.0, -hit.y);
    vec3 seen = albedo.rgb;
    if (volume && target.a > 0.01) seen = mix(seen, blurred_albedo(pixel, seen, kBlurHalfAngleRad / pixel_angle), target.a);
    // The target's light at its own depth; the water's along the ray at the ray's mean depth. Both are
    // relative to the light above the water (scaled by frame.lut.w); the lamps are not.
    radiance += seen * target.rgb * caustic_gain(hit.xz, -hit.y) * frame.lut.w;
    if (kUnderwaterLamps)  // compiled out without lights (shared/surface.h)
      radiance += albedo.rgb * lamp_irradiance(hit, n) * (volume ? underwater_transmittance(d) : vec3(1.0));
#ifdef LAGOON_UNDERWATER_TERMS
    vec3 at_target = underwater_target(0.0, -hit.y).rgb;
    view.transmission = target.rgb / max(at_target, vec3(1e-12));
    view.clean = albedo.rgb * at_target * caustic_gain(hit.xz, -hit.y) * frame.lut.w;
    if (kUnderwaterLamps) view.clean += albedo.rgb * lamp_irradiance(hit, n);
#endif
  }
  vec4 veil = sediment_veil_terms(eye, dir, d, volume);
  radiance = radiance * veil.a + veil.rgb;
#ifdef LAGOON_UNDERWATER_TERMS
  view.transmission *= veil.a;
  view.backscatter = view.backscatter * veil.a + veil.rgb;
#endif
  view.depth = hit_something ? depth : 1.0;
  view.radiance = max(radiance, vec3(0.0));  // shafts darken where the caustics do, never below black
  return view;
}

#endif
