// The refracted path between a point under a flat water surface (y = 0) and a point above it, shared by
// common/snell_window.glsl (objects above seen from below) and common/underwater_lamps.glsl (lamps above
// lighting what is below).
#ifndef LAGOON_COMMON_SNELL_PATH_GLSL
#define LAGOON_COMMON_SNELL_PATH_GLSL

// The horizontal distance, from the point below (depth `below`), at which the path crosses the surface when
// the point above (height `above`) is `across` metres away horizontally. It solves
// n·a/√(a² + below²) = (across − a)/√((across − a)² + above²), i.e. n sin θw = sin θa, whose left side minus
// right side rises with a from < 0 at a = 0 to > 0 at a = across: bisection.
float snell_crossing(float across, float below, float above, float n) {
  float lo = 0.0, hi = across;
  for (int i = 0; i < 24; ++i) {
    float a = 0.5 * (lo + hi), rest = across - a;
    if (n * a * inversesqrt(a * a + below * below) > rest * inversesqrt(rest * rest + above * above)) hi = a;
    else lo = a;
  }
  return 0.5 * (lo + hi);
}

#endif
