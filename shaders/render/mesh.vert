#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/mesh.h"

// Vertex pulling: indices and vertices from storage buffers, no vertex-input state.
layout(std140, binding = LAGOON_MESH_BIND_FRAME) uniform Frame { FrameUniforms frame; };
struct Vertex { float px, py, pz, nx, ny, nz, u, v, u1, v1, tx, ty, tz, tw; };
layout(std430, binding = LAGOON_MESH_BIND_VERTICES) readonly buffer Vertices { Vertex vertices[]; };
layout(std430, binding = LAGOON_MESH_BIND_INDICES) readonly buffer Indices { uint indices[]; };
layout(std430, binding = LAGOON_MESH_BIND_MATERIALS) readonly buffer Materials { MaterialGpu materials[]; };
layout(push_constant) uniform Push { MeshPush p; };
layout(constant_id = LAGOON_MESH_SPEC_MODE) const uint kMode = LAGOON_MESH_LIT;
#include "common/snell_window.glsl"

layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec2 v_uv;
layout(location = 3) out vec2 v_uv1;
layout(location = 4) out vec4 v_tangent;
// The base colour texture's coordinates, transformed here: the one texture every pass samples (the
// refraction pass samples only it), read with implicit gradients of an interpolated value, lavapipe's
// fastest path.
layout(location = 5) out vec2 v_base_uv;

void main() {
  Vertex vtx = vertices[indices[gl_VertexIndex]];
  vec4 world = p.model * vec4(vtx.px, vtx.py, vtx.pz, 1.0);
  v_world = world.xyz;
  v_normal = normalize(mat3(p.model) * vec3(vtx.nx, vtx.ny, vtx.nz));
  v_tangent = vec4(mat3(p.model) * vec3(vtx.tx, vtx.ty, vtx.tz), vtx.tw);
  v_uv = p.texture_scale > 0.0 ? world.xz / p.texture_scale : vec2(vtx.u, vtx.v);
  v_uv1 = vec2(vtx.u1, vtx.v1);
  MaterialGpu m = materials[p.material];
  vec3 base_uv = vec3(((m.flags.z >> LAGOON_TEX_BASE) & 1u) != 0u ? v_uv1 : v_uv, 1.0);
  v_base_uv = vec2(dot(m.uv_rows[2 * LAGOON_TEX_BASE].xyz, base_uv), dot(m.uv_rows[2 * LAGOON_TEX_BASE + 1].xyz, base_uv));
  if (kMode == LAGOON_MESH_MIRRORED) world.y = -world.y;  // reflection: the scene mirrored about the mean water level
  if (kMode == LAGOON_MESH_WINDOW) world.xyz = window_apparent_position(world.xyz);
  gl_Position = frame.view_proj * world;
}
