#version 460
#extension GL_EXT_ray_query : require
// Reflection test (error case): an acceleration structure descriptor, which reflection does not support.
layout(local_size_x = 1) in;

layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;
layout(set = 0, binding = 1) writeonly buffer Out {
  uint hit;
} result;

void main() {
  rayQueryEXT q;
  rayQueryInitializeEXT(q, scene, gl_RayFlagsOpaqueEXT, 0xff, vec3(0.0), 0.0, vec3(0.0, 0.0, 1.0), 100.0);
  while (rayQueryProceedEXT(q)) {
  }
  result.hit = rayQueryGetIntersectionTypeEXT(q, true) == gl_RayQueryCommittedIntersectionNoneEXT ? 0u : 1u;
}
