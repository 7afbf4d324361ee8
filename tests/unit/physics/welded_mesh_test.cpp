// welded() (physics/welded_mesh.h): a hull whose triangles each have their own corners (as glTF splits
// vertices at hard edges and UV seams) becomes one vertex per position, and a floating body made of it
// moves as one made of the shared-vertex mesh, with as few water lookups.
#include "physics/welded_mesh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <span>
#include <vector>

#include "physics/floating_body.h"
#include "support/box_mesh.h"

namespace lagoon::test {
namespace {

// `mesh` with three vertices of its own per triangle.
physics::TriangleMesh split(const physics::TriangleMesh& mesh) {
  physics::TriangleMesh out;
  for (uint32_t i : mesh.indices) {
    out.indices.push_back(uint32_t(out.vertices.size()));
    out.vertices.push_back(mesh.vertices[i]);
  }
  return out;
}

TEST(WeldedMesh, OneVertexPerPositionAndTheSameTriangles) {
  const physics::TriangleMesh shared = physics::welded(box({0.5, 0.3, 0.4}));
  const physics::TriangleMesh seams = split(box({0.5, 0.3, 0.4}));
  ASSERT_EQ(seams.vertices.size(), 36u);
  const physics::TriangleMesh welded = physics::welded(seams);
  EXPECT_EQ(welded.vertices.size(), 8u);
  ASSERT_EQ(welded.indices.size(), seams.indices.size());
  for (size_t k = 0; k < seams.indices.size(); ++k)
    EXPECT_EQ(welded.vertices[welded.indices[k]], seams.vertices[seams.indices[k]]) << "corner " << k;
  EXPECT_EQ(welded.vertices, shared.vertices) << "numbered in the order the triangles first use them";
  // -0 and +0 are one position; a triangle with a corner that is not a vertex is left out.
  physics::TriangleMesh odd{{{0, 0, 0}, {-0.0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 2, 3, 1, 3, 2, 0, 2, 9}};
  const physics::TriangleMesh fixed = physics::welded(odd);
  EXPECT_EQ(fixed.vertices.size(), 3u);
  EXPECT_EQ(fixed.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 1}));
}

// A body from the split hull samples the water at as many points as one from the shared hull, and moves as
// it does to the bit, in waves that rock and heave it.
TEST(WeldedMesh, ABodyFromASplitHullMovesAsOneFromTheSharedHull) {
  const physics::TriangleMesh shared = box({1.0, 0.3, 0.5});
  const physics::MassProperties mass = physics::solid_mass_properties(shared, 500.0);
  physics::FloatingBody a(shared, mass, {.linear = 0.5}, {}), b(split(shared), mass, {.linear = 0.5}, {});
  EXPECT_EQ(b.sample_points_in_world().size(), a.sample_points_in_world().size());
  const physics::WaterHeight water = [](double x, double z) { return 0.2 * std::sin(1.1 * x + 0.4 * z); };
  for (physics::FloatingBody* body : {&a, &b}) {
    body->place({0.3, 0.0, -0.2}, glm::dquat(1, 0, 0, 0));
    for (int step = 0; step < 240; ++step) body->step(1.0 / 120.0, water);
  }
  EXPECT_EQ(0, std::memcmp(&a.state(), &b.state(), sizeof(physics::BodyState)));
  EXPECT_GT(std::abs(a.state().angular_velocity.z) + std::abs(a.state().angular_velocity.x), 1e-3)
      << "the waves must rock it";
}

}  // namespace
}  // namespace lagoon::test
