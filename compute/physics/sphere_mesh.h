// A closed UV sphere as a hull: the IEA OES Task 10 floating sphere of `lagoon validate` and the tests, whose
// buoyancy, heave stiffness and wave force have closed forms or quadratures to check against.
#pragma once
#include "physics/mass_properties.h"

namespace lagoon::physics {

// Radius `r`, `rings` from pole to pole and 2·rings sectors, counter-clockwise from outside; the
// equator is a ring when `rings` is even (a half-submerged sphere's waterline on vertices).
TriangleMesh uv_sphere(double r, int rings);

}  // namespace lagoon::physics
