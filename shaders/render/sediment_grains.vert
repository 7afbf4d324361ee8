#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"
#include "shared/sediment.h"

// The sediment clouds' grains (common/sediment_grain.glsl): LAGOON_SEDIMENT_MAX_GRAINS candidates per cloud of
// the frame's buffer, each drawn as common/particle_quad.glsl's quad with the sediment's colour as albedo.
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_UW_TARGET) uniform sampler2D uw_target;
layout(binding = LAGOON_SURFACE_BIND_UW_DOWN) uniform sampler2D uw_down;
layout(binding = LAGOON_SURFACE_BIND_UW_UP) uniform sampler2D uw_up;
layout(std430, binding = LAGOON_SURFACE_BIND_SEDIMENT) readonly buffer Sediment {
  SedimentHeader sediment;
  SedimentPuffGpu sediment_puffs[];
};
layout(push_constant) uniform Push { vec4 look; };  // x = the grains' diameter m

#include "common/simplex4.glsl"
#include "common/sediment_grain.glsl"
#include "common/tonemap.glsl"
#include "common/underwater.glsl"
#include "common/particle_quad.glsl"

void main() {
  int grain = gl_VertexIndex / 6;
  int cloud = grain / LAGOON_SEDIMENT_MAX_GRAINS;
  if (cloud >= int(sediment.colour.w)) { particle_hide(); return; }
  vec4 at = sediment_grain(sediment_puffs[cloud], grain % LAGOON_SEDIMENT_MAX_GRAINS);
  if (at.w == 0.0 || at.y > -0.02) { particle_hide(); return; }
  particle_emit(at.xyz, look.x, sediment.colour.rgb);
}
