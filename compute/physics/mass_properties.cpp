#include "physics/mass_properties.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace lagoon::physics {

MassProperties solid_mass_properties(const TriangleMesh& mesh, double density) {
  // The covariance ∫ x xᵀ dV of the canonical tetrahedron (0, e1, e2, e3), whose volume is 1/6.
  const glm::dmat3 canonical = glm::dmat3(2, 1, 1, 1, 2, 1, 1, 1, 2) / 120.0;
  double volume = 0;
  glm::dvec3 moment(0.0);
  glm::dmat3 covariance(0.0);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.vertices[mesh.indices[t]], b = mesh.vertices[mesh.indices[t + 1]],
                     c = mesh.vertices[mesh.indices[t + 2]];
    const glm::dmat3 A(a, b, c);  // columns: the tetrahedron is A applied to the canonical one
    const double det = glm::dot(a, glm::cross(b, c));
    volume += det / 6.0;
    moment += det / 6.0 * (a + b + c) / 4.0;
    covariance += det * A * canonical * glm::transpose(A);
  }
  MassProperties out;
  out.volume = volume;
  out.mass = density * volume;
  if (volume <= 0) return out;
  out.centre = moment / volume;
  // Moved to the centre of mass (parallel axis), then I = tr(C)·1 − C.
  const glm::dmat3 c = density * covariance - out.mass * glm::outerProduct(out.centre, out.centre);
  out.inertia = (c[0][0] + c[1][1] + c[2][2]) * glm::dmat3(1.0) - c;
  return out;
}

}  // namespace lagoon::physics
