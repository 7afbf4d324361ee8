// The foam's constants, for C++ and GLSL (shared/foam_math.h has its formulas).
#ifndef LAGOON_SHARED_FOAM_H
#define LAGOON_SHARED_FOAM_H

// Foam fades as (foam + c) e^{-decay t} - c: exponentially at first, then to exactly 0, within
// ln(1 + 1/c)/decay seconds of its making (4.2 s at the default decay of 0.3/s). So a still frame's warm-up
// that long holds all the foam a live run still shows (render/passes/ocean_step_pass.h), and the fade
// composes exactly: fading by a and then by b is fading by a + b, whatever the steps.
#define LAGOON_FOAM_FADE_OFFSET 0.4

#endif
