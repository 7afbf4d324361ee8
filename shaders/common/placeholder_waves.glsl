// Four Gerstner waves for the foundation's placeholder surface (the FFT ocean replaces them).
#ifndef LAGOON_COMMON_PLACEHOLDER_WAVES_GLSL
#define LAGOON_COMMON_PLACEHOLDER_WAVES_GLSL

const int kWaveCount = 4;
const vec2 kWaveDir[kWaveCount] = vec2[](vec2(0.8, 0.6), vec2(0.96, -0.28), vec2(0.6, 0.8), vec2(-0.28, 0.96));
const float kWaveLength[kWaveCount] = float[](38.0, 21.0, 11.0, 5.5);  // metres
const float kWaveAmplitude[kWaveCount] = float[](0.55, 0.3, 0.14, 0.06);  // metres
const float kSteepness = 0.6;

// Displaced position and normal of the surface point that rests at xz at time t (deep-water dispersion).
void gerstner(vec2 xz, float t, out vec3 position, out vec3 normal) {
  vec3 p = vec3(xz.x, 0.0, xz.y);
  vec3 n = vec3(0.0, 1.0, 0.0);
  for (int i = 0; i < kWaveCount; ++i) {
    float k = 6.2831853 / kWaveLength[i];
    float omega = sqrt(9.81 * k);
    float a = kWaveAmplitude[i];
    float q = kSteepness / (k * a * float(kWaveCount));
    float phase = k * dot(kWaveDir[i], xz) - omega * t;
    float c = cos(phase), s = sin(phase);
    p.xz += q * a * kWaveDir[i] * c;
    p.y += a * s;
    n.xz -= kWaveDir[i] * k * a * c;
    n.y -= q * k * a * s;
  }
  position = p;
  normal = normalize(n);
}

#endif
