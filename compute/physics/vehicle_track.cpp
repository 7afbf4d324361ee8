#include "physics/vehicle_track.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/compass.h"

namespace lagoon::physics {
namespace {

double wrap(double angle) {
  return std::remainder(angle, 2 * std::numbers::pi);
}

}  // namespace

TrackPoint VehicleTrack::at(double time_s) const {
  const double t = std::max(time_s, 0.0);
  auto after = std::upper_bound(legs_.begin(), legs_.end(), t,
                                [](double time, const Leg& leg) { return time < leg.start_s; });
  if (after == legs_.begin()) return path_.at(t);
  const Leg& leg = *(after - 1);
  const double tau = t - leg.start_s, v = leg.order.speed_mps, w = leg.order.yaw_rate_radps;
  const double h0 = leg.from.heading, h = h0 + w * tau;
  TrackPoint p;
  // The arc of radius v / w: d/dτ of (cos h0 - cos h, sin h0 - sin h) v / w is v (sin h, -cos h), the
  // velocity along compass::toward(h).
  if (std::abs(w * tau) > 1e-9)
    p.position =
        leg.from.position + (v / w) * glm::dvec2(std::cos(h0) - std::cos(h), std::sin(h0) - std::sin(h));
  else
    p.position = leg.from.position + v * tau * compass::toward(h0 + 0.5 * w * tau);
  p.heading = wrap(h);
  p.velocity = v * compass::toward(h);
  p.yaw_rate = w;
  return p;
}

void VehicleTrack::order(double time_s, HelmOrder order) {
  const double t = std::max(time_s, 0.0);
  const TrackPoint from = at(t);  // before the erase: a placement at this very time is where it is
  std::erase_if(legs_, [t](const Leg& leg) { return leg.start_s >= t; });
  legs_.push_back({t, from, order});
}

void VehicleTrack::place(double time_s, TrackPoint where, HelmOrder order) {
  const double t = std::max(time_s, 0.0);
  std::erase_if(legs_, [t](const Leg& leg) { return leg.start_s >= t; });
  where.heading = wrap(where.heading);
  where.velocity = order.speed_mps * compass::toward(where.heading);
  where.yaw_rate = order.yaw_rate_radps;
  legs_.push_back({t, where, order});
}

}  // namespace lagoon::physics
