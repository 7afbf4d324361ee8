// The ocean surface's mesh: nested square rings (a geometry clipmap) on world-aligned lattices, shared by
// the vertex shader (shaders/render/ocean_surface.vert) and the C++ tests of its crack- and pop-freedom.
//
// Level i has spacing s_i = grid.x * 2^i and covers 2m x 2m cells (m = grid.y) around a centre snapped to
// multiples of 2 s_i, so its vertices rest on a lattice fixed in the world (they never swim) and every other
// vertex is also a vertex of level i + 1. Level i > 0 skips the cells the finer level covers; the finer
// square always lies on the coarser lattice, so the rings tile the plane without gaps or overlap.
//
// Near its outer edge a level morphs into the next coarser one (clipmap.z = width of that zone in cells,
// ending a cell inside the edge):
// odd vertices move to the middle of the coarse edge they sit on, so at the edge the fine mesh is the coarse
// mesh (no cracks) and cells that change level as the camera moves look the same in both (no popping).
// clipmap.y fades the finest level into the next as the camera rises (render/surface_grid.h).
#ifndef LAGOON_SHARED_CLIPMAP_H
#define LAGOON_SHARED_CLIPMAP_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
struct ClipmapVertex {
  vec2 rest;      // resting position on the level's lattice (m, world xz)
  vec2 coarse_a;  // ends of the coarser level's edge through `rest`; both equal `rest` for even vertices
  vec2 coarse_b;
  float spacing;  // s_i (m)
  float morph;    // 0 = this level's mesh, 1 = the next coarser level's mesh
};

LAGOON_FN float clipmap_spacing(int level, vec4 grid) {
  return grid.x * exp2(float(level));
}

// Centre of level `level`: the camera snapped to the coarser lattice (multiples of 2 s_i).
LAGOON_FN vec2 clipmap_centre(int level, vec2 camera, vec4 grid) {
  float step = 2.0f * clipmap_spacing(level, grid);
  return floor(camera / step + 0.5f) * step;
}

// Cells per level (2m)^2; quads are drawn as two triangles sharing the (0,0)-(1,1) diagonal.
LAGOON_FN int clipmap_cells_per_side(vec4 grid) {
  return 2 * int(grid.y);
}

// Whether cell `cell` (0 .. 2m-1 per axis) of level `level` is drawn by that level.
LAGOON_FN bool clipmap_cell_visible(int level, ivec2 cell, vec2 camera, vec4 grid) {
  if (level == 0) return true;
  int m = int(grid.y);
  // The finer square in this level's cell indices: its centre is on this level's lattice.
  vec2 offset = (clipmap_centre(level - 1, camera, grid) - clipmap_centre(level, camera, grid)) /
                clipmap_spacing(level, grid);
  ivec2 lo = ivec2(floor(offset + 0.5f)) + ivec2(m - m / 2);
  ivec2 hi = lo + ivec2(m);
  return cell.x < lo.x || cell.y < lo.y || cell.x >= hi.x || cell.y >= hi.y;
}

// Vertex `vertex` (0 .. 2m per axis) of level `level`.
LAGOON_FN ClipmapVertex clipmap_vertex(int level, ivec2 vertex, vec2 camera, vec4 grid, vec4 clipmap) {
  ClipmapVertex v;
  int m = int(grid.y);
  v.spacing = clipmap_spacing(level, grid);
  v.rest = clipmap_centre(level, camera, grid) + vec2(vertex - ivec2(m)) * v.spacing;
  // The centre is on the even lattice and m is even, so parity of the index is parity in the world.
  vec2 odd = vec2(vertex.x & 1, vertex.y & 1) * v.spacing;
  v.coarse_a = v.rest - odd;
  v.coarse_b = v.rest + odd;
  // Chebyshev distance in cells; the level's edge is at least m - 1 cells from the camera, the row inside it
  // at least m - 2. Both are wholly morphed, so the edge's stitched triangles (render/surface_grid.h:
  // clipmap_patch) lie on the coarser mesh, as the plain cells there do: the two triangulations are the
  // same surface and a cell that changes from one to the other as the level's centre snaps does not pop.
  vec2 d = abs(v.rest - camera) / v.spacing;
  float width = clipmap.z;
  v.morph = clamp((max(d.x, d.y) - (float(m - 2) - width)) / width, 0.0f, 1.0f);
  if (level == 0) v.morph = max(v.morph, clipmap.y);
  return v;
}

// The CPU culls the rings against the view in blocks of kClipmapBlock^2 cells (render/surface_grid.h);
// 2m must be a multiple of the block size.
const int kClipmapBlock = 8;

// Vertices per level of the indexed draw: the (2m+1)^2 lattice points of its square.
LAGOON_FN int clipmap_vertices_per_level(vec4 grid) {
  int side = clipmap_cells_per_side(grid) + 1;
  return side * side;
}

// The vertex an index of the indexed draw names: level * (2m+1)^2 + j * (2m+1) + i. Indexed, so that each
// lattice point is shaded once rather than once per triangle using it.
LAGOON_FN ClipmapVertex clipmap_indexed_vertex(int index, vec2 camera, vec4 grid, vec4 clipmap) {
  int side = clipmap_cells_per_side(grid) + 1;
  int level = index / (side * side);
  int in_level = index - level * side * side;
  return clipmap_vertex(level, ivec2(in_level % side, in_level / side), camera, grid, clipmap);
}
LAGOON_GPU_END

#endif
