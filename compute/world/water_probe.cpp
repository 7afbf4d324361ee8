#include "world/water_probe.h"

#include <glm/geometric.hpp>
#include <memory>

#include "world/wake_heights.h"

namespace lagoon::world {
namespace {

// Null when the scene makes no wakes or its bodies do not feel them.
Result<std::unique_ptr<WakeHeights>> wakes_at(const scene::Scene& scene, double t,
                                              std::span<const glm::dvec2> points) {
  if (!scene.wakes.felt_by_bodies || points.empty()) return std::unique_ptr<WakeHeights>();
  auto hulls = VehicleWakes::create(scene);
  if (!hulls) return hulls.error();
  if (hulls->empty()) return std::unique_ptr<WakeHeights>();
  glm::dvec2 centre(0.0);
  for (const glm::dvec2& p : points) centre += p / double(points.size());
  const long long first = hulls->first_step_for(t);
  auto wakes = std::make_unique<WakeHeights>(std::move(*hulls), scene.wakes.bodies_resolution);
  wakes->advance(t, centre, first);
  return wakes;
}

}  // namespace

Result<WaterAtPoints> water_at_points(const scene::Scene& scene, ocean::WaveQuery& query, double time_s,
                                      std::span<const glm::dvec2> points) {
  WaterAtPoints out{.samples = query.sample(time_s, points),
                    .wake_heights = std::vector<double>(points.size())};
  auto wakes = wakes_at(scene, time_s, points);
  if (!wakes) return wakes.error();
  if (!*wakes) return out;
  for (size_t i = 0; i < points.size(); ++i) {
    ocean::WaveSample& s = out.samples[i];
    const glm::dvec2 slope = glm::dvec2(-s.normal.x, -s.normal.z) / s.normal.y + (*wakes)->slope(points[i]);
    out.wake_heights[i] = (*wakes)->height(points[i]);
    s.height += out.wake_heights[i];
    s.normal = glm::normalize(glm::dvec3(-slope.x, 1.0, -slope.y));
    s.velocity.y += (*wakes)->rate(points[i]);
  }
  return out;
}

}  // namespace lagoon::world
