#include "world/world.h"

#include <utility>

namespace lagoon::world {

Result<std::unique_ptr<World>> World::create(const scene::Scene& scene, const ocean::OceanParams& ocean,
                                             const std::vector<ocean::CascadeSpectrum>& spectra,
                                             WorldOptions options) {
  std::unique_ptr<World> world(new World());
  world->tracks_ = tracks_or_fresh(scene, std::move(options.tracks));
  auto bodies = FloatingObjects::create(scene, ocean, spectra, world->tracks_);
  if (!bodies) return bodies.error();
  world->bodies_ = std::move(*bodies);
  auto sediment = VehicleSediment::create(scene, world->tracks_);
  if (!sediment) return sediment.error();
  world->sediment_ = std::move(*sediment);
  if (options.camera_reach_m > 0)
    world->camera_medium_ = std::make_unique<CameraMedium>(ocean, spectra, options.camera_reach_m);
  return world;
}

}  // namespace lagoon::world
