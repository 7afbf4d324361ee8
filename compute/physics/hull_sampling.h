// The hull the water's pressure is integrated over (physics/hydrostatics.h samples the water's height at its
// vertices only): a copy of the body's mesh whose triangles are split until no edge is longer than a sample
// spacing, so the buoyancy a body feels depends on the waves, not on how its model was tessellated. A wave
// shorter than about two samples averages out over the hull, as it does in the Froude–Krylov force of a
// body of length L (sinc(kL/2)): the spacing sets the shortest wave a body responds to.
#pragma once
#include <cstddef>

#include "physics/mass_properties.h"

namespace lagoon::physics {

struct HullSampling {
  static constexpr double kDivisions = 16;
  static constexpr double kMinSpacingM =
      0.2;  // waves under ~0.4 m barely move a body (sinc), and each sample costs a lookup

  // Longest edge (m) of the triangles the pressure is integrated over. 0: derived from the hull (its
  // largest extent / kDivisions, at least min_spacing_m); < 0: the hull's own triangles (the pressure only at
  // the model's vertices: how coarse it is then depends on the modeller).
  double spacing_m = 0;
  // The finest spacing derived from the hull. A water whose shortest wave is λ needs no sample closer than
  // about λ/4 (world/floating_objects.h: the bodies' sea holds waves of 2 m and longer).
  double min_spacing_m = kMinSpacingM;
  // More triangles than this raise the spacing until they fit: the step's cost is one water lookup per
  // vertex, about half this count.
  size_t max_triangles = 20000;
};

// The spacing `sampling` asks for on `hull` (before the triangle cap), in m; <= 0 when it asks for none.
double sample_spacing(const TriangleMesh& hull, const HullSampling& sampling);

// `hull` with every triangle split along its longest edge until all edges are at most the spacing (edges a
// split shares with a neighbour get one midpoint vertex, so the water is looked up once there). The surface
// is the same (a split adds no area and leaves no gap), so closed stays closed and still water gives the
// same buoyancy to rounding. Returns `hull` itself when `sampling` asks for no refinement.
TriangleMesh refine_hull(const TriangleMesh& hull, const HullSampling& sampling);

}  // namespace lagoon::physics
