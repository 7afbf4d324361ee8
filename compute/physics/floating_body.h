// A rigid body with six degrees of freedom floating on the water (issue 14): gravity, the water's pressure on
// its hull (physics/hydrostatics.h) and damping, integrated with a fixed time step (semi-implicit Euler with
// a unit-quaternion attitude), so the same inputs give the same motion whatever the frame rate.
// The pressure is integrated over a refined copy of the hull (physics/hull_sampling.h): its heave in a wave
// follows the wave, not the model's tessellation. With a floor (physics/floor_contact.h) a body denser than
// water comes to rest on it, and a lighter one rises off it. Heave added mass and radiation damping are
// opt-in (physics/heave_radiation.h).
// Deterministic: no threads, no clocks.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "physics/floor_contact.h"
#include "physics/heave_radiation.h"
#include "physics/hull_sampling.h"
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

struct BodyOptions {
  HullSampling sampling;  // the points the water's height is sampled at
  FloorHeight floor;      // none: nothing under the body (it sinks for ever if it cannot float)
  FloorContactParams contact;
  HeaveRadiation radiation;  // off: the hydrostatic pressure alone
};

class FloatingBody {
 public:
  // `hull` in body coordinates (the model's); `mass` from solid_mass_properties or given by the scene (of
  // the model's own mesh: refining it for the pressure changes no mass property).
  FloatingBody(const TriangleMesh& hull, const MassProperties& mass, Damping damping, WaterProperties water,
               BodyOptions options = {});

  // Places the body's model origin at `origin` with `orientation`, at rest.
  void place(glm::dvec3 origin, glm::dquat orientation);
  // Moves it vertically, keeping its orientation, to where the water's pressure in still water at height
  // `level` carries its weight (bisection). False, unmoved, when it cannot float (it sinks even submerged).
  bool settle_vertically(double level);
  // One step of dt seconds with the water's height as it is at the step's start; `water_top` bounds it
  // from above (physics/hydrostatics.h: the hull's dry part is then not looked up). With `head` the hull
  // feels the pressure under the waves as linear theory has it, and the heave radiation the water's motion
  // at the hull's depth (physics/heave_radiation.h); without it, the height above each point.
  // `heights`, when given, answers for the hull's points in one call instead of `water` at each.
  void step(double dt, const WaterHeight& water, double water_top = std::numeric_limits<double>::infinity(),
            const PressureHead& head = {}, const WaterHeights& heights = {});
  // Puts a floor under the body (or takes it away with an empty function).
  void set_floor(FloorHeight floor) { options_.floor = std::move(floor); }

  const BodyState& state() const { return state_; }
  BodyState& state() { return state_; }
  // Where the model's origin is: the pose a renderer draws the mesh at.
  glm::dvec3 model_origin() const;
  const MassProperties& mass() const { return mass_; }
  // The last step's water wrench about the centre of mass.
  const Wrench& last_wrench() const { return wrench_; }
  // The last step's push of the floor (no points when it did not touch it).
  const FloorPush& last_floor_push() const { return floor_push_; }
  // How many points the water's height is sampled at (the refined hull's vertices).
  size_t sample_points() const { return hull_.size(); }
  // The farthest of them from the centre of mass (m): a box of this half-width about the centre holds the
  // hull however it turns.
  double reach() const { return reach_; }
  // Those points where the body is now (world coordinates).
  std::vector<glm::dvec3> sample_points_in_world() const;
  double kinetic_energy() const;

 private:
  // The floor's push and friction for this step, added to the step's force and torque (about the centre).
  void add_floor(double dt, const glm::dmat3& inverse_inertia, glm::dvec3& force, glm::dvec3& torque);
  // With options_.radiation: adds the radiation and diffraction forces to `force`, returns the heave's
  // added mass (kg).
  double add_heave_radiation(double dt, const WaterHeight& water, const PressureHead& head,
                             glm::dvec3& force);

  std::vector<glm::dvec3> hull_;  // the refined hull, relative to the centre of mass
  std::vector<uint32_t> indices_;
  HullPressure pressure_;  // the water's wrench on hull_
  double hull_area_ = 0;
  double reach_ = 0;
  MassProperties mass_;
  glm::dmat3 inverse_inertia_{1.0};
  Damping damping_;
  WaterProperties water_;
  BodyOptions options_;
  BodyState state_;
  Wrench wrench_;
  FloorPush floor_push_;
  // The water's pressure head at the hull's depth under the centre, and its rate, a step ago (radiation
  // only).
  double last_head_ = 0, last_rise_ = 0;
  int head_steps_ = 0;             // how many of them are known (0 to 2)
  std::vector<glm::dvec3> world_;  // scratch: the hull in world coordinates
};

}  // namespace lagoon::physics
