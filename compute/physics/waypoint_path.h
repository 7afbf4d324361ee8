// The path a vehicle follows (vehicles[].path, issue 14): a centripetal Catmull-Rom curve through the
// waypoints (no cusps or self-loops between unevenly spaced points), tabulated by arc length so the vehicle
// moves along it at a constant speed, with a heading that turns smoothly. Plain C++, deterministic.
#pragma once
#include <glm/vec2.hpp>
#include <vector>

namespace lagoon::physics {

// Where a vehicle is on its path at a time: position, heading (radians on the compass, core/compass.h, as
// an object's yaw) and their rates.
struct TrackPoint {
  glm::dvec2 position{0.0};  // (x, z), m
  double heading = 0;        // rad, in [-pi, pi]
  glm::dvec2 velocity{0.0};  // (x, z), m/s
  double yaw_rate = 0;       // rad/s of the heading: clockwise seen from above, so -ω about +y
};

class WaypointPath {
 public:
  // `waypoints` in (x, z); repeated neighbours are merged. A closed path (`loop`) returns from the last
  // point to the first and repeats; an open one ends at the last point, where the vehicle stops.
  WaypointPath(std::vector<glm::dvec2> waypoints, bool loop, double speed_mps, double start_m);

  TrackPoint at(double time_s) const;
  double length() const { return arc_.empty() ? 0.0 : arc_.back(); }

 private:
  // The point and heading at arc length s in [0, length()].
  TrackPoint along(double s) const;

  bool loop_;
  double speed_, start_;
  std::vector<glm::dvec2> samples_;  // the curve, densely sampled
  std::vector<double> arc_;          // arc length at each sample
  std::vector<double> heading_;      // unwrapped heading at each sample
};

}  // namespace lagoon::physics
