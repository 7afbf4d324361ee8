#version 450
#extension GL_GOOGLE_include_directive : require
#define LAGOON_UNDERWATER_TERMS 1
#include "common/underwater_view.glsl"

// The underwater view's image formation terms (common/underwater_view.glsl) for the dataset's ground truth
// (engine/render/underwater_terms.cpp): linear, in the frame's white units before exposure and tone mapping.
layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_clean;         // rgb, a = 1 where the ray meets something
layout(location = 1) out vec4 out_transmission;  // rgb
layout(location = 2) out vec4 out_backscatter;   // rgb

void main() {
  UnderwaterView view = underwater_view(ivec2(gl_FragCoord.xy), v_ndc);
  gl_FragDepth = view.depth;
  out_clean = vec4(view.clean, view.depth < 1.0 ? 1.0 : 0.0);
  out_transmission = vec4(view.transmission, 1.0);
  out_backscatter = vec4(view.backscatter, 1.0);
}
