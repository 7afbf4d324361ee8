#version 450
#extension GL_GOOGLE_include_directive : require
#include "common/underwater_view.glsl"
#include "common/tonemap.glsl"

// Under the water, everything but the surface (common/underwater_view.glsl). The surface is drawn over this
// from below (ocean_surface_below.frag). Writes the geometry's depth, so the surface depth-tests against it.
layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_colour;  // tone-mapped for display

void main() {
  UnderwaterView view = underwater_view(ivec2(gl_FragCoord.xy), v_ndc);
  gl_FragDepth = view.depth;
  out_colour = vec4(display_encode(frame, view.radiance), 1.0);
}
