// Exposure, the tone-mapping operator of seed 000's eq. 18 (constants from optics::tone_map_curve, so it is
// the same curve as the LUT previews) and display gamma.
#ifndef LAGOON_COMMON_TONEMAP_GLSL
#define LAGOON_COMMON_TONEMAP_GLSL

vec3 display_encode(FrameUniforms f, vec3 radiance) {
  vec3 x = max(radiance * f.post.x, vec3(0.0));
  if (f.post2.z > 0.5) {
    float L = dot(x, vec3(0.2126, 0.7152, 0.0722));
    if (L > 0.0) {
      float Ld = f.post.z * pow(L / f.post2.y, f.post.w);
      float white = f.post2.x;
      float Ldf = Ld >= white ? 1.0 : min(1.0, Ld * (1.0 + Ld / (white * white)) / (1.0 + Ld));
      x = x * (Ldf / L);
    }
  }
  return pow(clamp(x, 0.0, 1.0), vec3(1.0 / f.post.y));
}

#endif
