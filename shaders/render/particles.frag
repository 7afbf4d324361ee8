#version 450
// A particle: a round spot, blended over the water behind it.
layout(location = 0) in vec3 v_colour;
layout(location = 1) in float v_alpha;
layout(location = 2) in vec2 v_corner;
layout(location = 0) out vec4 out_colour;

void main() {
  if (dot(v_corner, v_corner) > 1.0) discard;
  out_colour = vec4(v_colour, v_alpha);
}
