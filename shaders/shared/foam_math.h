// The foam rule (compute/ocean/whitecaps.h), written once for the GPU (float: the ocean step, the surface
// shader) and the CPU (double: ocean/cpu_step.cpp, ocean/whitecaps.cpp, the validation's drawn foam). No
// include guard: the includer defines foam_real and makes clamp and max visible (GLSL has them).

#include "shared/foam.h"

// The foam a Jacobian J makes: none above the onset, rising to 1 over `width` below it.
LAGOON_FN foam_real foam_made(foam_real onset, foam_real width, foam_real jacobian) {
  return clamp((onset - jacobian) / width, foam_real(0), foam_real(1));
}

// A texel's foam after a step: what it held, faded by `fade` = exp(-decay_per_s · dt) (shared/foam.h), or
// what J makes now.
LAGOON_FN foam_real foam_after_step(foam_real previous, foam_real fade, foam_real made) {
  const foam_real c = foam_real(LAGOON_FOAM_FADE_OFFSET);
  return max((previous + c) * fade - c, made);
}
