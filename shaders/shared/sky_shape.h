// The analytic sky's angular shape, shared by the sky and water shaders (common/light.glsl) and the C++ that
// normalises it (render/sky_light.cpp: sky_shape_integral), so the sky's irradiance is the optics model's
// E_sky in both languages. Unnormalised: brighter towards the horizon and around the sun.
#ifndef LAGOON_SHARED_SKY_SHAPE_H
#define LAGOON_SHARED_SKY_SHAPE_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
LAGOON_FN float sky_shape(vec3 dir, vec3 sun) {
  float up = max(dir.y, 0.0f);
  float horizon = 1.0f - up;
  return 0.55f + 1.2f * horizon * horizon * horizon * horizon + 0.6f * pow(max(dot(dir, sun), 0.0f), 12.0f);
}
LAGOON_GPU_END

#endif
