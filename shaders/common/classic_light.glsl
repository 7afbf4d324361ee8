// The Blinn-Phong model of seed 001 §2.1 for render.shading's classic modes: ambient, diffuse and specular
// parts, the specular from the half vector between the directions to the light and to the viewer. Lights: the
// sun (its irradiance) and the scene's point lights; the ambient light is the sky's. The result is in the
// renderer's white units, and display_encode applies exposure, tone map and the display gamma as for the
// physical shading. Needs `frame` (FrameUniforms) and `point_lights` (PointLightGpu[]) declared, and
// common/light.glsl included.
#ifndef LAGOON_COMMON_CLASSIC_LIGHT_GLSL
#define LAGOON_COMMON_CLASSIC_LIGHT_GLSL

vec3 blinn_phong_light(vec3 irradiance, vec3 n, vec3 to_light, vec3 to_viewer) {
  vec3 h = normalize(to_light + to_viewer);
  float specular = pow(max(dot(n, h), 0.0), frame.classic_diffuse.w);
  return irradiance * (frame.classic_diffuse.rgb + frame.classic_specular.rgb * specular);
}

// `p` the lit point, `n` its unit normal, `v` the unit direction to the viewer.
vec3 classic_light(vec3 p, vec3 n, vec3 v) {
  vec3 colour = frame.classic_ambient.rgb * frame.sky_radiance.rgb;
  vec3 l = frame.sun_dir.xyz;
  colour += blinn_phong_light(frame.sun_irradiance.rgb * max(dot(n, l), 0.0), n, l, v);
  for (int i = 0; i < int(frame.lights.x); ++i) {
    vec3 to_light;
    vec3 irradiance = point_light_irradiance(point_lights[i], p, n, to_light);
    colour += blinn_phong_light(irradiance, n, to_light, v);
  }
  return colour;
}

#endif
