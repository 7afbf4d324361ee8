#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/mesh.h"
#include "common/light.glsl"
#include "common/tonemap.glsl"

// LAGOON_MESH_LIT: lit radiance above the water, tone-mapped for display (the surface pass writes the final
// frame). LAGOON_MESH_REFRACTION: albedo only, for the refraction pass; the water's light
// transport (the LUTs) lights it in the surface pass. LAGOON_MESH_MIRRORED: lit, mirrored, only what is above
// the water. LAGOON_MESH_WINDOW: lit, only what is above the water, into the Snell's window map.
layout(std140, binding = LAGOON_MESH_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_MESH_BIND_ALBEDO) uniform sampler2D albedo_texture;
layout(std430, binding = LAGOON_MESH_BIND_LIGHTS) readonly buffer Lights { PointLightGpu point_lights[]; };
layout(push_constant) uniform Push { MeshPush p; };
layout(constant_id = LAGOON_MESH_SPEC_MODE) const uint kMode = LAGOON_MESH_LIT;

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 0) out vec4 out_colour;

void main() {
  const uint mode = kMode;
  if (mode == LAGOON_MESH_REFRACTION && v_world.y > 0.0) discard;  // the refraction pass sees only what is under the water
  if (mode != LAGOON_MESH_REFRACTION && v_world.y < 0.0) discard;  // above-water passes see only what is above
  vec3 albedo = p.base_colour.rgb;
  if (p.base_colour.a > 0.5) albedo *= texture(albedo_texture, v_uv).rgb;
  if (mode == LAGOON_MESH_REFRACTION) {
    out_colour = vec4(albedo, 1.0);
    return;
  }
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = frame.sun_dir.xyz;
  // Lambert under the sun and a sky hemisphere (brighter from above), in white units.
  vec3 light = frame.sun_irradiance.rgb * max(dot(n, l), 0.0) + frame.sky_radiance.rgb * (0.6 + 0.4 * n.y);
  // Point lights: Lambert plus a Blinn-Phong highlight (seed 001's lighting model).
  vec3 v = normalize(frame.camera_pos.xyz - v_world);
  vec3 highlight = vec3(0.0);
  for (int i = 0; i < int(frame.lights.x); ++i) {
    vec3 to_light;
    vec3 irradiance = point_light_irradiance(point_lights[i], v_world, n, to_light);
    light += irradiance;
    highlight += irradiance * 0.04 * (32.0 + 2.0) / 8.0 * pow(max(dot(n, normalize(to_light + v)), 0.0), 32.0);
  }
  vec3 radiance = albedo * light + highlight;
  out_colour = vec4(mode == LAGOON_MESH_LIT ? display_encode(frame, radiance) : radiance, 1.0);
}
