// A scene's world in one object (issue 35): what moves in it (the floating bodies and vehicles stepped at
// fixed steps, world/floating_objects.h), the vehicles' tracks they share with their wakes and sediment, the
// sediment they stir (world/vehicle_sediment.h) and, for a host that draws, where the camera is
// (world/camera_medium.h). The renderer makes one and reads its state each frame; `lagoon probe`, `export`,
// `bench bodies` and embedding hosts make the same one without a device (examples/embed/world_step.cpp).
#pragma once
#include <memory>
#include <vector>

#include "core/result.h"
#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "scene/scene.h"
#include "world/camera_medium.h"
#include "world/floating_objects.h"
#include "world/vehicle_sediment.h"
#include "world/vehicle_tracks.h"

namespace lagoon::world {

struct WorldOptions {
  VehicleTracks tracks;       // one per scene vehicle (shared with a host's helm); fresh when empty
  double camera_reach_m = 0;  // > 0: judge the camera's side against waves that stay within it (the
                              // renderer's displacement bound); 0: no camera medium (a host that only steps)
};

class World {
 public:
  // The sea is `ocean` with its cascades' `spectra` (ocean::make_cascade_spectra, or the GPU ocean's own).
  // Fails naming the field when a hull, a vehicle's model or a glTF floor cannot be read.
  static Result<std::unique_ptr<World>> create(const scene::Scene& scene, const ocean::OceanParams& ocean,
                                               const std::vector<ocean::CascadeSpectrum>& spectra,
                                               WorldOptions options = {});

  // The bodies and vehicles to time_s (from the start when it is before their time).
  void advance(double time_s) { bodies_->advance(time_s); }
  FloatingObjects& bodies() { return *bodies_; }
  const FloatingObjects& bodies() const { return *bodies_; }
  const VehicleTracks& tracks() const { return tracks_; }
  const VehicleSediment& sediment() const { return sediment_; }
  // Only with options.camera_reach_m > 0.
  bool has_camera_medium() const { return camera_medium_ != nullptr; }
  CameraMedium& camera_medium() { return *camera_medium_; }

 private:
  World() = default;
  VehicleTracks tracks_;
  std::unique_ptr<FloatingObjects> bodies_;
  VehicleSediment sediment_;
  std::unique_ptr<CameraMedium> camera_medium_;
};

}  // namespace lagoon::world
