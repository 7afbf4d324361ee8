#version 450
// Reflection test: every image-like descriptor type a fragment shader uses, plus descriptor arrays.
layout(set = 0, binding = 0) uniform sampler2D albedo;                           // combined image sampler
layout(set = 0, binding = 1) uniform texture2D height_map;                       // sampled image
layout(set = 0, binding = 2) uniform sampler linear_sampler;                     // separate sampler
layout(set = 0, binding = 3, rgba32f) uniform readonly image2D accumulation;     // storage image
layout(set = 0, binding = 4) uniform samplerBuffer offsets;                      // uniform texel buffer
layout(set = 0, binding = 5) uniform textureBuffer weights;                      // uniform texel buffer
layout(set = 0, binding = 6, r32f) uniform readonly imageBuffer storage_texels;  // storage texel buffer
layout(set = 1, binding = 0) uniform sampler2D layers[3];                        // array of 3
layout(set = 2, binding = 1) uniform texture2D cascades[4];                      // array of 4

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
  vec4 c = texture(albedo, uv) + texture(sampler2D(height_map, linear_sampler), uv);
  c += imageLoad(accumulation, ivec2(uv * 64.0));
  c += texelFetch(offsets, 0) + texelFetch(weights, 1) + imageLoad(storage_texels, 2);
  for (int i = 0; i < 3; ++i) c += texture(layers[i], uv);
  c += texture(sampler2D(cascades[2], linear_sampler), uv);
  color = c;
}
