// Mass, centre of mass and inertia of a uniform solid bounded by a closed triangle mesh, by the divergence
// theorem over the tetrahedra the triangles span with the origin (Blow & Binstock's covariance method): the
// mass properties a floating body gets from its hull and a density (issue 14).
#pragma once
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace lagoon::physics {

// A closed surface, counter-clockwise seen from outside (glTF's front faces), in metres.
struct TriangleMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<uint32_t> indices;  // three per triangle
};

struct MassProperties {
  double volume = 0;        // m³
  double mass = 0;          // kg
  glm::dvec3 centre{0.0};   // centre of mass, in the mesh's coordinates
  glm::dmat3 inertia{1.0};  // kg·m², about the centre of mass, along the mesh's axes
};

// For density kg/m³. A mesh that is not closed or winds inward gives a volume <= 0; callers check it.
MassProperties solid_mass_properties(const TriangleMesh& mesh, double density);

}  // namespace lagoon::physics
