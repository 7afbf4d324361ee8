// What moves in the scene (docs/physics.md): the floating objects (objects[].floating), each a rigid body
// (physics/floating_body.h) on the sea's heights around it (ocean/local_heights.h), and the vehicles
// (vehicles[], physics/vehicle_motion.h), stepped together at a fixed 120 Hz from the scene's bodies_start_s
// (0 unless set), when they are at rest where the scene puts them. The floating objects rest on the scene's
// sea floor (world/floor_height.h) when they sink. With wakes.felt_by_bodies they ride the vehicles' wakes
// too (world/wake_heights.h), a vehicle every wake but its own. advance() brings them to a frame's time,
// simulating again from the start when asked for an earlier one, so a frame at time t shows the same poses
// however it was reached.
#pragma once
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/result.h"
#include "ocean/initial_spectrum.h"
#include "ocean/local_heights.h"
#include "physics/floating_body.h"
#include "physics/vehicle_motion.h"
#include "scene/scene.h"
#include "world/vehicle_tracks.h"
#include "world/wake_heights.h"

namespace lagoon::world {

class FloatingObjects {
 public:
  static constexpr double kStepS = 1.0 / 120.0;

  // Loads the hull of every floating object and surface vehicle (its glTF mesh, scaled), and the floor under
  // them. Fails naming the field when a hull is not a closed surface with a positive volume, or a glTF floor
  // cannot be read.
  // The vehicles follow `tracks` (one per scene vehicle; fresh ones on the scene's paths when not given).
  static Result<std::unique_ptr<FloatingObjects>> create(const scene::Scene& scene,
                                                         const ocean::OceanParams& ocean,
                                                         const std::vector<ocean::CascadeSpectrum>& spectra,
                                                         VehicleTracks tracks = {});

  bool empty() const { return bodies_.empty() && vehicles_.empty(); }
  void advance(double time_s);
  // The steps advance(time_s) would take (from the start when time_s is before the bodies' time).
  long long steps_to(double time_s) const;
  // The physics advance(time_s) would take, in hull-seconds (steps_to() times each hull's step): what the
  // scene rule on time_s bounds (scene.h: kMaxBodyHullSecondsPerFrame).
  double hull_seconds_to(double time_s) const;
  // The time they start at rest (scene.bodies_start_s, on the step grid).
  double start_s() const { return double(first_step_) * kStepS; }

  struct Pose {
    size_t object;             // index into the scene's objects, then its vehicles (objects.size() + v)
    glm::mat4 model_to_world;  // where to draw its model
  };
  std::vector<Pose> poses() const;
  // For tools and tests: the body of objects[object], or nullptr when it does not float.
  const physics::FloatingBody* body(size_t object) const;
  // The motion of vehicles[vehicle].
  const physics::VehicleMotion& vehicle(size_t vehicle) const { return vehicles_.at(vehicle).motion; }
  // The water's height as the hull of `object` (numbered as Pose::object) felt it at its last step, at
  // world (x, z) points within its reach: the sea around it plus every other vehicle's wake (beyond its
  // reach, the sea alone). Empty when it neither floats nor runs on the surface (a submerged vehicle feels
  // no surface).
  std::vector<double> water_under(size_t object, const std::vector<glm::dvec2>& points) const;
  // The body of `object` (a floating object's or a surface vehicle's hull), or nullptr.
  const physics::FloatingBody* hull_body(size_t object) const;
  // The vehicles' tracks (one per scene vehicle), shared with whoever created these objects.
  const VehicleTracks& tracks() const { return tracks_; }
  // The wakes the bodies ride (world/wake_heights.h), or nullptr.
  const WakeHeights* wakes() const { return wakes_.get(); }

 private:
  struct Body {
    size_t object;
    double scale;
    physics::FloatingBody body;
    std::unique_ptr<ocean::LocalHeights> heights;
    double water_top = 0;  // this step's bound on the water under it (physics/hydrostatics.h)
  };
  struct Vehicle {
    double scale;
    physics::VehicleMotion motion;
    std::unique_ptr<ocean::LocalHeights> heights;  // null when submerged
    double water_top = 0;
  };
  FloatingObjects(const scene::Scene& scene, ocean::OceanParams ocean,
                  std::vector<ocean::CascadeSpectrum> spectra)
      : scene_(scene), ocean_(std::move(ocean)), spectra_(std::move(spectra)) {}
  void reset();
  // Where the bodies' wake layer is centred: the mean position of what floats.
  glm::dvec2 centre() const;
  // One step of a hull, from what advance() prepared for the step (its knots with the wakes, its water_top).
  void step_body(Body& b);
  void step_vehicle(size_t vehicle, double t);

  scene::Scene scene_;
  ocean::OceanParams ocean_;
  std::vector<ocean::CascadeSpectrum> spectra_;
  std::vector<physics::TriangleMesh> hulls_;          // floating objects', in scene order
  std::vector<physics::TriangleMesh> vehicle_hulls_;  // surface vehicles', in scene order
  physics::FloorHeight floor_;                        // world y of the sea floor the floating objects rest on
  // The one thread that works ahead for the steps: the sea's next knots and their lattices, the wake layers'
  // next step, soonest due first. One, not one each: with two, both cores of a two-core machine were taken
  // from the steps whenever a knot and a wake step ran together (issue 35's worst frames).
  std::shared_ptr<BackgroundWorker> helper_ = std::make_shared<BackgroundWorker>();
  std::shared_ptr<ocean::WaveQuery> sea_;  // shared by every body's LocalHeights: one evaluation per knot
  std::vector<Body> bodies_;
  std::vector<Vehicle> vehicles_;
  VehicleTracks tracks_;
  std::unique_ptr<WakeHeights> wakes_;  // null when the bodies do not feel the wakes
  long long first_step_ = 0;            // the start, in steps from time 0
  long long wakes_first_step_ = 0;      // the step the bodies' wake layer starts from at rest
  long long steps_ = 0;                 // the bodies are at step steps_ (time steps_ · kStepS)
};

}  // namespace lagoon::world
