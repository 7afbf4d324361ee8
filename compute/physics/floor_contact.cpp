#include "physics/floor_contact.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

namespace lagoon::physics {
namespace {

// The floor's upward normal at (x, z) by central differences over 0.1 m (a finer step only adds rounding).
glm::dvec3 floor_normal(const FloorHeight& floor, double x, double z) {
  constexpr double h = 0.05;
  const double gx = (floor(x + h, z) - floor(x - h, z)) / (2 * h);
  const double gz = (floor(x, z + h) - floor(x, z - h)) / (2 * h);
  if (!std::isfinite(gx) || !std::isfinite(gz)) return {0, 1, 0};  // at the floor's edge
  return glm::normalize(glm::dvec3(-gx, 1.0, -gz));
}

// The floor's height under `centre` when the body may touch it, NaN when it surely does not: its lowest
// point is higher than that plus twice its horizontal radius (a floor steeper than 2:1 under a body could be
// missed), so a floating body costs one floor lookup a step. +inf where the floor has no height there.
double may_touch(std::span<const glm::dvec3> points, glm::dvec3 centre, const FloorHeight& floor) {
  // The squared radius: this runs over every hull point at every step, and std::hypot's care for
  // overflow costs several times the rest of the loop. Any bound on the radius gives the same contact.
  double lowest = 1e300, radius2 = 0;
  for (const glm::dvec3& p : points) {
    const double dx = p.x - centre.x, dz = p.z - centre.z;
    lowest = std::min(lowest, p.y), radius2 = std::max(radius2, dx * dx + dz * dz);
  }
  const double under = floor(centre.x, centre.z);
  if (!std::isfinite(under)) return std::numeric_limits<double>::infinity();
  return lowest <= under + 2 * std::sqrt(radius2) ? under : std::numeric_limits<double>::quiet_NaN();
}

// False when p is surely above the floor by may_touch()'s rule: higher than the floor under the centre plus
// twice its horizontal distance from it. Spares the floor lookups of a resting hull's upper points.
bool surely_above(const glm::dvec3& p, glm::dvec3 centre, double under) {
  const double rise = p.y - under, dx = p.x - centre.x, dz = p.z - centre.z;
  return std::isfinite(under) && rise > 0 && rise * rise > 4 * (dx * dx + dz * dz);
}

}  // namespace

FloorPush floor_push(std::span<const glm::dvec3> points, const RigidMotion& body, double mass,
                     const FloorHeight& floor, const FloorContactParams& params, double gravity) {
  FloorPush out;
  if (!floor || points.empty()) return out;
  const double floor_under_centre = may_touch(points, body.centre, floor);
  if (std::isnan(floor_under_centre)) return out;
  std::vector<std::pair<glm::dvec3, double>> under;  // point, vertical depth below the floor
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& p : points) {
    if (surely_above(p, body.centre, floor_under_centre)) continue;
    const double depth = floor(p.x, p.z) - p.y;
    if (!(depth > 0) || !std::isfinite(depth)) continue;
    under.push_back({p, depth});
    mean += p;
  }
  if (under.empty()) return out;
  mean /= double(under.size());
  out.normal = floor_normal(floor, mean.x, mean.z);
  const double n = double(under.size());
  const double stiffness = mass * gravity / params.settle_m;
  const double damping = 2 * params.damping_ratio * std::sqrt(stiffness * mass);
  for (const auto& [p, depth] : under) {
    const glm::dvec3 r = p - body.centre;
    const double closing = -glm::dot(body.velocity + glm::cross(body.angular_velocity, r), out.normal);
    // Vertical depth times n.y: the distance to a locally planar floor along its normal.
    const double push = std::max(0.0, (stiffness * depth * out.normal.y + damping * closing) / n);
    out.force += push * out.normal;
    out.torque += glm::cross(r, push * out.normal);
    out.at += push * p;
    out.normal_force += push;
    ++out.points;
  }
  out.at = out.normal_force > 0 ? out.at / out.normal_force : mean;
  return out;
}

glm::dvec3 floor_friction(const FloorPush& push, const RigidMotion& body, double mass,
                          const glm::dmat3& inverse_inertia, glm::dvec3 other_force, glm::dvec3 other_torque,
                          double dt, const FloorContactParams& params) {
  if (push.normal_force <= 0) return glm::dvec3(0.0);
  // The contact's velocity after the step without friction, along the floor.
  const glm::dvec3 r = push.at - body.centre;
  const glm::dvec3 v = body.velocity + dt * other_force / mass;
  const glm::dvec3 w = body.angular_velocity + dt * (inverse_inertia * other_torque);
  glm::dvec3 slip = v + glm::cross(w, r);
  slip -= glm::dot(slip, push.normal) * push.normal;
  const double speed = glm::length(slip);
  if (speed < 1e-12) return glm::dvec3(0.0);
  const glm::dvec3 t = slip / speed;
  // The impulse along −t that stops it: speed / (1/m + (r×t)·I⁻¹(r×t)).
  const glm::dvec3 rt = glm::cross(r, t);
  const double stop = speed / (1.0 / mass + glm::dot(rt, inverse_inertia * rt)) / dt;
  return -std::min(stop, params.friction * push.normal_force) * t;
}

}  // namespace lagoon::physics
