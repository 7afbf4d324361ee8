#version 450
// Writes texel (x, y) of layer z = vec4(x, y, z, x*y) scaled by push.scale into a storage image array,
// and copies a sampled input image (with a sampler) into the alpha of a buffer: exercises storage images,
// combined image samplers and the spec-constant workgroup size.
layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(rgba32f, binding = 0) writeonly uniform image2DArray dst;
layout(binding = 1) uniform sampler2D src;
layout(std430, binding = 2) writeonly buffer Out { vec4 sampled[]; };
layout(push_constant) uniform Push { vec4 scale; uvec4 size; } push;
void main() {
  uvec3 id = gl_GlobalInvocationID;
  if (id.x >= push.size.x || id.y >= push.size.y) return;
  imageStore(dst, ivec3(id), vec4(id.x, id.y, id.z, id.x * id.y) * push.scale);
  if (id.z == 0) {
    vec2 uv = (vec2(id.xy) + 0.5) / vec2(push.size.xy);
    sampled[id.y * push.size.x + id.x] = textureLod(src, uv, 0.0);
  }
}
