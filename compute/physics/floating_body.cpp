#include "physics/floating_body.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "physics/welded_mesh.h"

namespace lagoon::physics {

FloatingBody::FloatingBody(const TriangleMesh& hull, const MassProperties& mass, Damping damping,
                           WaterProperties water, BodyOptions options)
    : mass_(mass), damping_(damping), water_(water), options_(std::move(options)) {
  TriangleMesh sampled = refine_hull(welded(hull), options_.sampling);
  indices_ = std::move(sampled.indices);
  hull_.reserve(sampled.vertices.size());
  for (const glm::dvec3& v : sampled.vertices) {
    hull_.push_back(v - mass.centre);
    reach_ = std::max(reach_, glm::length(hull_.back()));
  }
  for (size_t t = 0; t + 2 < indices_.size(); t += 3)
    hull_area_ += 0.5 * glm::length(glm::cross(hull_[indices_[t + 1]] - hull_[indices_[t]],
                                               hull_[indices_[t + 2]] - hull_[indices_[t]]));
  inverse_inertia_ = glm::inverse(mass.inertia);
  world_.resize(hull_.size());
  pressure_ = HullPressure(hull_, indices_);
}

void FloatingBody::place(glm::dvec3 origin, glm::dquat orientation) {
  state_ = BodyState{};
  head_steps_ = 0;
  state_.orientation = glm::normalize(orientation);
  state_.position = origin + state_.orientation * mass_.centre;
}

bool FloatingBody::settle_vertically(double level) {
  const glm::dmat3 r = glm::mat3_cast(state_.orientation);
  double lo = 1e30, hi = -1e30;  // the hull's lowest and highest point relative to the centre of mass
  for (const glm::dvec3& v : hull_) lo = std::min(lo, (r * v).y), hi = std::max(hi, (r * v).y);
  const WaterHeight still = [level](double, double) { return level; };
  auto lift = [&](double centre_y) {  // buoyancy minus weight with the centre of mass at centre_y
    for (size_t i = 0; i < hull_.size(); ++i)
      world_[i] = glm::dvec3(state_.position.x, centre_y, state_.position.z) + r * hull_[i];
    return hydrostatic_wrench(world_, indices_, still, state_.position, water_.density, water_.gravity)
               .force.y -
           mass_.mass * water_.gravity;
  };
  double deep = level - hi, high = level - lo;  // fully under, fully out
  if (lift(deep) < 0) return false;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (deep + high);
    (lift(mid) > 0 ? deep : high) = mid;
  }
  state_.position.y = 0.5 * (deep + high);
  return true;
}

glm::dvec3 FloatingBody::model_origin() const {
  return state_.position - state_.orientation * mass_.centre;
}

std::vector<glm::dvec3> FloatingBody::sample_points_in_world() const {
  std::vector<glm::dvec3> out;
  out.reserve(hull_.size());
  for (const glm::dvec3& p : hull_) out.push_back(state_.position + state_.orientation * p);
  return out;
}

double FloatingBody::kinetic_energy() const {
  const glm::dmat3 r = glm::mat3_cast(state_.orientation);
  const glm::dvec3 w = state_.angular_velocity;
  return 0.5 * mass_.mass * glm::dot(state_.velocity, state_.velocity) +
         0.5 * glm::dot(w, r * mass_.inertia * glm::transpose(r) * w);
}

void FloatingBody::step(double dt, const WaterHeight& water, double water_top, const PressureHead& head,
                        const WaterHeights& heights) {
  const glm::dmat3 r = glm::mat3_cast(state_.orientation);
  for (size_t i = 0; i < hull_.size(); ++i) world_[i] = state_.position + r * hull_[i];
  wrench_ = pressure_.wrench(world_, r, state_.position,
                             {.height = &water,
                              .heights = heights ? &heights : nullptr,
                              .head = head ? &head : nullptr,
                              .top = water_top},
                             water_.density, water_.gravity);
  const double wet = hull_area_ > 0 ? std::min(wrench_.wetted_area / hull_area_, 1.0) : 0.0;

  const glm::dvec3 v = state_.velocity, w = state_.angular_velocity;
  const glm::dmat3 inertia = r * mass_.inertia * glm::transpose(r);
  glm::dvec3 force = wrench_.force + glm::dvec3(0.0, -water_.gravity * mass_.mass, 0.0);
  force -= wet * (damping_.linear + damping_.quadratic * glm::length(v)) * mass_.mass * v;
  glm::dvec3 torque = wrench_.torque;
  torque -= wet * (damping_.angular + damping_.angular_quadratic * glm::length(w)) * (inertia * w);
  torque -= glm::cross(w, inertia * w);  // gyroscopic
  const glm::dmat3 inverse_inertia = r * inverse_inertia_ * glm::transpose(r);
  const double added_mass = add_heave_radiation(dt, water, head, force);
  add_floor(dt, inverse_inertia, force, torque);

  // Semi-implicit Euler: velocities first, then positions with the new velocities. The water's added mass
  // slows the heave only.
  glm::dvec3 dv = dt * force / mass_.mass;
  dv.y = dt * force.y / (mass_.mass + added_mass);
  state_.velocity += dv;
  state_.angular_velocity += dt * (inverse_inertia * torque);
  state_.position += dt * state_.velocity;
  const glm::dvec3 wn = state_.angular_velocity;
  state_.orientation =
      glm::normalize(state_.orientation + 0.5 * dt * glm::dquat(0.0, wn.x, wn.y, wn.z) * state_.orientation);
}

double FloatingBody::add_heave_radiation(double dt, const WaterHeight& water, const PressureHead& head,
                                         glm::dvec3& force) {
  if (!options_.radiation.enabled) return 0.0;
  const double displaced = std::max(wrench_.force.y, 0.0) / (water_.density * water_.gravity);
  const HeaveTerms terms = heave_terms(options_.radiation, displaced, water_.density, water_.gravity);
  // The water's vertical motion where the hull displaces it: the pressure head at the centre of buoyancy's
  // depth, differenced over steps (linear theory: ∂H/∂t is the vertical velocity there). Without a head,
  // the surface's.
  const double level = water(state_.position.x, state_.position.z);
  const double at = level - terms.buoyancy_depth_m;
  const double sample = head ? head(state_.position.x, at, state_.position.z) : level;
  const double rise = head_steps_ > 0 ? (sample - last_head_) / dt : 0.0;
  const double lift = head_steps_ > 1 ? (rise - last_rise_) / dt : 0.0;
  last_head_ = sample, last_rise_ = rise;
  head_steps_ = std::min(head_steps_ + 1, 2);
  // Radiation and diffraction together, in relative motion: the body feels the added mass and damping
  // against its motion relative to the water's (the long-wave approximation of the diffraction force).
  force.y += terms.damping_n_s_per_m * (rise - state_.velocity.y) + terms.added_mass_kg * lift;
  return terms.added_mass_kg;
}

void FloatingBody::add_floor(double dt, const glm::dmat3& inverse_inertia, glm::dvec3& force,
                             glm::dvec3& torque) {
  floor_push_ = {};
  if (!options_.floor) return;
  const RigidMotion motion{state_.position, state_.velocity, state_.angular_velocity};
  floor_push_ = floor_push(world_, motion, mass_.mass, options_.floor, options_.contact, water_.gravity);
  if (floor_push_.points == 0) return;
  force += floor_push_.force;
  torque += floor_push_.torque;
  // Friction last: it holds the body against everything else the step applies.
  const glm::dvec3 friction =
      floor_friction(floor_push_, motion, mass_.mass, inverse_inertia, force, torque, dt, options_.contact);
  force += friction;
  torque += glm::cross(floor_push_.at - state_.position, friction);
}

}  // namespace lagoon::physics
