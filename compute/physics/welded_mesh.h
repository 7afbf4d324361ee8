// A hull with one vertex per position (issue 35: physics at physics rate). glTF models repeat a vertex
// wherever its normal or texture coordinate changes (a hard edge, a UV seam): the harbour's buoy has 1,970
// vertices where its 2,112 closed triangles need about 1,060. A hull step looks the water up once per
// vertex, so every repeat is a lookup for nothing. Welding keeps each triangle's corners where they were,
// so the pressure a hull feels is the same to the bit; only points a body counts one by one (floor contact)
// no longer count a seam twice.
#pragma once
#include "physics/mass_properties.h"

namespace lagoon::physics {

// `mesh` with vertices at exactly the same position merged into the first of them (in order), the triangles
// renumbered (in the order the triangles first
// use them), unused vertices dropped, and triangles with a corner that is not a vertex left out.
TriangleMesh welded(const TriangleMesh& mesh);

}  // namespace lagoon::physics
