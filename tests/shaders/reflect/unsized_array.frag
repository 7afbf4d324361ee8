#version 450
#extension GL_EXT_nonuniform_qualifier : require
// Reflection test (error case): a runtime-sized descriptor array, which reflection rejects.
layout(set = 0, binding = 0) uniform sampler2D textures[];

layout(location = 0) flat in int index;
layout(location = 0) out vec4 color;

void main() {
  color = texture(textures[nonuniformEXT(index)], vec2(0.5));
}
