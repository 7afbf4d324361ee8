// The spot cone of shared/light_spot.h (KHR_lights_punctual's reference form), as C++ compiles it; the
// shaders include the same header.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/light_spot.h"

namespace lagoon::gpu {
namespace {

TEST(LightSpot, FullInsideTheInnerConeNothingOutsideTheOuterSmoothBetween) {
  const float inner = std::cos(0.2f), outer = std::cos(0.4f);
  const vec2 cone = spot_cone(inner, outer);
  const vec3 axis(0, -1, 0);
  auto at = [&](float angle) {
    return spot_attenuation(axis, cone.x, cone.y, vec3(std::sin(angle), -std::cos(angle), 0));
  };
  EXPECT_FLOAT_EQ(at(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(at(0.19f), 1.0f);
  EXPECT_FLOAT_EQ(at(0.41f), 0.0f);
  EXPECT_FLOAT_EQ(at(2.0f), 0.0f);
  // Half way in cos: (1/2)² of the light.
  const float half = std::acos(0.5f * (inner + outer));
  EXPECT_NEAR(at(half), 0.25f, 1e-4f);
  for (float a = 0.2f; a < 0.4f; a += 0.01f) EXPECT_GE(at(a), at(a + 0.01f)) << a;
  // A point light: scale 0, offset 1, whatever the direction.
  EXPECT_FLOAT_EQ(spot_attenuation(axis, 0.0f, 1.0f, vec3(0, 1, 0)), 1.0f);
}

}  // namespace
}  // namespace lagoon::gpu
