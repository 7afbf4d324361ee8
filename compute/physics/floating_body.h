// A rigid body with six degrees of freedom floating on the water (issue 14): gravity, the water's pressure on
// its hull (physics/hydrostatics.h) and damping, integrated with a fixed time step (semi-implicit Euler with
// a unit-quaternion attitude), so the same inputs give the same motion whatever the frame rate.
// Deterministic: no threads, no clocks.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "physics/hydrostatics.h"
#include "physics/mass_properties.h"

namespace lagoon::physics {

struct BodyState {
  glm::dvec3 position{0.0};            // of the centre of mass, world, m
  glm::dquat orientation{1, 0, 0, 0};  // body to world
  glm::dvec3 velocity{0.0};            // m/s
  glm::dvec3 angular_velocity{0.0};    // rad/s, world axes
};

// Forces against the motion while the hull is in the water, scaled by its wetted share (a body in the air
// falls freely): −(linear + quadratic·|v|)·m·v and −(angular + angular_quadratic·|ω|)·I·ω. Per second: a
// linear 0.5 halves a velocity in about 1.4 s.
struct Damping {
  double linear = 0.5;             // 1/s
  double quadratic = 0.5;          // 1/m
  double angular = 0.5;            // 1/s
  double angular_quadratic = 0.5;  // 1/rad
};

struct WaterProperties {
  double density = 1025.0;  // kg/m³, sea water
  double gravity = 9.81;    // m/s²
};

class FloatingBody {
 public:
  // `hull` in body coordinates (the model's); `mass` from solid_mass_properties or given by the scene.
  FloatingBody(const TriangleMesh& hull, const MassProperties& mass, Damping damping, WaterProperties water);

  // Places the body's model origin at `origin` with `orientation`, at rest.
  void place(glm::dvec3 origin, glm::dquat orientation);
  // Moves it vertically, keeping its orientation, to where the water's pressure in still water at height
  // `level` carries its weight (bisection). False, unmoved, when it cannot float (it sinks even submerged).
  bool settle_vertically(double level);
  // One step of dt seconds with the water's height as it is at the step's start.
  void step(double dt, const WaterHeight& water);

  const BodyState& state() const { return state_; }
  BodyState& state() { return state_; }
  // Where the model's origin is: the pose a renderer draws the mesh at.
  glm::dvec3 model_origin() const;
  const MassProperties& mass() const { return mass_; }
  // The last step's water wrench about the centre of mass.
  const Wrench& last_wrench() const { return wrench_; }
  double kinetic_energy() const;

 private:
  std::vector<glm::dvec3> hull_;  // relative to the centre of mass
  std::vector<uint32_t> indices_;
  double hull_area_ = 0;
  MassProperties mass_;
  glm::dmat3 inverse_inertia_{1.0};
  Damping damping_;
  WaterProperties water_;
  BodyState state_;
  Wrench wrench_;
  std::vector<glm::dvec3> world_;  // scratch: the hull in world coordinates
};

}  // namespace lagoon::physics
