// Limits that C++ and GLSL share: plain #defines so both languages (and compute/ocean, which has no GPU code)
// read the same number.
#ifndef LAGOON_SHARED_LIMITS_H
#define LAGOON_SHARED_LIMITS_H

// Cascades an ocean may have: FrameUniforms packs per-cascade values in vec4s, and the surface shaders bind
// one texture array element per cascade.
#define LAGOON_MAX_CASCADES 4
// Specialisation constant of the shaders that sum the cascades (common/cascade_uv.glsl): how many there are.
// A uniform count did not do: lavapipe runs the code of a cascade that is not there, masked off, at full
// cost (the surface pass was 10-20 % slower for the 4th slot of a 3-cascade sea).
#define LAGOON_SPEC_CASCADE_COUNT 3
// Point lights in the scene format's "lights" block, and in the frame's light buffer.
#define LAGOON_MAX_LIGHTS 64

#endif
