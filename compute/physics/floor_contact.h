// A body resting on the sea floor (issue 33): a penalty spring–damper at the points of its hull below the
// floor, and Coulomb friction that holds it where the floor's slope and the water would move it.
//
// Normal: each of the N points below the floor pushes along the floor's normal with
// (K·penetration − C·closing speed)/N, never pulling. Sharing K among the points in contact makes the floor's
// total stiffness K whatever the tessellation or contact patch: K = m·g/settle_m, so the body's full weight
// sinks it settle_m in, and its vertical frequency sqrt(K/m) = sqrt(g/settle_m) (22 rad/s at 2 cm) keeps
// ω·dt ≈ 0.2 at FloatingObjects' 120 Hz, well inside semi-implicit Euler's stability (ω·dt < 2);
// C = 2ζ·sqrt(K·m) damps it critically-ish. Rocking modes use the same springs at lever arms, so they stay
// below about sqrt(3)·sqrt(K/m).
// Friction: an impulse at the contact's centre that stops its tangential velocity this step (after the step's
// other forces), clamped to μ times the normal force: a stuck body does not creep, a pushed one slides.
// Stopping the contact point rather than the centre lets round bodies roll.
#pragma once
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <span>

namespace lagoon::physics {

// The world y (m, up) of the floor at (x, z): -infinity where there is none.
using FloorHeight = std::function<double(double x, double z)>;

struct FloorContactParams {
  double settle_m = 0.02;      // penetration under the body's full weight in air; > 0
  double damping_ratio = 0.7;  // ζ of the normal spring–damper
  double friction = 0.6;       // Coulomb μ (wet sand on steel or wood ~0.5–0.7)
};

// The normal forces of one step, about the body's centre of mass.
struct FloorPush {
  glm::dvec3 force{0.0};   // N
  glm::dvec3 torque{0.0};  // N·m about the centre of mass
  glm::dvec3 normal{0, 1, 0};
  glm::dvec3 at{0.0};       // where they act on average (weighted by force), world
  double normal_force = 0;  // N, along `normal`
  int points = 0;           // in contact
};

struct RigidMotion {
  glm::dvec3 centre{0.0};  // of mass, world
  glm::dvec3 velocity{0.0};
  glm::dvec3 angular_velocity{0.0};
};

// `points` the hull's sample points in world coordinates, of a body of `mass` kg.
FloorPush floor_push(std::span<const glm::dvec3> points, const RigidMotion& body, double mass,
                     const FloorHeight& floor, const FloorContactParams& params, double gravity);

// The friction force (N, at push.at) for a step of dt seconds, given the other forces and torque (about the
// centre) the step applies and the world inverse inertia.
glm::dvec3 floor_friction(const FloorPush& push, const RigidMotion& body, double mass,
                          const glm::dmat3& inverse_inertia, glm::dvec3 other_force, glm::dvec3 other_torque,
                          double dt, const FloorContactParams& params);

}  // namespace lagoon::physics
