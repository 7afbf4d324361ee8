// The wakes under the hulls (issue 14, docs/physics.md "Wakes under the hulls"): the dynamic wave layer on
// the CPU (ocean/dynamic_layer.h), stepped with the bodies, so a buoy rocks when a boat passes and a probe's
// heights include the wakes. The picture's layer follows the camera; this one follows the bodies, over the
// same window width with coarser cells (wakes.physics_resolution), so it holds the same waves without the
// shortest ones, which a hull of several metres averages out anyway.
//
// One layer per wake-making vehicle: the layer is linear, so the sea's wakes are the sum of the layers, and a
// vehicle's hull can be given every wake but its own (its own depression is the water it displaces, which its
// buoyancy already counts). Between the layer's steps the heights are Hermite-interpolated from the height
// and its rate at both ends, so the forces on a body do not jump at every step. Each step of the layers is
// computed on another thread during the interval before it is needed (see next_).
#pragma once
#include <array>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <future>
#include <glm/vec2.hpp>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "core/background_worker.h"
#include "ocean/dynamic_layer.h"
#include "world/vehicle_wakes.h"

namespace lagoon::world {

class WakeHeights {
 public:
  static constexpr size_t kNoVehicle = std::numeric_limits<size_t>::max();

  // Empty (no layers) when `wakes` is; `resolution` cells per side over the wakes' window width.
  // `worker`: the thread the layers step on ahead of time, shared with the caller's other helpers (null: one
  // of its own).
  WakeHeights(VehicleWakes wakes, uint32_t resolution, std::shared_ptr<BackgroundWorker> worker = nullptr);
  WakeHeights(const WakeHeights&) = delete;  // its next step's thread holds `this`
  WakeHeights& operator=(const WakeHeights&) = delete;

  bool empty() const { return layers_.empty(); }
  // Brings the layers to time t, their window centred on `centre` (world x, z). The layers step from
  // `first_step` (the state at rest then); an earlier time than the last runs them again from there.
  void advance(double t, glm::dvec2 centre, long long first_step = 0);

  // At the last advance's time: the wakes' height at (x, z), leaving out vehicles[skip_vehicle]'s own; its
  // slopes (dh/dx, dh/dz) and its rate dh/dt. Zero outside the window.
  double height(glm::dvec2 p, size_t skip_vehicle = kNoVehicle) const;
  // Adds height(points[i], skip_vehicle) to heights[i]: a hull's points in one call, the cells they share
  // summed once.
  void add_heights(std::span<const glm::dvec2> points, std::span<double> heights,
                   size_t skip_vehicle = kNoVehicle) const;
  glm::dvec2 slope(glm::dvec2 p) const;
  double rate(glm::dvec2 p) const;

  const ocean::DynamicLayerParams& params() const { return params_; }
  long long steps_done() const { return steps_done_; }

 private:
  struct Layer {
    size_t vehicle;
    std::unique_ptr<ocean::DynamicLayerCpu> layer;
    std::unique_ptr<ocean::DynamicLayerCpu> previous;  // the layer at step steps_done_ - 1
  };
  // The cubic Hermite weights of the last advance's time within its interval: h00, h10·dt, h01, h11·dt for
  // the height and their time derivatives for the rate.
  struct Weights {
    double h[4] = {0, 0, 0, 0}, r[4] = {0, 0, 0, 0};
  };
  // The sum of the layers but vehicles[skip]'s at the last advance's time, in window order (cell (i, j) of
  // the window at i + n j). Cells are summed when a lookup first needs them after an advance (`fresh` holds
  // the advance they were summed at): the bodies ask for thousands of points a step, all near the hulls,
  // and summing the whole window at every 120 Hz step cost more than the lookups.
  struct View {
    size_t skip;
    std::vector<double> height, rate;
    std::vector<uint32_t> fresh;
  };
  using Stepped = std::vector<std::unique_ptr<ocean::DynamicLayerCpu>>;
  void restart(long long first_step);
  glm::ivec2 window_for(glm::dvec2 centre) const;
  // One layer's next step: a spare, copied over from the layer (copy-assigned, so no allocation once it has
  // the size) and stepped by whoever begins it: the worker, or this thread in a catch-up that overtook it.
  // One per layer, so that no piece of the helpers' work is longer than a layer's step (~1 ms).
  struct NextStep {
    Claim begun;  // the worker's job or this thread, whichever begins first (core/background_worker.h)
    size_t hull = 0;
    std::unique_ptr<ocean::DynamicLayerCpu> layer;  // the spare, then the step's result
    glm::ivec2 origin{0};
    long long step = 0;
  };
  // Reads nothing of this but layers_[next.hull] (which this thread only reads until it takes the result),
  // wakes_ and params_, so it may run on another thread.
  void run(NextStep& next) const;
  // next_ for the step from steps_done_, handed to the worker or (on_worker false) left for take_next().
  void begin_next(glm::dvec2 centre, bool on_worker);
  // next_'s layers, stepped: by the worker, or here for what it has not begun.
  Stepped take_next();
  void step_all(glm::dvec2 centre);
  View& view(size_t skip) const;
  // Sums cell `w` (window order) of `v` at the last advance's time.
  void refresh(View& v, size_t w) const;
  double lookup(View& v, bool rate, glm::dvec2 p) const;
  // The Catmull-Rom sum over cells (a - 1 .. a + 2, b - 1 .. b + 2) of `field`, all inside the window and
  // fresh: lookup()'s and add_heights()' one arithmetic, so both give the same sum to the bit.
  double inner_sum(const std::vector<double>& field, const std::array<double, 4>& wa,
                   const std::array<double, 4>& wb, int a, int b) const;
  // The cells (first and last, inclusive, in window coordinates) that Catmull-Rom taps of points in the box
  // [lo, hi] reach; none (first > last) when it is empty or outside the window.
  std::pair<glm::ivec2, glm::ivec2> cells_under(glm::dvec2 lo, glm::dvec2 hi) const;
  // Sums the stale cells of `v` in cells_under().
  void refresh_cells(View& v, std::pair<glm::ivec2, glm::ivec2> cells) const;

  VehicleWakes wakes_;
  ocean::DynamicLayerParams params_;
  std::vector<Layer> layers_;
  mutable std::vector<View> views_;  // skipping none, then each layer's vehicle (summed lazily)
  Weights weights_;
  uint32_t advances_ = 0;      // stamps View::fresh
  glm::ivec2 origin_{0};       // the window's first cell
  long long steps_done_ = -1;  // the layers' state is at this step (the step before is in Layer::previous)
  long long first_step_ = 0;
  // The layers' next step, begun on another thread when an advance has brought them to steps_done_, with
  // the window where the bodies were then: the FFTs of a step run while the bodies take the 120 Hz steps
  // before it, instead of on one of them. The window thus trails the bodies by one step of the layer.
  std::vector<std::shared_ptr<NextStep>> next_;  // per layer; empty when none is begun ahead
  std::vector<std::future<void>> next_done_;     // the worker's jobs for next_
  // The layers two steps old, kept for the next step to copy into: a fresh copy each step was allocated,
  // faulted in and freed on the stepping thread, 3-7 ms every 0.1 s (issue 35's worst frame).
  Stepped spare_;
  // Runs next_, on the worker given (shared with the bodies' sea) or its own. Last: its jobs read the rest,
  // so it waits for them before the rest goes.
  WorkerLane lane_;
};

}  // namespace lagoon::world
