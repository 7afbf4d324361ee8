// The frame's sky and sun (render/sky_light.h): the clear sky of shared/sky_model.h, whose cosine-weighted
// integral over the upper hemisphere is the optics model's E_sky.
#ifndef LAGOON_COMMON_LIGHT_GLSL
#define LAGOON_COMMON_LIGHT_GLSL

#include "shared/light_spot.h"

vec3 sky_radiance(FrameUniforms f, vec3 dir, bool with_sun) {
  // Below the horizon: the horizon's colour (distant sea haze); sky_model_rgb clamps the elevation.
  vec3 sky = sky_model_rgb(f.sky, dir, f.sun_dir.xyz);
  if (with_sun && dir.y > 0.0 && dot(dir, f.sun_dir.xyz) > f.sky_radiance.w) sky += f.sun_disc.rgb;
  return sky;
}

// Unpolarised Fresnel reflectance at a dielectric boundary, light coming from the side of index 1.
float fresnel_dielectric(float cos_i, float ior) {
  cos_i = clamp(cos_i, 0.0, 1.0);
  float sin_t2 = (1.0 - cos_i * cos_i) / (ior * ior);
  if (sin_t2 >= 1.0) return 1.0;
  float cos_t = sqrt(1.0 - sin_t2);
  float rs = (cos_i - ior * cos_t) / (cos_i + ior * cos_t);
  float rp = (ior * cos_i - cos_t) / (ior * cos_i + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

// Irradiance (white units) from point light `light` at point p with normal n: inverse square, cut at range
// with a smooth window so lights end without a visible edge.
// The smooth cut at a light's range: (1 - (r/range)^4)², from the squared distance.
float light_range_window(float dist2, float range) {
  float window = clamp(1.0 - dist2 * dist2 / (range * range * range * range), 0.0, 1.0);
  return window * window;
}

// A spot light's cone (shared/light_spot.h); 1 for a point light.
float light_cone(PointLightGpu light, vec3 from_light) {
  return spot_attenuation(light.spot.xyz, light.colour.w, light.spot.w, from_light);
}

vec3 point_light_irradiance(PointLightGpu light, vec3 p, vec3 n, out vec3 to_light) {
  vec3 d = light.position_range.xyz - p;
  float dist2 = max(dot(d, d), 1e-4);
  to_light = d * inversesqrt(dist2);
  return light.colour.rgb * (light_range_window(dist2, light.position_range.w) / dist2) *
         max(dot(n, to_light), 0.0) * light_cone(light, -to_light);
}

#endif
