// Objects above the water seen from below through Snell's window. The "snell window" objects pass draws them (mesh.vert,
// LAGOON_MESH_WINDOW) where a flat surface at y = 0 shows them to the camera: each vertex moves to the
// direction of the ray that leaves the camera, crosses the surface and, bent by Snell's law, reaches it.
// ocean_surface_below.frag then looks its own refracted ray up in that picture. Needs `frame`.
#include "common/snell_path.glsl"

float window_camera_depth() { return max(-frame.camera_pos.y, 0.01); }

// Where the refracted path from the camera to p (above the surface) crosses the flat surface.
vec3 window_crossing(vec3 p) {
  vec3 eye = frame.camera_pos.xyz;
  vec2 across = p.xz - eye.xz;
  float dist = length(across);
  float a = snell_crossing(dist, window_camera_depth(), max(p.y, 1e-3), frame.sun_dir.w);
  vec2 dir = dist > 0.0 ? across / dist : vec2(0.0);
  return vec3(eye.xz + a * dir, 0.0).xzy;
}

// Where to draw p so the camera sees it along the refracted path's first leg, as far away as the whole path.
vec3 window_apparent_position(vec3 p) {
  vec3 eye = frame.camera_pos.xyz, s = window_crossing(p);
  return eye + normalize(s - eye) * (length(s - eye) + length(p - s));
}

// The camera direction through which a flat surface would show what a ray leaving the water along t meets
// (t upward, in the air): undo the flat surface's refraction.
vec3 window_flat_direction(vec3 t) { return -refract(-t, vec3(0.0, 1.0, 0.0), 1.0 / frame.sun_dir.w); }
