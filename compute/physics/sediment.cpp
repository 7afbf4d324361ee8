#include "physics/sediment.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "shared/sediment.h"

namespace lagoon::physics {
namespace sed_double {
using sed_real = double;
using sed_real2 = glm::dvec2;
using sed_real3 = glm::dvec3;
using glm::dot;
using std::abs;
using std::exp;
using std::max;
using std::min;
using std::sqrt;
#define LAGOON_FN inline
#include "shared/sediment_math.h"
#undef LAGOON_FN
}  // namespace sed_double

namespace {

// Release times are multiples of a float interval from the scene (1.1f is 1.10000002): a step meant to be
// whole counts as whole.
constexpr double kStepSlack = 1e-6;
// A cloud with less of its mass suspended than this is settled and no longer listed.
constexpr double kSettledShare = 1e-4;

double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

}  // namespace

SedimentCloud::SedimentCloud(SedimentParams params, FloorDepth floor, std::vector<StirrerBottom> stirrers)
    : params_(params), floor_(std::move(floor)), stirrers_(std::move(stirrers)) {}

double SedimentCloud::release_rate(double altitude_m) const {
  const double h = params_.release_height_m;
  if (h <= 0 || altitude_m >= h) return 0;
  return params_.release_g_per_s * (1.0 - std::max(altitude_m, 0.0) / h);
}

double SedimentCloud::release_at(size_t stirrer, long long step, glm::dvec2* where) const {
  const glm::dvec3 bottom = stirrers_[stirrer](double(step) * params_.interval_s);
  *where = {bottom.x, bottom.z};
  const double depth = floor_(*where);
  if (!(depth > 0)) return 0;  // dry land or no floor: nothing to stir
  return release_rate(depth + bottom.y) * params_.interval_s;
}

SedimentPuff SedimentCloud::puff(glm::dvec2 origin, double mass_g, double age_s) const {
  const glm::dvec2 drift = origin + params_.current_mps * age_s;
  SedimentPuff p;
  // The burst: 0 at release, 1 once the wash has thrown the cloud up and out.
  const double burst = params_.burst_s > 0 ? 1 - std::exp(-age_s / params_.burst_s) : 1.0;
  const double size = params_.radius_m * (0.2 + 0.8 * burst);
  p.centre = {drift.x, -floor_(origin) + params_.rise_m * burst - params_.settling_mps * age_s, drift.y};
  p.sigma = std::sqrt(size * size + 2.0 * params_.diffusivity_m2_s * age_s);
  p.mass_g = mass_g;
  p.age_s = age_s;
  // Above the floor under its centre: the floor taken as level across the cloud.
  p.suspended_g = mass_g * normal_cdf((p.centre.y + floor_(drift)) / p.sigma);
  return p;
}

std::vector<SedimentPuff> SedimentCloud::puffs(double time_s) const {
  std::vector<SedimentPuff> out;
  if (params_.interval_s <= 0 || time_s < 0) return out;
  const long long last = (long long)std::floor(time_s / params_.interval_s + kStepSlack);
  const long long first =
      std::max(1LL, (long long)std::ceil((time_s - params_.max_age_s) / params_.interval_s - kStepSlack));
  for (size_t s = 0; s < stirrers_.size(); ++s)
    for (long long k = first; k <= last; ++k) {
      glm::dvec2 origin;
      const double mass = release_at(s, k, &origin);
      if (mass <= 0) continue;
      SedimentPuff p = puff(origin, mass, std::max(time_s - double(k) * params_.interval_s, 0.0));
      p.release = uint32_t((uint64_t(k) * 1000003u + s) * 2654435761u);
      if (p.suspended_g > kSettledShare * mass) out.push_back(p);
    }
  return out;
}

double SedimentCloud::released_g(double time_s) const {
  if (params_.interval_s <= 0 || time_s < 0) return 0;
  const long long last = (long long)std::floor(time_s / params_.interval_s + kStepSlack);
  double sum = 0;
  for (size_t s = 0; s < stirrers_.size(); ++s)
    for (long long k = 1; k <= last; ++k) {
      glm::dvec2 origin;
      sum += release_at(s, k, &origin);
    }
  return sum;
}

double SedimentCloud::suspended_g(double time_s) const {
  double sum = 0;
  for (const SedimentPuff& p : puffs(time_s)) sum += p.suspended_g;
  return sum;
}

double sediment_concentration(std::span<const SedimentPuff> puffs, const FloorDepth& floor, glm::dvec3 p) {
  if (p.y < -floor({p.x, p.z})) return 0;
  double c = 0;
  for (const SedimentPuff& q : puffs) {
    const glm::dvec3 d = p - q.centre;
    const double s2 = q.sigma * q.sigma;
    c += q.mass_g * std::exp(-0.5 * glm::dot(d, d) / s2) / std::pow(2.0 * M_PI * s2, 1.5);
  }
  return c;
}

glm::dvec2 sediment_ray(std::span<const SedimentPuff> puffs, double attenuation_m2_per_g, glm::dvec3 origin,
                        glm::dvec3 dir, double length_m) {
  glm::dvec2 sum(0.0);
  for (const SedimentPuff& q : puffs)
    sum += sed_double::sed_ray(origin, dir, length_m, q.centre, q.sigma, q.mass_g * attenuation_m2_per_g);
  return sum;
}

SedimentBox sediment_reach(std::span<const SedimentPuff> puffs) {
  SedimentBox box;
  for (const SedimentPuff& q : puffs) {
    const glm::dvec3 reach(std::sqrt(LAGOON_SEDIMENT_REACH2_SIGMA2) * q.sigma);
    box.lo = glm::min(box.lo, q.centre - reach);
    box.hi = glm::max(box.hi, q.centre + reach);
  }
  return box;
}

bool segment_meets(const SedimentBox& box, glm::dvec3 origin, glm::dvec3 dir, double length_m) {
  return sed_double::sed_segment_meets_box(origin, dir, length_m, box.lo, box.hi);
}

}  // namespace lagoon::physics
