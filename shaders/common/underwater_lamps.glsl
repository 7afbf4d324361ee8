// The scene's point lights under the water (a diver's torch, an AUV's lamp): their irradiance at a point
// under the water, attenuated over the distance by the water's white-light transmittance
// (common/underwater.glsl). Lights above the surface would reach the point refracted through the waves:
// left out. Needs, declared by the includer: `point_lights` (PointLightGpu[]), common/light.glsl and
// common/underwater.glsl.
#ifndef LAGOON_COMMON_UNDERWATER_LAMPS_GLSL
#define LAGOON_COMMON_UNDERWATER_LAMPS_GLSL

// White units, not relative to the sun: not scaled by frame.lut.w.
vec3 lamp_irradiance(vec3 p, vec3 n) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < int(frame.lights.x); ++i) {
    if (point_lights[i].position_range.y >= 0.0) continue;
    vec3 to_light;
    vec3 e = point_light_irradiance(point_lights[i], p, n, to_light);
    sum += e * underwater_transmittance(length(point_lights[i].position_range.xyz - p));
  }
  return sum;
}

#endif
