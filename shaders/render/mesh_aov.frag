#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/mesh.h"
#include "shared/ground_truth.h"

// Ground truth of the scene's meshes per pixel (engine/dataset/ground_truth.h), in the targets of the water
// surface's (ocean_surface_aov.frag): the mesh's world-space normal, facing the side that is seen (normal maps
// are not applied), and the world point with what the mesh is (shared/ground_truth.h). Every mesh is drawn,
// above and below the water; alpha MASK cut-outs and single-sided back faces are left out as in mesh.frag.
layout(binding = LAGOON_MESH_BIND_ALBEDO) uniform sampler2D base_texture;
layout(std430, binding = LAGOON_MESH_BIND_MATERIALS) readonly buffer Materials { MaterialGpu materials[]; };
layout(push_constant) uniform Push { MeshPush p; };

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 3) in vec2 v_uv1;
layout(location = 4) in vec4 v_tangent;
layout(location = 5) in vec2 v_base_uv;
layout(location = 0) out vec4 out_normal;  // xyz unit normal (world), w = 0
layout(location = 1) out vec4 out_world;   // xyz world point (m), w = p.ground_truth

void main() {
  MaterialGpu m = materials[p.material];
  if (m.flags.w == 0u && !gl_FrontFacing) discard;  // single-sided: back faces are culled
  if (m.flags.x == LAGOON_ALPHA_MASK) {
    float alpha = m.base_colour.a;
    if (((m.flags.y >> LAGOON_TEX_BASE) & 1u) != 0u) alpha *= texture(base_texture, v_base_uv).a;
    if (alpha < m.emissive.w) discard;
  }
  vec3 n = normalize(v_normal);
  out_normal = vec4(gl_FrontFacing ? n : -n, 0.0);
  out_world = vec4(v_world, float(p.ground_truth));
}
