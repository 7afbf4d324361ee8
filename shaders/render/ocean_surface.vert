#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"

// The water surface's vertices (common/surface_vertex.glsl).
#include "common/surface_vertex.glsl"

void main() {
  ClipmapVertex v = clipmap_indexed_vertex(gl_VertexIndex, frame.camera_pos.xz, frame.grid, frame.clipmap);
  v_rest = v.rest;
  v_floor = floor_under(v.rest);
  v_world = clipmap_displaced(v);
  gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
