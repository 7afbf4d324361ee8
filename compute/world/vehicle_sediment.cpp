#include "world/vehicle_sediment.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/common.hpp>
#include <span>
#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "world/floor_height.h"
#include "world/vehicle_tracks.h"

namespace lagoon::world {

Result<VehicleSediment> VehicleSediment::create(const scene::Scene& scene, VehicleTracks tracks) {
  VehicleSediment out;
  const scene::Sediment& s = scene.sediment;
  // Every drawn floor stirs, the slope and a glTF floor (by its triangles): the heights the bodies rest on.
  // Without one there is nothing to stir (and the shaders compile the clouds out).
  if (!s.enabled || scene.vehicles.empty() || scene.seafloor.type == scene::SeafloorType::None) return out;
  auto floor = floor_height(scene);
  if (!floor) return floor.error();
  tracks = tracks_or_fresh(scene, std::move(tracks));
  std::vector<physics::StirrerBottom> stirrers;
  for (size_t v = 0; v < scene.vehicles.size(); ++v) {
    const scene::Vehicle& vehicle = scene.vehicles[v];
    auto model = gltf::load_gltf(vehicle.file);
    if (!model) return make_error("vehicles[" + std::to_string(v) + "].file: " + model.error().message);
    // The hull's lowest point below its origin; the origin at the mean level for a surface hull (its heave
    // of a few decimetres is left out), at depth_m for a submerged one.
    const double bottom = double(model->bounds_min.y) * double(vehicle.scale) - double(vehicle.depth_m);
    std::shared_ptr<const physics::VehicleTrack> track = tracks[v];
    stirrers.push_back([track, bottom](double t) {
      const glm::dvec2 p = track->at(t).position;
      return glm::dvec3(p.x, bottom, p.y);
    });
  }
  out.cloud_.emplace(
      physics::SedimentParams{.release_height_m = s.release_height_m,
                              .release_g_per_s = s.release_g_per_s,
                              .rise_m = s.rise_m,
                              .radius_m = s.radius_m,
                              .settling_mps = s.settling_mps,
                              .diffusivity_m2_s = s.diffusivity_m2_s,
                              .current_mps = glm::dvec2(s.current_mps),
                              .interval_s = s.interval_s,
                              .max_age_s = s.max_age_s,
                              .burst_s = s.burst_s},
      [height = *floor](glm::dvec2 xz) { return -height(xz.x, xz.y); }, std::move(stirrers));
  out.attenuation_ = s.attenuation_m2_per_g;
  out.colour_ = s.colour;
  out.grains_per_g_ = s.grains_per_g;
  return out;
}

std::vector<physics::SedimentPuff> VehicleSediment::puffs(double time_s) const {
  return cloud_ ? cloud_->puffs(time_s) : std::vector<physics::SedimentPuff>{};
}

uint32_t VehicleSediment::write(double time_s, gpu::SedimentHeader* header,
                                gpu::SedimentPuffGpu* puffs) const {
  std::vector<physics::SedimentPuff> all = this->puffs(time_s);
  // The most mass in the water first; past the buffer's capacity the faintest clouds are left out.
  const size_t kept = std::min<size_t>(all.size(), LAGOON_MAX_SEDIMENT_PUFFS);
  std::partial_sort(all.begin(), all.begin() + long(kept), all.end(),
                    [](const auto& a, const auto& b) { return a.suspended_g > b.suspended_g; });
  for (size_t i = 0; i < kept; ++i) {
    const physics::SedimentPuff& p = all[i];
    puffs[i] = {.centre_sigma = glm::vec4(glm::vec3(p.centre), float(p.sigma)),
                .strength = glm::vec4(float(p.mass_g * attenuation_),
                                      std::min(std::round(float(p.suspended_g) * grains_per_g_),
                                               float(LAGOON_SEDIMENT_MAX_GRAINS)),
                                      std::bit_cast<float>(p.release), 0)};
  }
  // The boxes from the clouds as the shaders read them (floats), a millimetre and a float's rounding wider so
  // that their float test never culls a cloud the cut inside the loop keeps. The mass order groups a
  // vehicle's stream of clouds by age, hence by where along its track they were released.
  std::vector<physics::SedimentPuff> sent(all.begin(), all.begin() + long(kept));
  for (physics::SedimentPuff& p : sent) {
    p.centre = glm::dvec3(glm::vec3(p.centre));
    p.sigma = double(float(p.sigma));
  }
  const auto write_box = [](std::span<const physics::SedimentPuff> clouds, glm::vec4& lo, glm::vec4& hi) {
    const physics::SedimentBox box = physics::sediment_reach(clouds);
    const glm::dvec3 pad = 1e-3 + 1e-5 * glm::max(glm::abs(box.lo), glm::abs(box.hi));
    lo = glm::vec4(glm::vec3(clouds.empty() ? glm::dvec3(1e30) : box.lo - pad), 0.0f);
    hi = glm::vec4(glm::vec3(clouds.empty() ? glm::dvec3(-1e30) : box.hi + pad), 0.0f);
  };
  header->colour = glm::vec4(colour_, float(kept));
  write_box(sent, header->box_lo, header->box_hi);
  for (size_t g = 0; g < LAGOON_SEDIMENT_GROUPS; ++g) {
    const size_t first = std::min(kept, g * LAGOON_SEDIMENT_GROUP);
    const size_t end = std::min(kept, first + LAGOON_SEDIMENT_GROUP);
    write_box(std::span(sent).subspan(first, end - first), header->group_lo[g], header->group_hi[g]);
  }
  return uint32_t(kept);
}

}  // namespace lagoon::world
