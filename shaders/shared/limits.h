// Limits that C++ and GLSL share: plain #defines so both languages (and compute/ocean, which has no GPU code)
// read the same number.
#ifndef LAGOON_SHARED_LIMITS_H
#define LAGOON_SHARED_LIMITS_H

// Cascades an ocean may have: FrameUniforms packs per-cascade values in vec4s, and the surface shaders bind
// one texture array element per cascade.
#define LAGOON_MAX_CASCADES 4
// Point lights in the scene format's "lights" block, and in the frame's light buffer.
#define LAGOON_MAX_LIGHTS 64

#endif
