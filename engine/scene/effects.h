// The image's switchable effects (render.effects), in one table: the scene format reads and documents each
// from it (world_blocks.cpp), `lagoon bench effects` measures each alone and all together from it, and the
// renderer reads the flags of RenderEffects (scene.h). An effect added to RenderEffects and here reaches
// the scene format, its generated docs, the demo's panel and the bench.
#pragma once
#include <iterator>
#include <string_view>

#include "scene/scene.h"

namespace lagoon::scene {

struct EffectKind {
  const char* name;           // the field under render.effects
  bool RenderEffects::*flag;  // its switch
  const char* summary;        // one line, as `lagoon bench effects` lists its configurations
  const char* doc;            // the scene format's documentation of the field
  const char* measured_with;  // nullptr, or the effect the bench switches it on with (it needs that one)
};

inline constexpr EffectKind kEffects[] = {
    {"reflection", &RenderEffects::reflection, "planar reflection of what is above the water",
     "Planar reflection of the objects above the water; false = the water reflects the sky alone.", nullptr},
    {"refraction", &RenderEffects::refraction, "the floor and submerged objects seen through the surface",
     "The floor and submerged objects seen through the surface, coloured by the water LUTs; false = the "
     "water's own colour only.",
     nullptr},
    {"foam", &RenderEffects::foam, "breaking waves' foam and shore foam",
     "Whitecaps from ocean.foam; false hides them, and the shore foam with them (the vehicles' foam trails "
     "are the wakes').",
     nullptr},
    {"shore_foam", &RenderEffects::shore_foam, "foam where the floor or an object meets the surface",
     "Foam where the floor or an object meets the surface (a shore, a hull, a buoy): waves break where the "
     "water is shallower than 1.25 times their significant height (breaker index 0.8, docs/physics.md, Shore "
     "foam), so the band widens with the waves and on gentle slopes. Needs refraction (the depth under the "
     "surface comes from the refraction pass) and foam.",
     "foam"},
    {"caustics", &RenderEffects::caustics, "the sun focused by the waves on the floor",
     "The sun focused by the displaced surface onto the floor and submerged objects, from above and below "
     "(docs/rendering.md, Caustics); false = the light under a flat surface.",
     nullptr},
    {"caustics_blur", &RenderEffects::caustics_blur, "the caustic pattern blurred with depth",
     "The caustic pattern blurred with depth by what its 12.5 cm cells leave out: the waves shorter than a "
     "cell (their mean square slope, the glint's) and the solar disc spread the refracted sun, by 1.6° "
     "under a 7 m/s sea and a 60° sun: a blur of 0.2 m at 6 m and 0.5 m at 15 m (docs/rendering.md, "
     "Caustics); false = "
     "the resolved waves' sharp pattern at every depth.",
     "caustics"},
    {"particles", &RenderEffects::particles, "suspended particles seen under the water",
     "Suspended particles in the water, seen from under the water (underwater.particles).", nullptr},
    {"shafts", &RenderEffects::shafts, "light shafts in the water",
     "Light shafts: the sun's beams, focused by the waves, seen in the water from under it (a volumetric "
     "estimate, docs/rendering.md). Off by default: on lavapipe they cost about 35 ms of a 1280x720 "
     "reef-dive frame (docs/rendering.md).",
     nullptr},
    {"underwater", &RenderEffects::underwater,
     "the water volume: attenuation and in-scattering along view rays",
     "Under the water, the water's effect on light along each view ray (attenuation, its own light, blur); "
     "false = what lies in the water as if the water were clear (it is still lit as under water).",
     nullptr},
};

// Every field of RenderEffects is in kEffects: a bool each, so the sizes agree only when none is missing.
static_assert(sizeof(RenderEffects) == std::size(kEffects) * sizeof(bool),
              "a field of RenderEffects is missing from kEffects (scene/effects.h)");

// Every effect off.
inline RenderEffects no_effects() {
  RenderEffects e;
  for (const EffectKind& k : kEffects) e.*k.flag = false;
  return e;
}

}  // namespace lagoon::scene
