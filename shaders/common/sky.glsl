// Simple analytic sky of the placeholder scene: a zenith-to-horizon gradient, a warm glow around the sun
// and the sun disc. Radiance in linear units, before exposure. (Issue 5 replaces it with a sky consistent
// with the colour LUTs' irradiance.)
#ifndef LAGOON_COMMON_SKY_GLSL
#define LAGOON_COMMON_SKY_GLSL

vec3 sky_radiance(vec3 dir, vec3 sun_dir, float sun_intensity, bool with_disc) {
  float up = max(dir.y, 0.0);
  vec3 zenith = vec3(0.16, 0.34, 0.72);
  vec3 horizon = vec3(0.62, 0.74, 0.86);
  vec3 sky = mix(horizon, zenith, pow(up, 0.45));
  float cos_sun = max(dot(dir, sun_dir), 0.0);
  sky += vec3(1.0, 0.78, 0.5) * 0.35 * pow(cos_sun, 8.0);
  if (with_disc) sky += vec3(1.0, 0.92, 0.8) * 40.0 * smoothstep(0.9995, 0.9998, cos_sun);
  if (dir.y < 0.0) sky = mix(horizon, vec3(0.35, 0.4, 0.45), clamp(-dir.y * 4.0, 0.0, 1.0));
  return sky * sun_intensity;
}

// Exposure, a filmic curve (Narkowicz's ACES fit) and display gamma.
vec3 tone_map(vec3 radiance, float exposure, float gamma) {
  vec3 x = radiance * exposure;
  vec3 mapped = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  return pow(mapped, vec3(1.0 / gamma));
}

#endif
