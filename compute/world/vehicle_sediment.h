// The scene's vehicles as stirrers of the floor (docs/physics.md, Sediment): each hull's lowest point along
// its path, over the floor's heights (world/floor_height.h: the slope, a glTF floor), releases clouds
// (physics/sediment.h) with the scene's `sediment` parameters. Shared by the frame (its sediment buffer,
// shared/sediment.h) and the tools, so both see the same clouds.
#pragma once
#include <optional>
#include <vector>

#include "core/result.h"
#include "physics/sediment.h"
#include "scene/scene.h"
#include "shared/sediment.h"
#include "world/vehicle_tracks.h"

namespace lagoon::world {

class VehicleSediment {
 public:
  // Fails naming the field when a vehicle's model cannot be read (its lowest point comes from its bounds).
  // Fails naming seafloor.file when a glTF floor cannot be read. Empty when sediment.enabled is false, there
  // are no vehicles or no floor is drawn (seafloor.type "none").
  // The stirrers follow `tracks` (one per scene vehicle; fresh ones on the scene's paths when not given).
  static Result<VehicleSediment> create(const scene::Scene& scene, VehicleTracks tracks = {});

  bool empty() const { return !cloud_; }
  std::vector<physics::SedimentPuff> puffs(double time_s) const;
  const physics::SedimentCloud& cloud() const { return *cloud_; }
  double attenuation_m2_per_g() const { return attenuation_; }

  // The frame's buffer at time t: the header, then at most LAGOON_MAX_SEDIMENT_PUFFS clouds, the ones with
  // the most suspended mass. Returns how many were written.
  uint32_t write(double time_s, gpu::SedimentHeader* header, gpu::SedimentPuffGpu* puffs) const;

 private:
  std::optional<physics::SedimentCloud> cloud_;
  double attenuation_ = 0;
  glm::vec3 colour_{0.f};
  float grains_per_g_ = 0;
};

}  // namespace lagoon::world
