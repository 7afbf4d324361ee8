// The glTF 2.0 reference BRDF (glTF spec, Appendix B): GGX microfacets (Trowbridge–Reitz D, height-
// correlated Smith visibility V) with Fresnel–Schlick, over Lambert diffuse; metals take their Fresnel
// colour from the base colour. For the environment, the split-sum of Karis (2013) with the directional
// albedo integrated for this very lobe (render/dfg_table.h), and the multiple-scattering energy
// compensation of Fdez-Agüera (2019), so a white surface under a uniform white environment returns its
// light at every roughness (the white furnace, tests/unit/render/pbr_brdf_test.cpp). One formula for the mesh
// shader and the C++.
#ifndef LAGOON_SHARED_PBR_H
#define LAGOON_SHARED_PBR_H
#include "shared/interop.h"

#define LAGOON_PBR_PI 3.14159265358979f
// Layers of the pre-filtered environment (render/environment_map.h): 0..LAGOON_ENV_SPECULAR_LAYERS-1 hold
// the radiance pre-filtered for roughness layer / (LAGOON_ENV_SPECULAR_LAYERS - 1); the last one holds the
// irradiance over π (the radiance a white Lambertian surface of that normal returns).
#define LAGOON_ENV_SPECULAR_LAYERS 5
#define LAGOON_ENV_LAYERS 6
// The directional-albedo table (render/dfg_table.h): LAGOON_DFG_SIZE² texels over (n·v, roughness) from 0
// to 1 inclusive, texel i at i / (LAGOON_DFG_SIZE − 1); pbr_dfg_uv says where a sampler reads them.
#define LAGOON_DFG_SIZE 32

LAGOON_GPU_BEGIN
// Trowbridge–Reitz normal distribution, alpha = roughness².
LAGOON_FN float pbr_d_ggx(float n_dot_h, float alpha) {
  float a2 = alpha * alpha;
  float f = n_dot_h * n_dot_h * (a2 - 1.0f) + 1.0f;
  return a2 / (LAGOON_PBR_PI * max(f * f, 1e-12f));
}

// Height-correlated Smith visibility V = G / (4 n·l n·v), as the glTF spec writes it.
LAGOON_FN float pbr_v_smith(float n_dot_l, float n_dot_v, float alpha) {
  float a2 = alpha * alpha;
  float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0f - a2) + a2);
  float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0f - a2) + a2);
  float s = gv + gl;
  return s > 0.0f ? 0.5f / s : 0.0f;
}

LAGOON_FN vec3 pbr_fresnel_schlick(vec3 f0, float v_dot_h) {
  float m = clamp(1.0f - v_dot_h, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

LAGOON_FN vec2 pbr_dfg_uv(float n_dot_v, float roughness) {
  return (vec2(n_dot_v, roughness) * float(LAGOON_DFG_SIZE - 1) + vec2(0.5f)) / float(LAGOON_DFG_SIZE);
}

// Single and multiple scattering of the specular lobe seen from n·v, from the directional-albedo terms
// ab = (A, B) at n·v and this roughness (∫ f_spec cos = f0·A + B; render/dfg_table.h integrates them):
// x = F_ss·E_ss, y = F_ms·E_ms (Fdez-Agüera 2019), per channel.
struct PbrSpecularEnergy {
  vec3 single_scattered;
  vec3 multiple_scattered;
};
LAGOON_FN PbrSpecularEnergy pbr_specular_energy(vec2 ab, vec3 f0) {
  PbrSpecularEnergy e;
  e.single_scattered = f0 * ab.x + vec3(ab.y);
  float ess = ab.x + ab.y;
  float ems = 1.0f - ess;
  vec3 f_avg = f0 + (vec3(1.0f) - f0) / 21.0f;
  e.multiple_scattered = e.single_scattered * f_avg / max(vec3(1.0f) - ems * f_avg, vec3(1e-4f)) * ems;
  return e;
}

// f(l, v)·(n·l): the radiance leaving towards v per unit irradiance arriving from l (both unit vectors away
// from the surface). base: linear base colour; dielectrics have f0 = 0.04 (ior 1.5). ab: the directional
// albedo terms at n·v (pbr_specular_energy). The specular lobe is glTF's; the diffuse is energy-conserving:
// Lambert gets what the specular leaves at this view, and the light the single-scattering lobe loses comes
// back spread like diffuse light (Fdez-Agüera 2019), so a white surface returns all its light at any
// roughness. (glTF's sample implementation weights the diffuse by 1 − F(v·h) instead, which returns up to
// 1.33 of the light at grazing views: tests/unit/render/pbr_brdf_test.cpp.)
LAGOON_FN vec3 pbr_brdf_cos(vec3 n, vec3 v, vec3 l, vec3 base, float metallic, float roughness, vec2 ab) {
  float n_dot_l = dot(n, l);
  float n_dot_v = dot(n, v);
  if (n_dot_l <= 0.0f || n_dot_v <= 0.0f) return vec3(0.0f);
  vec3 h = normalize(l + v);
  float alpha = max(roughness * roughness, 1e-3f);
  vec3 f0 = mix(vec3(0.04f), base, metallic);
  vec3 f = pbr_fresnel_schlick(f0, dot(v, h));
  vec3 specular = f * (pbr_d_ggx(dot(n, h), alpha) * pbr_v_smith(n_dot_l, n_dot_v, alpha));
  PbrSpecularEnergy e = pbr_specular_energy(ab, f0);
  vec3 diffuse = mix(base, vec3(0.0f), metallic) * (vec3(1.0f) - e.single_scattered - e.multiple_scattered);
  return (specular + (diffuse + e.multiple_scattered) / LAGOON_PBR_PI) * n_dot_l;
}

// The environment's light leaving towards v: `prefiltered` is the radiance pre-filtered for this roughness
// around the mirror direction, `irradiance` the irradiance over π around n (render/environment_map.h), ab
// as for pbr_brdf_cos. Under a uniform environment of radiance 1 a white surface returns exactly 1.
LAGOON_FN vec3 pbr_environment(vec2 ab, vec3 base, float metallic, vec3 prefiltered, vec3 irradiance) {
  vec3 f0 = mix(vec3(0.04f), base, metallic);
  PbrSpecularEnergy e = pbr_specular_energy(ab, f0);
  vec3 diffuse = mix(base, vec3(0.0f), metallic) * (vec3(1.0f) - e.single_scattered - e.multiple_scattered);
  return e.single_scattered * prefiltered + (e.multiple_scattered + diffuse) * irradiance;
}

// The environment's equirectangular layout: u = azimuth from +x towards +z over 2π, v = 0 at the zenith
// and 1 at the nadir.
LAGOON_FN vec3 env_direction(vec2 uv) {
  float phi = 2.0f * LAGOON_PBR_PI * uv.x;
  float theta = LAGOON_PBR_PI * uv.y;
  return vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}
LAGOON_FN vec2 env_uv(vec3 dir) {
  return vec2(fract(atan(dir.z, dir.x) / (2.0f * LAGOON_PBR_PI) + 1.0f),
              acos(clamp(dir.y, -1.0f, 1.0f)) / LAGOON_PBR_PI);
}
LAGOON_GPU_END

#endif
