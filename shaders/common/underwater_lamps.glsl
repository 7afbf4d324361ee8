// The scene's point lights at a point under the water (a diver's torch, an AUV's lamp, a lamp on a pier):
// their irradiance there, attenuated over the water path by the water's white-light transmittance
// (common/underwater.glsl). A lamp above the surface reaches the point refracted through the surface, taken
// as flat here (the waves' focusing of a lamp is left out). Needs, declared by the includer: `frame`,
// `point_lights` (PointLightGpu[]), common/light.glsl and common/underwater.glsl.
#ifndef LAGOON_COMMON_UNDERWATER_LAMPS_GLSL
#define LAGOON_COMMON_UNDERWATER_LAMPS_GLSL
#include "common/snell_path.glsl"

layout(constant_id = LAGOON_SURFACE_SPEC_LAMPS) const bool kUnderwaterLamps = true;

// A lamp of intensity I at height h above the surface, a point at depth z below it: the path crosses the
// surface r_a = a from the point (common/snell_path.glsl) and loses the Fresnel reflection there. The rays
// leaving the lamp within dθa·dφ spread over r·dr·dφ·cos θw across the path at the point, r = h tan θa +
// z tan θw, so E⊥ = I·T·sin θa / (r·cos θw·dr/dθa), dr/dθa = h/cos²θa + z·cos θa/(n·cos³θw) (n sin θw =
// sin θa). Straight down it tends to I·T/(h + z/n)²: the lamp seems nearer by the depth's factor 1/n.
vec3 lamp_above_irradiance(PointLightGpu light, vec3 p, vec3 n_surface, out float water_path) {
  vec3 lamp = light.position_range.xyz;
  float h = max(lamp.y, 1e-3), z = max(-p.y, 1e-3), ior = frame.sun_dir.w;
  vec2 across = lamp.xz - p.xz;
  float dist = length(across);
  float a = snell_crossing(dist, z, h, ior);
  vec3 s = vec3(p.x, 0.0, p.z);
  if (dist > 0.0) s.xz += a * across / dist;
  water_path = length(s - p);
  vec3 to_light = (s - p) / water_path;
  float sin_w = a / water_path, cos_w = z / water_path;
  float sin_a = min(ior * sin_w, 1.0), cos_a = sqrt(1.0 - sin_a * sin_a);
  float t = 1.0 - fresnel_dielectric(cos_a, ior);
  float focus;  // E⊥ / I
  if (sin_a < 1e-3) {
    float apparent = h + z / ior;
    focus = 1.0 / (apparent * apparent);
  } else {
    float r = h * sin_a / cos_a + z * sin_w / cos_w;
    float dr = h / (cos_a * cos_a) + z * cos_a / (ior * cos_w * cos_w * cos_w);
    focus = sin_a / (r * cos_w * dr);
  }
  float path = water_path + length(lamp - s);
  return light.colour.rgb * t * focus * light_range_window(path * path, light.position_range.w) *
         max(dot(n_surface, to_light), 0.0) * light_cone(light, normalize(s - lamp));
}

// White units, not relative to the sun: not scaled by frame.lut.w.
vec3 lamp_irradiance(vec3 p, vec3 n) {
  vec3 sum = vec3(0.0);
  if (!kUnderwaterLamps) return sum;
  for (int i = 0; i < int(frame.lights.x); ++i) {
    vec3 offset = point_lights[i].position_range.xyz - p;
    float range = point_lights[i].position_range.w;
    if (dot(offset, offset) >= range * range) continue;  // out of range either way (a bent path is longer)
    vec3 e;
    float water_path;
    if (point_lights[i].position_range.y >= 0.0) {
      e = lamp_above_irradiance(point_lights[i], p, n, water_path);
    } else {
      vec3 to_light;
      e = point_light_irradiance(point_lights[i], p, n, to_light);
      water_path = length(point_lights[i].position_range.xyz - p);
    }
    sum += e * underwater_transmittance(water_path);
  }
  return sum;
}

#endif
