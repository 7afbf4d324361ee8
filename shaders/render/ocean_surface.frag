#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/mesh.h"
#include "shared/surface.h"
#include "common/light.glsl"
#include "common/tonemap.glsl"

// The water surface: normal from the cascades' slopes, exact dielectric Fresnel between the reflected sky
// (plus the sun's glint) and the water's own colour from the optics LUT (deep water), foam from the foam
// textures, haze towards the horizon. Output: the radiance (white units), tone-mapped for display.
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_NORMAL_JACOBIAN) uniform sampler2DArray normal_jacobian[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_SURFACE_BIND_REFRACTION_ALBEDO) uniform sampler2D refraction_albedo;  // floor and submerged objects: albedo, a = coverage
layout(binding = LAGOON_SURFACE_BIND_REFRACTION_DEPTH) uniform sampler2D refraction_depth;
layout(binding = LAGOON_SURFACE_BIND_LUT_T0) uniform sampler2D lut_t0;             // (T0 RGB, a) over (u, v) = (sqrt(r/r_max), sqrt(h/h_max))
layout(binding = LAGOON_SURFACE_BIND_LUT_T1) uniform sampler2D lut_t1;
layout(binding = LAGOON_SURFACE_BIND_REFLECTION) uniform sampler2D reflection;  // mirrored objects above the water; a = coverage
layout(std430, binding = LAGOON_SURFACE_BIND_LIGHTS) readonly buffer Lights { PointLightGpu point_lights[]; };
layout(binding = LAGOON_SURFACE_BIND_CAUSTICS) uniform sampler2DArray caustic_map;
layout(binding = LAGOON_SURFACE_BIND_UW_TARGET) uniform sampler2D uw_target;
layout(binding = LAGOON_SURFACE_BIND_UW_DOWN) uniform sampler2D uw_down;
layout(binding = LAGOON_SURFACE_BIND_UW_UP) uniform sampler2D uw_up;
layout(binding = LAGOON_SURFACE_BIND_JACOBIAN_TERMS) uniform sampler2DArray jacobian_terms[LAGOON_MAX_CASCADES];  // (λ∂Dx/∂x, λ∂Dz/∂z, λ∂Dx/∂z, foam)

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_rest;
layout(location = 0) out vec4 out_colour;

#include "common/surface_normal.glsl"
#include "common/refracted_hit.glsl"
#include "common/caustics.glsl"
#include "common/underwater.glsl"
#include "common/underwater_lamps.glsl"
#include "common/sediment.glsl"
#include "common/shore_foam.glsl"

// The light leaving the water towards the viewer below the surface, in white units: eq. 22 with the floor
// point C seen along the refracted ray, r and h measured along that ray (docs/optics.md), or the deep-water
// colour where there is no floor within the LUT's depth. `lamps`: what the point lights under the water add
// to it, in white units (not relative to the sun), the floor lit as if horizontal (no normals under water).
// `seen_m`: how far along the refracted ray the light comes from (the floor, or the LUT's depth); `depth_m`:
// the still water's depth there, to the floor or a submerged object (1e6 where none is seen).
vec3 water_radiance(vec3 n, vec3 v, out vec3 lamps, out float seen_m, out float depth_m) {
  lamps = vec3(0.0);
  depth_m = 1e6;
  vec3 deep = frame.water_deep.rgb;
  vec3 t = refract(-v, n, 1.0 / frame.sun_dir.w);
  float down = max(-t.y, 0.05);
  seen_m = frame.lut.y / down;
  if (frame.lut.z < 0.5) return deep;
  float depth;
  vec2 uv = refracted_hit(v_world, t, seen_m, depth);
  // The texel whose depth was read (nearest): a filtered albedo would blend an object's edge into the floor
  // beside it, and outline every object where the search lands beside it.
  vec4 albedo = texelFetch(refraction_albedo, refraction_texel(uv), 0);
  if (albedo.a < 0.5) return deep;
  vec3 floor_point = world_of(uv, depth);
  float h = max(v_world.y - floor_point.y, 0.0);
  float l = h / down;
  seen_m = l;
  depth_m = max(-floor_point.y, 0.0);  // below the mean level: breaking depends on the still-water depth
  float r = l * sqrt(max(1.0 - t.y * t.y, 0.0));
  vec2 lut_uv = vec2(sqrt(clamp(r / frame.lut.x, 0.0, 1.0)), sqrt(clamp(h / frame.lut.y, 0.0, 1.0)));
  vec4 t0 = texture(lut_t0, lut_uv);
  vec3 t1 = texture(lut_t1, lut_uv).rgb;
  vec3 through = t0.a * t0.rgb * albedo.rgb * caustic_gain(floor_point.xz, -floor_point.y) + (1.0 - t0.a) * t1;
  if (kUnderwaterLamps)  // compiled out without lights (shared/surface.h)
    lamps = albedo.rgb * lamp_irradiance(floor_point, vec3(0.0, 1.0, 0.0)) * underwater_transmittance(l);
  return mix(through, deep, smoothstep(0.8, 1.0, h / frame.lut.y));
}


void main() {
  vec3 v = normalize(frame.camera_pos.xyz - v_world);
  SurfaceSample ss = surface_sample(v);
  vec3 n = ss.normal;
  float foam = ss.foam, mss = ss.mss;
  vec3 l = frame.sun_dir.xyz;
  float ior = frame.sun_dir.w;
  float fresnel = fresnel_dielectric(dot(n, v), ior);

  vec3 r = reflect(-v, n);
  vec3 reflected = sky_radiance(frame, r, false);
  vec2 mirror_uv = gl_FragCoord.xy * frame.screen.zw + n.xz * vec2(0.03, -0.03);
  // Outside the reflection texture there is nothing mirrored to show: the sky is the fallback.
  if (all(greaterThanEqual(mirror_uv, vec2(0.0))) && all(lessThanEqual(mirror_uv, vec2(1.0)))) {
    vec4 mirrored = texture(reflection, mirror_uv);
    reflected = mix(reflected, mirrored.rgb, mirrored.a);
  }
  // Sun glint: normalised Blinn-Phong lobe (seed 001's model) with Fresnel at the half vector; its exponent
  // from the unresolved mean square slope (the Beckmann equivalent: s = 2/mss - 2).
  vec3 h = normalize(l + v);
  float shininess = clamp(2.0 / max(mss, 1e-4) - 2.0, 8.0, 4000.0);
  float glint = (shininess + 2.0) / 8.0 * pow(max(dot(n, h), 0.0), shininess) *
                fresnel_dielectric(dot(h, v), ior) * max(dot(n, l), 0.0);
  vec3 lamps;
  float seen_m, depth_m;
  vec3 below = water_radiance(n, v, lamps, seen_m, depth_m) * frame.lut.w + lamps;
  foam = max(foam, shore_foam(depth_m));
  below = sediment_veil(below, v_world, refract(-v, n, 1.0 / ior), seen_m, true);
  vec3 surface = fresnel * reflected + glint * frame.sun_irradiance.rgb + (1.0 - fresnel) * below;
  // Point lights: Blinn-Phong highlights on the water (seed 001), same lobe as the sun's.
  for (int i = 0; i < int(frame.lights.x); ++i) {
    vec3 to_light;
    vec3 irradiance = point_light_irradiance(point_lights[i], v_world, n, to_light);
    vec3 hl = normalize(to_light + v);
    surface += irradiance * (shininess + 2.0) / 8.0 * pow(max(dot(n, hl), 0.0), shininess) *
               fresnel_dielectric(dot(hl, v), ior);
  }

  vec3 lit_white = frame.sun_irradiance.rgb * max(dot(n, l), 0.0) + frame.sky_radiance.rgb;
  surface = mix(surface, frame.water_deep.w * lit_white, clamp(foam, 0.0, 1.0));

  // Aerial perspective: far water fades into the horizon sky.
  float dist = length(v_world.xz - frame.camera_pos.xz);
  float haze = 1.0 - exp(-dist / frame.grid.z);
  surface = mix(surface, sky_radiance(frame, vec3(-v.x, 0.0, -v.z), false), haze);
  out_colour = vec4(display_encode(frame, surface), 1.0);
  if (ss.dry) discard;  // a beach's sand above the water (common/shoaling.glsl), after the derivatives
}
