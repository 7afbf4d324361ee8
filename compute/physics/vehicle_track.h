// Where a vehicle is at any time (issue 14): on its path (physics/waypoint_path.h), or, once someone has
// taken the helm (the demo's keyboard), on the legs they ordered. Each leg holds a speed and a rate of turn
// from its start, so the vehicle runs a circular arc (or a straight line) in closed form: any time is
// answered without stepping, and the same history gives the same answer. Orders only change the track from
// their time on, so everything that follows a vehicle (its body, its wake, the sediment it stirs) agrees
// about its past.
#pragma once
#include <vector>

#include "physics/waypoint_path.h"

namespace lagoon::physics {

struct HelmOrder {
  double speed_mps = 0;  // along the heading
  double yaw_rate_radps =
      0;  // of the compass heading: positive turns clockwise seen from above, to starboard
};

class VehicleTrack {
 public:
  explicit VehicleTrack(WaypointPath path) : path_(std::move(path)) {}

  TrackPoint at(double time_s) const;
  // From time t (>= 0) on, the vehicle runs at the order's speed and rate of turn from where it is then;
  // orders given for later times before are dropped (a replay from an earlier time).
  void order(double time_s, HelmOrder order);
  // From time t (>= 0) on, the vehicle runs from `where` (its position and heading; the velocity and rate
  // of turn come from `order`) instead of from where it was: an external controller's pose. Orders given
  // for later times before are dropped, as order() drops them.
  void place(double time_s, TrackPoint where, HelmOrder order);
  bool steered() const { return !legs_.empty(); }
  size_t legs() const { return legs_.size(); }
  const WaypointPath& path() const { return path_; }

 private:
  struct Leg {
    double start_s;
    TrackPoint from;
    HelmOrder order;
  };
  WaypointPath path_;
  std::vector<Leg> legs_;  // by start time
};

}  // namespace lagoon::physics
