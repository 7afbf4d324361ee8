#include "physics/waypoint_path.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/compass.h"

namespace lagoon::physics {
namespace {

// Samples per metre of a segment, and their bounds per segment: dense enough that the chord polyline is
// within millimetres of the curve for turns of metres' radius.
constexpr double kSamplesPerMetre = 4.0;
constexpr int kMinSamples = 16, kMaxSamples = 4096;

// Centripetal Catmull-Rom (Barry-Goldman pyramid, knot spacing |Δp|^0.5) between p1 and p2 at u in [0, 1].
glm::dvec2 centripetal(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 p3, double u) {
  const auto knot = [](glm::dvec2 a, glm::dvec2 b) { return std::max(std::sqrt(glm::distance(a, b)), 1e-9); };
  const double t0 = 0, t1 = t0 + knot(p0, p1), t2 = t1 + knot(p1, p2), t3 = t2 + knot(p2, p3);
  const double t = t1 + u * (t2 - t1);
  const glm::dvec2 a1 = ((t1 - t) * p0 + (t - t0) * p1) / (t1 - t0);
  const glm::dvec2 a2 = ((t2 - t) * p1 + (t - t1) * p2) / (t2 - t1);
  const glm::dvec2 a3 = ((t3 - t) * p2 + (t - t2) * p3) / (t3 - t2);
  const glm::dvec2 b1 = ((t2 - t) * a1 + (t - t0) * a2) / (t2 - t0);
  const glm::dvec2 b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
  return ((t2 - t) * b1 + (t - t1) * b2) / (t2 - t1);
}

}  // namespace

WaypointPath::WaypointPath(std::vector<glm::dvec2> waypoints, bool loop, double speed_mps, double start_m)
    : loop_(loop), speed_(speed_mps), start_(start_m) {
  std::vector<glm::dvec2> p;
  for (const glm::dvec2& w : waypoints)
    if (p.empty() || glm::distance(p.back(), w) > 1e-6) p.push_back(w);
  if (loop && p.size() > 2 && glm::distance(p.front(), p.back()) <= 1e-6) p.pop_back();
  if (p.size() < 2) {  // one place: the vehicle stays there
    samples_ = {p.empty() ? glm::dvec2(0.0) : p.front()};
    arc_ = {0.0};
    heading_ = {0.0};
    return;
  }
  const int n = int(p.size());
  const int segments = loop ? n : n - 1;
  // Beyond an open path's ends the curve continues straight, so it starts and ends along its first and
  // last legs.
  const auto point = [&](int i) {
    if (loop) return p[size_t(((i % n) + n) % n)];
    if (i < 0) return 2.0 * p[0] - p[1];
    if (i >= n) return 2.0 * p[size_t(n - 1)] - p[size_t(n - 2)];
    return p[size_t(i)];
  };
  samples_.push_back(p[0]);
  for (int s = 0; s < segments; ++s) {
    const double chord = glm::distance(point(s), point(s + 1));
    const int count = std::clamp(int(std::ceil(chord * kSamplesPerMetre)), kMinSamples, kMaxSamples);
    for (int k = 1; k <= count; ++k)
      samples_.push_back(centripetal(point(s - 1), point(s), point(s + 1), point(s + 2), double(k) / count));
  }
  arc_.assign(samples_.size(), 0.0);
  for (size_t i = 1; i < samples_.size(); ++i)
    arc_[i] = arc_[i - 1] + glm::distance(samples_[i - 1], samples_[i]);
  // Heading at each sample from its neighbours (central difference), unwrapped so it can be interpolated.
  const size_t m = samples_.size();
  heading_.resize(m);
  for (size_t i = 0; i < m; ++i) {
    glm::dvec2 d;
    if (loop) {  // the first and last samples are the same point
      const size_t prev = i == 0 ? m - 2 : i - 1, next = i == m - 1 ? 1 : i + 1;
      d = samples_[next] - samples_[prev];
    } else {
      d = samples_[std::min(i + 1, m - 1)] - samples_[i == 0 ? 0 : i - 1];
    }
    heading_[i] = compass::azimuth_of(d);
    if (i > 0) {
      const double step = heading_[i] - heading_[i - 1];
      heading_[i] -= 2 * std::numbers::pi * std::round(step / (2 * std::numbers::pi));
    }
  }
}

TrackPoint WaypointPath::along(double s) const {
  TrackPoint out;
  if (samples_.size() == 1) {
    out.position = samples_[0];
    return out;
  }
  const size_t i = std::clamp<size_t>(size_t(std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin()), 1,
                                      arc_.size() - 1);
  const double span = arc_[i] - arc_[i - 1];
  const double f = span > 0 ? std::clamp((s - arc_[i - 1]) / span, 0.0, 1.0) : 0.0;
  out.position = glm::mix(samples_[i - 1], samples_[i], f);
  const double heading = heading_[i - 1] + f * (heading_[i] - heading_[i - 1]);
  out.heading = heading - 2 * std::numbers::pi * std::round(heading / (2 * std::numbers::pi));
  const double turn = span > 0 ? (heading_[i] - heading_[i - 1]) / span : 0.0;  // rad per metre
  out.velocity = speed_ * compass::toward(heading);
  out.yaw_rate = speed_ * turn;
  return out;
}

TrackPoint WaypointPath::at(double time_s) const {
  const double length = this->length();
  double s = start_ + speed_ * std::max(time_s, 0.0);
  if (loop_ && length > 0) {
    s = std::fmod(s, length);
  } else if (s >= length) {  // an open path's end: stopped, facing along the last leg
    TrackPoint end = along(length);
    end.velocity = glm::dvec2(0.0);
    end.yaw_rate = 0;
    return end;
  }
  return along(s);
}

}  // namespace lagoon::physics
