// The scene's vehicles as the wakes see them (docs/physics.md, Wakes): each a pressure patch on the water
// (ocean::WakeSource) moving along its path, with the layer's parameters, window and time steps. Shared by
// the frame's wakes pass (render/passes/wakes_pass.h) and `lagoon export`, so both run the same layer.
#pragma once
#include <glm/vec2.hpp>
#include <vector>

#include "core/result.h"
#include "ocean/dynamic_layer.h"
#include "scene/scene.h"
#include "world/vehicle_tracks.h"

namespace lagoon::world {

class VehicleWakes {
 public:
  // Fails naming the field when a vehicle's model cannot be read (a footprint comes from its bounds).
  // Empty when wakes.enabled is false or no vehicle makes a wake or a trail. The hulls follow `tracks` (one
  // per scene vehicle; fresh ones on the scene's paths when not given).
  static Result<VehicleWakes> create(const scene::Scene& scene, VehicleTracks tracks = {});

  bool empty() const { return hulls_.empty(); }
  // The hulls on the water at time t (from their tracks; their heave does not matter here).
  std::vector<ocean::WakeSource> sources(double t) const;
  // The vehicle (index into the scene's vehicles) whose hull is sources(t)[source].
  size_t vehicle_of(size_t source) const { return hulls_.at(source).vehicle; }
  const ocean::DynamicLayerParams& params() const { return params_; }

  // Where the window lies for `camera`: where it looks, the camera inside (its centre 0.35 of the window's
  // width ahead of the camera, in whole cells).
  glm::ivec2 window_for(const scene::Camera& camera) const;

  // The layer steps at step_s() from time 0: the last step not after time t, and the step a layer for time t
  // starts from at rest when no earlier frame's layer is carried to it (history_s before it, or 0).
  double step_s() const { return step_s_; }
  long long step_at(double t) const;
  long long first_step_for(double t) const;

 private:
  struct Hull {
    size_t vehicle;  // in the scene's vehicles
    std::shared_ptr<const physics::VehicleTrack> track;
    glm::dvec2 sigma;   // along, across
    double depression;  // m
    double depth;       // m, of a submerged vehicle
    double foam_per_s;  // 0 when submerged
  };
  std::vector<Hull> hulls_;
  ocean::DynamicLayerParams params_;
  double step_s_ = 0.1;
  long long history_steps_ = 300;
};

}  // namespace lagoon::world
