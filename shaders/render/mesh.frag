#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/mesh.h"
#include "shared/pbr.h"
#include "common/light.glsl"
#include "common/tonemap.glsl"

// glTF metallic-roughness materials under the glTF reference BRDF (shared/pbr.h), lit by the sun, the point
// lights and the pre-filtered sky (render/environment_map.h), in white units.
// LAGOON_MESH_LIT: above the water, tone-mapped for display (the surface pass writes the final frame).
// LAGOON_MESH_REFRACTION: albedo only, for the refraction pass; the water's light transport (the LUTs)
// lights it in the surface pass. LAGOON_MESH_MIRRORED: lit, mirrored, only what is above the water.
// LAGOON_MESH_WINDOW: lit, only what is above the water, into the Snell's window map. BLEND materials write
// their alpha; the pipeline blends them over what is drawn (render/scene_objects.cpp sorts them).
layout(std140, binding = LAGOON_MESH_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_MESH_BIND_ALBEDO) uniform sampler2D base_texture;
layout(binding = LAGOON_MESH_BIND_METAL_ROUGH) uniform sampler2D metal_rough_texture;
layout(binding = LAGOON_MESH_BIND_NORMAL) uniform sampler2D normal_texture;
layout(binding = LAGOON_MESH_BIND_OCCLUSION) uniform sampler2D occlusion_texture;
layout(binding = LAGOON_MESH_BIND_EMISSIVE) uniform sampler2D emissive_texture;
layout(binding = LAGOON_MESH_BIND_ENVIRONMENT) uniform sampler2DArray environment;
layout(binding = LAGOON_MESH_BIND_DFG) uniform sampler2D dfg_table;
layout(std430, binding = LAGOON_MESH_BIND_LIGHTS) readonly buffer Lights { PointLightGpu point_lights[]; };
layout(std430, binding = LAGOON_MESH_BIND_MATERIALS) readonly buffer Materials { MaterialGpu materials[]; };
layout(push_constant) uniform Push { MeshPush p; };
layout(constant_id = LAGOON_MESH_SPEC_MODE) const uint kMode = LAGOON_MESH_LIT;

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 3) in vec2 v_uv1;
layout(location = 4) in vec4 v_tangent;
layout(location = 5) in vec2 v_base_uv;  // the base colour texture's, transformed (mesh.vert)
layout(location = 0) out vec4 out_colour;

bool has_texture(MaterialGpu m, int i) { return ((m.flags.y >> i) & 1u) != 0u; }

// Texture i of the material at its set of coordinates (TEXCOORD_0 or 1) through its KHR_texture_transform.
// The gradients are the interpolated coordinates' own, transformed: lavapipe picks a blurrier mip level
// for a coordinate computed in the shader than for an interpolated one (the floor's sand at 10 m lost 15 %
// of its contrast at the same footprint).
vec4 material_texture(sampler2D tex, MaterialGpu m, int i) {
  bool second = ((m.flags.z >> i) & 1u) != 0u;
  vec2 uv = second ? v_uv1 : v_uv;
  vec2 dx = second ? dFdx(v_uv1) : dFdx(v_uv), dy = second ? dFdy(v_uv1) : dFdy(v_uv);
  mat2 linear = mat2(m.uv_rows[2 * i].x, m.uv_rows[2 * i + 1].x, m.uv_rows[2 * i].y, m.uv_rows[2 * i + 1].y);
  vec2 at = linear * uv + vec2(m.uv_rows[2 * i].z, m.uv_rows[2 * i + 1].z);
  return textureGrad(tex, at, linear * dx, linear * dy);
}

// The pre-filtered environment in direction d: `layer` may fall between two of its layers.
vec3 environment_light(vec3 d, float layer) {
  vec2 uv = env_uv(d);
  float l0 = floor(layer);
  vec3 a = textureLod(environment, vec3(uv, l0), 0.0).rgb;
  vec3 b = textureLod(environment, vec3(uv, min(l0 + 1.0, float(LAGOON_ENV_SPECULAR_LAYERS - 1))), 0.0).rgb;
  return mix(a, b, layer - l0);
}

// The shading normal: the interpolated normal (turned towards the viewer on a back face) through the
// material's normal map.
vec3 shading_normal(MaterialGpu m, bool front) {
  vec3 ng = normalize(v_normal) * (front ? 1.0 : -1.0);
  if (!has_texture(m, LAGOON_TEX_NORMAL)) return ng;
  vec3 tn = material_texture(normal_texture, m, LAGOON_TEX_NORMAL).xyz * 2.0 - 1.0;
  tn.xy *= m.pbr.z;
  vec3 t = v_tangent.xyz - ng * dot(ng, v_tangent.xyz);
  if (dot(t, t) < 1e-12) return ng;
  t = normalize(t);
  vec3 b = cross(ng, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
  return normalize(t * tn.x + b * tn.y + ng * tn.z);
}

void main() {
  const uint mode = kMode;
  // The refraction pass sees only what is under the water, and the procedural floor's dry sand beside it:
  // a refracted lookup near the waterline lands there on the screen (without it: grey notches along a beach).
  if (mode == LAGOON_MESH_REFRACTION && v_world.y > 0.0 && p.height_field == 0u) discard;
  if (mode != LAGOON_MESH_REFRACTION && v_world.y < 0.0) discard;  // above-water passes see only what is above
  MaterialGpu m = materials[p.material];
  // Mirroring the scene (reflection) turns its triangles' winding around.
  bool front = gl_FrontFacing != (mode == LAGOON_MESH_MIRRORED);
  if (m.flags.w == 0u && !front) discard;  // single-sided: back faces are culled
  vec4 base = m.base_colour;
  if (has_texture(m, LAGOON_TEX_BASE)) base *= texture(base_texture, v_base_uv);
  if (m.flags.x == LAGOON_ALPHA_MASK && base.a < m.emissive.w) discard;
  if (m.flags.x != LAGOON_ALPHA_BLEND) base.a = 1.0;
  if (mode == LAGOON_MESH_REFRACTION) {
    out_colour = vec4(base.rgb, p.height_field != 0u ? LAGOON_REFRACTION_ALPHA_HEIGHT_FIELD
                                                        : LAGOON_REFRACTION_ALPHA_OBJECT * base.a);
    return;
  }
  vec3 n = shading_normal(m, front);
  float metallic = m.pbr.x, roughness = m.pbr.y;
  if (has_texture(m, LAGOON_TEX_METAL_ROUGH)) {
    vec4 mr = material_texture(metal_rough_texture, m, LAGOON_TEX_METAL_ROUGH);
    metallic *= mr.b;
    roughness *= mr.g;
  }
  float occlusion = 1.0;
  if (has_texture(m, LAGOON_TEX_OCCLUSION))
    occlusion = 1.0 + m.pbr.w * (material_texture(occlusion_texture, m, LAGOON_TEX_OCCLUSION).r - 1.0);
  vec3 emissive = m.emissive.rgb;
  if (has_texture(m, LAGOON_TEX_EMISSIVE)) emissive *= material_texture(emissive_texture, m, LAGOON_TEX_EMISSIVE).rgb;

  // The viewer: in the reflection, the camera mirrored about the mean water level.
  vec3 eye = frame.camera_pos.xyz;
  if (mode == LAGOON_MESH_MIRRORED) eye.y = -eye.y;
  vec3 v = normalize(eye - v_world);
  float n_dot_v = dot(n, v);
  if (n_dot_v < 1e-4) {  // a normal-mapped normal facing away: bend it back to the horizon of v
    n = normalize(n + v * (1e-4 - n_dot_v));
    n_dot_v = dot(n, v);
  }
  vec2 ab = textureLod(dfg_table, pbr_dfg_uv(n_dot_v, roughness), 0.0).rg;
  vec3 radiance = pbr_brdf_cos(n, v, frame.sun_dir.xyz, base.rgb, metallic, roughness, ab) * frame.sun_irradiance.rgb;
  for (int i = 0; i < int(frame.lights.x); ++i) {
    vec3 to_light;
    // The irradiance on a surface facing the lamp; the BRDF applies the cosine.
    vec3 facing = point_light_irradiance(point_lights[i], v_world, normalize(point_lights[i].position_range.xyz - v_world), to_light);
    radiance += pbr_brdf_cos(n, v, to_light, base.rgb, metallic, roughness, ab) * facing;
  }
  vec3 prefiltered = environment_light(reflect(-v, n), roughness * float(LAGOON_ENV_SPECULAR_LAYERS - 1));
  vec3 irradiance = textureLod(environment, vec3(env_uv(n), float(LAGOON_ENV_LAYERS - 1)), 0.0).rgb;
  radiance += occlusion * pbr_environment(ab, base.rgb, metallic, prefiltered, irradiance);
  radiance += emissive;
  out_colour = vec4(mode == LAGOON_MESH_LIT ? display_encode(frame, radiance) : radiance, base.a);
}
