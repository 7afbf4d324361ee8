// Binding slots of the ocean surface shaders (render/ocean_surface.vert, ocean_surface.frag,
// ocean_surface_aov.frag, and under the water ocean_surface_below.frag, underwater_medium.frag) and
// engine/render/passes/surface_pass.cpp, underwater_pass.cpp.
#ifndef LAGOON_SHARED_SURFACE_H
#define LAGOON_SHARED_SURFACE_H
#include "shared/limits.h"

#define LAGOON_SURFACE_BIND_FRAME 0              // FrameUniforms
#define LAGOON_SURFACE_BIND_DISPLACEMENT 1       // sampler2DArray[LAGOON_MAX_CASCADES]: (λDx, h, λDz, foam)
#define LAGOON_SURFACE_BIND_NORMAL_JACOBIAN 2    // sampler2DArray[LAGOON_MAX_CASCADES]: (n, J)
#define LAGOON_SURFACE_BIND_REFRACTION_ALBEDO 3  // the refraction pass's albedo, a = coverage
#define LAGOON_SURFACE_BIND_REFRACTION_DEPTH 4   // ... and its depth
#define LAGOON_SURFACE_BIND_LUT_T0 5             // colour LUT T0 (RGB, a)
#define LAGOON_SURFACE_BIND_LUT_T1 6             // colour LUT T1
#define LAGOON_SURFACE_BIND_REFLECTION 7         // the reflection pass's colour, a = coverage
#define LAGOON_SURFACE_BIND_LIGHTS 8             // PointLightGpu[]
#define LAGOON_SURFACE_BIND_JACOBIAN_TERMS 9     // sampler2DArray[LAGOON_MAX_CASCADES]
#define LAGOON_SURFACE_BIND_UW_TARGET 10         // underwater table: white target (RGB, blur) over (d, z)
#define LAGOON_SURFACE_BIND_UW_DOWN 11           // ... the water's light looking down
#define LAGOON_SURFACE_BIND_UW_UP 12             // ... looking up
#define LAGOON_SURFACE_BIND_CAUSTICS 13          // caustic map (shared/caustics.h), sampler2DArray
// Specialisation constant of the shaders that include common/light_shafts.glsl: shafts compiled in (1) or
// not.
#define LAGOON_UNDERWATER_SPEC_SHAFTS 0
// Specialisation constant of the shaders that include common/underwater_lamps.glsl: the lamps' light under
// the water compiled in (1) or not (no lights in the scene). A uniform branch does not do: on lavapipe the
// mere presence of the code made the surface pass 45 % slower.
#define LAGOON_SURFACE_SPEC_LAMPS 1
// ... and of those that include common/caustics.glsl: caustics compiled in (1) or not (no map this frame),
// for the same reason.
#define LAGOON_SURFACE_SPEC_CAUSTICS 2
#define LAGOON_SURFACE_BIND_BELOW_COLOR 14  // waterline.frag: the frame drawn from below, colour
#define LAGOON_SURFACE_BIND_BELOW_DEPTH 15  // ... and depth
#define LAGOON_SURFACE_BIND_WINDOW 16  // ocean_surface_below.frag: objects above, seen through Snell's window
// The wakes' dynamic layer (h, dh/dx, dh/dz, foam), sampler2D with repeat addressing
// (common/wake_fields.glsl).
#define LAGOON_SURFACE_BIND_WAKES 17
// Specialisation constant of the shaders that include common/wake_fields.glsl: the wakes compiled in (1) or
// not (no vehicle makes one). Ids 0-2 above, 3 is LAGOON_SPEC_CASCADE_COUNT (shared/limits.h).
#define LAGOON_SURFACE_SPEC_WAKES 4
// Specialisation constant of render/ocean_surface_classic.frag: the seed 001 shading it draws,
// 1 = blinn-phong (per pixel), 2 = gouraud (lit per vertex), 3 = flat (one normal per triangle).
#define LAGOON_SURFACE_SPEC_SHADING 6
// Specialisation constant of render/ocean_surface.frag: the search for an object the refracted ray meets
// before what the fixed point settles on (common/refracted_hit.glsl) compiled in (1: objects are under the
// water this frame) or not. On lavapipe its mere presence, never entered, made the open ocean's surface pass
// 15 % slower.
#define LAGOON_SURFACE_SPEC_FIRST_HIT 8

#endif
