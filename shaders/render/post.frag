#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "common/tonemap.glsl"

layout(std140, binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D hdr;
layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_color;

void main() {
  vec2 uv = vec2(v_ndc.x, -v_ndc.y) * 0.5 + 0.5;  // the viewport flips y: NDC +y is the image's top row
  out_color = vec4(display_encode(frame, textureLod(hdr, uv, 0.0).rgb), 1.0);
}
