#include "world/vehicle_wakes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "gltf/gltf_loader.h"
#include "world/vehicle_tracks.h"

namespace lagoon::world {

Result<VehicleWakes> VehicleWakes::create(const scene::Scene& scene, VehicleTracks tracks) {
  VehicleWakes wakes;
  const scene::Wakes& w = scene.wakes;
  wakes.params_ = ocean::DynamicLayerParams{.n = w.resolution,
                                            .cell_m = double(w.cell_size_m),
                                            .depth_m = double(scene.ocean.depth_m),
                                            .decay_per_s = double(w.damping_per_s),
                                            .sponge_m = double(w.border_m),
                                            .foam_lifetime_s = double(w.foam_lifetime_s),
                                            .foam_spread_m2_s = double(w.foam_spread_m2_s)};
  wakes.step_s_ = double(w.step_s);
  wakes.history_steps_ = (long long)std::ceil(double(w.history_s) / wakes.step_s_);
  if (!w.enabled) return wakes;
  tracks = tracks_or_fresh(scene, std::move(tracks));
  for (size_t v = 0; v < scene.vehicles.size(); ++v) {
    const scene::Vehicle& vehicle = scene.vehicles[v];
    const bool submerged = vehicle.depth_m > 0;
    if (vehicle.wake_strength <= 0 && (vehicle.foam_per_s <= 0 || submerged)) continue;
    auto model = gltf::load_gltf(vehicle.file);
    if (!model) return make_error("vehicles[" + std::to_string(v) + "].file: " + model.error().message);
    // The hull's footprint: a Gaussian whose ±2 sigma span its length and beam, as deep at its centre as
    // the model reaches below its waterline (its origin) at the surface, or as its height when submerged.
    const glm::dvec3 lo = glm::dvec3(model->bounds_min) * double(vehicle.scale);
    const glm::dvec3 hi = glm::dvec3(model->bounds_max) * double(vehicle.scale);
    const double reach = submerged ? hi.y - lo.y : std::max(-lo.y, 0.0);
    wakes.hulls_.push_back({v, tracks[v],
                            glm::dvec2(std::max(hi.z - lo.z, 1e-3) / 4, std::max(hi.x - lo.x, 1e-3) / 4),
                            reach * double(vehicle.wake_strength), submerged ? double(vehicle.depth_m) : 0.0,
                            submerged ? 0.0 : double(vehicle.foam_per_s)});
  }
  return wakes;
}

std::vector<ocean::WakeSource> VehicleWakes::sources(double t) const {
  std::vector<ocean::WakeSource> out;
  for (const Hull& h : hulls_) {
    const physics::TrackPoint p = h.track->at(t);
    out.push_back({.centre = p.position,
                   .velocity = p.velocity,
                   .heading = p.heading,
                   .sigma = h.sigma,
                   .depression = h.depression,
                   .depth = h.depth,
                   .foam_per_s = h.foam_per_s});
  }
  return out;
}

glm::ivec2 VehicleWakes::window_for(const scene::Camera& camera) const {
  const double cell = params_.cell_m, width = params_.n * cell;
  glm::dvec2 ahead(camera.look_at.x - camera.position.x, camera.look_at.z - camera.position.z);
  const double length = glm::length(ahead);
  ahead = length > 1e-6 ? ahead / length : glm::dvec2(0.0);  // straight down: the camera at the centre
  const glm::dvec2 centre = glm::dvec2(camera.position.x, camera.position.z) + 0.35 * width * ahead;
  const int half = int(params_.n / 2);
  return {int(std::floor(centre.x / cell)) - half, int(std::floor(centre.y / cell)) - half};
}

long long VehicleWakes::step_at(double t) const {
  // step_s is a float in the scene (0.1f is 0.10000000149): 9 s / 0.1f is 89.9999987 steps, meant as 90.
  return (long long)std::floor(std::max(t, 0.0) / step_s_ + 1e-4);
}

long long VehicleWakes::first_step_for(double t) const {
  return std::max(0LL, step_at(t) - history_steps_);
}

}  // namespace lagoon::world
