#include "ocean/springs.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "core/compass.h"

namespace lagoon::ocean {
namespace {

using sp_real = double;
using sp_real2 = glm::dvec2;
using glm::dot;
using std::cos;
using std::exp;
using std::floor;
using std::sin;
using std::sqrt;
glm::dvec2 floor(glm::dvec2 v) {
  return glm::floor(v);
}
#define LAGOON_FN inline
#include "shared/springs_math.h"
#undef LAGOON_FN

// The Gaussian's weight averaged over the grid's nodes. The weight is a product of one per axis (the nearest
// image is taken per axis), so the sum is too; the same for every centre, up to the nodes' spacing.
double mean_patch_weight(glm::dvec2 centre, double sigma, uint32_t n, double spacing) {
  const double period = n * spacing;
  double sum[2] = {0, 0};
  for (uint32_t i = 0; i < n; ++i)
    for (int axis = 0; axis < 2; ++axis) {
      glm::dvec2 node(0);
      node[axis] = i * spacing;
      glm::dvec2 at = centre;
      at[1 - axis] = 0;
      sum[axis] += sp_patch_weight(node, at, sigma, period);
    }
  return sum[0] * sum[1] / (double(n) * n);
}

}  // namespace

double springs_stability_limit_s(const SpringsParams& p) {
  return 2.0 / std::sqrt(8.0 * p.stiffness_n_per_m / p.mass_kg);
}

double springs_omega(const SpringsParams& p, double spacing_m, double kx, double kz) {
  const double sx = std::sin(kx * spacing_m / 2), sz = std::sin(kz * spacing_m / 2);
  const double omega =
      std::sqrt(4 * p.stiffness_n_per_m * (1 - p.rest_length) / p.mass_kg * (sx * sx + sz * sz));
  return 2 / p.step_s * std::asin(std::min(1.0, p.step_s * omega / 2));
}

uint64_t springs_steps_for(const SpringsParams& p, double time_s) {
  return uint64_t(std::floor(std::max(time_s, 0.0) / p.step_s)) + 1;
}

std::vector<gpu::SpringExcitation> springs_excitations(const OceanParams& params) {
  const SpringsParams& p = params.springs;
  const uint32_t n = params.cascades.front().resolution;
  const double spacing = params.cascades.front().patch_size_m / n;
  std::vector<gpu::SpringExcitation> out;
  auto step_of = [&](double t) { return uint32_t(std::floor(std::max(t, 0.0) / p.step_s)); };
  // A drop gives its speed within one step: the acceleration speed / Δt, downward.
  for (const SpringDrop& d : p.drops)
    out.push_back({.centre = glm::vec2(d.x_m, d.z_m),
                   .velocity = glm::vec2(0),
                   .sigma = float(d.radius_m),
                   .accel = float(-d.speed_mps / p.step_s),
                   .start_s = float(d.time_s),
                   .first_step = step_of(d.time_s),
                   .end_step = step_of(d.time_s) + 1,
                   .mean_weight = float(mean_patch_weight({d.x_m, d.z_m}, d.radius_m, n, spacing))});
  for (const SpringGust& g : p.gusts) {
    const glm::dvec2 heading = compass::toward_deg(g.direction_deg);
    const uint32_t first = step_of(g.time_s);
    out.push_back({.centre = glm::vec2(g.x_m, g.z_m),
                   .velocity = glm::vec2(g.speed_mps * heading),
                   .sigma = float(g.radius_m),
                   .accel = float(-g.force_n / p.mass_kg),
                   .start_s = float(g.time_s),
                   .first_step = first,
                   .end_step = std::max(first + 1, step_of(g.time_s + g.duration_s)),
                   .mean_weight = float(mean_patch_weight({g.x_m, g.z_m}, g.radius_m, n, spacing))});
  }
  return out;
}

SpringGrid::SpringGrid(const OceanParams& params)
    : p_(params.springs),
      n_(params.cascades.front().resolution),
      spacing_(params.cascades.front().patch_size_m / params.cascades.front().resolution),
      excitations_(springs_excitations(params)) {
  reset();
}

void SpringGrid::reset() {
  state_.assign(size_t{n_} * n_, glm::dvec2(0));
  next_ = state_;
  steps_ = 0;
}

void SpringGrid::step() {
  const int n = int(n_);
  const double t = double(steps_) * p_.step_s, period = n * spacing_;
  const double rest = p_.rest_length * spacing_;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 here = state_[size_t(j) * n + i];
      auto height = [&](int a, int b) { return state_[size_t((b + n) % n) * n + size_t((a + n) % n)].x; };
      double springs = 0;
      for (double neighbour : {height(i - 1, j), height(i + 1, j), height(i, j - 1), height(i, j + 1)})
        springs += sp_spring_force(neighbour - here.x, p_.stiffness_n_per_m, rest, spacing_);
      double pushed = 0;
      const glm::dvec2 node(i * spacing_, j * spacing_);
      for (const gpu::SpringExcitation& e : excitations_) {
        if (steps_ < e.first_step || steps_ >= e.end_step) continue;
        const glm::dvec2 centre = glm::dvec2(e.centre) + glm::dvec2(e.velocity) * (t - double(e.start_s));
        pushed += double(e.accel) *
                  (sp_patch_weight(node, centre, double(e.sigma), period) - double(e.mean_weight));
      }
      glm::dvec2 next = sp_node_step(here, springs, pushed, p_.mass_kg, p_.damping_kg_per_s, p_.step_s);
      if (i == 0 && p_.boundary_amplitude_m > 0) {  // the driven column, held to its motion
        const double omega = 2 * std::numbers::pi / p_.boundary_period_s, later = t + p_.step_s;
        next = {p_.boundary_amplitude_m * std::sin(omega * later),
                p_.boundary_amplitude_m * omega * std::cos(omega * later)};
      }
      next_[size_t(j) * n + i] = next;
    }
  std::swap(state_, next_);
  ++steps_;
}

void SpringGrid::advance_to(uint64_t steps) {
  if (steps < steps_) reset();
  if (steps - steps_ > kSpringsMaxCatchUpSteps)
    throw std::out_of_range("model springs: " + std::to_string(steps - steps_) +
                            " steps to take at once, more than " + std::to_string(kSpringsMaxCatchUpSteps) +
                            "; ask for an earlier time");
  while (steps_ < steps) step();
}

std::vector<glm::dvec2> SpringGrid::surface_at(double time_s) {
  time_s = std::max(time_s, 0.0);  // the grid rests before t = 0 (x_1 - v_1 Δt = x_0 = 0)
  advance_to(springs_steps_for(p_, time_s));
  const double behind = double(steps_) * p_.step_s - time_s;
  std::vector<glm::dvec2> out(state_.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = {state_[i].x - state_[i].y * behind, state_[i].y};
  return out;
}

double SpringGrid::energy() const {
  const size_t n = n_;
  double kinetic = 0, potential = 0;
  for (size_t j = 0; j < n; ++j)
    for (size_t i = 0; i < n; ++i) {
      const double y = state_[j * n + i].x;
      kinetic += 0.5 * p_.mass_kg * state_[j * n + i].y * state_[j * n + i].y;
      const double right = state_[j * n + (i + 1) % n].x, up = state_[((j + 1) % n) * n + i].x;
      potential += 0.5 * p_.stiffness_n_per_m * ((right - y) * (right - y) + (up - y) * (up - y));
    }
  return kinetic + potential;
}

}  // namespace lagoon::ocean
