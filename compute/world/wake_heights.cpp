#include "world/wake_heights.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "ocean/catmull_rom.h"

namespace lagoon::world {
namespace {

ocean::DynamicLayerParams coarse(ocean::DynamicLayerParams p, uint32_t resolution) {
  p.cell_m *= double(p.n) / double(resolution);  // the same window width
  p.n = resolution;
  return p;
}

// One row's four taps weighted along x: lookups sum rows of these along z (separable Catmull-Rom).
double row_sum(const std::array<double, 4>& w, const double* row) {
  return w[0] * row[0] + w[1] * row[1] + w[2] * row[2] + w[3] * row[3];
}

}  // namespace

WakeHeights::WakeHeights(VehicleWakes wakes, uint32_t resolution, std::shared_ptr<BackgroundWorker> worker)
    : wakes_(std::move(wakes)), params_(coarse(wakes_.params(), resolution)), lane_(std::move(worker)) {
  if (wakes_.empty()) return;
  const size_t hulls = wakes_.sources(0.0).size();
  views_.push_back({kNoVehicle, {}, {}});
  for (size_t h = 0; h < hulls; ++h) {
    layers_.push_back({wakes_.vehicle_of(h), nullptr, {}});
    views_.push_back({wakes_.vehicle_of(h), {}, {}});
  }
}

void WakeHeights::restart(long long first_step) {
  for (size_t h = 0; h < next_.size(); ++h)  // a step of the states being replaced: dropped
    if (!next_[h]->begun.take() && next_done_[h].valid()) next_done_[h].get();
  next_.clear();
  next_done_.clear();
  for (Layer& l : layers_) {
    // One thread: the layers step on the background worker (next_), where a second thread of normal
    // priority would take the core the bodies' steps run on.
    l.layer = std::make_unique<ocean::DynamicLayerCpu>(params_, 1);
    l.layer->set_foam(false);  // the bodies feel heights only
    l.previous = nullptr;      // set by the first step
  }
  first_step_ = first_step;
  steps_done_ = first_step;
}

glm::ivec2 WakeHeights::window_for(glm::dvec2 centre) const {
  const int half = int(params_.n / 2);
  return {int(std::floor(centre.x / params_.cell_m)) - half,
          int(std::floor(centre.y / params_.cell_m)) - half};
}

void WakeHeights::run(NextStep& next) const {
  const ocean::DynamicLayerCpu& from = *layers_[next.hull].layer;
  if (next.layer)
    *next.layer = from;
  else
    next.layer = std::make_unique<ocean::DynamicLayerCpu>(from);
  const std::vector<ocean::WakeSource> sources = wakes_.sources(double(next.step) * wakes_.step_s());
  next.layer->set_window(next.origin);
  next.layer->step(wakes_.step_s(), std::span(&sources[next.hull], 1));
}

WakeHeights::Stepped WakeHeights::take_next() {
  Stepped stepped;
  for (size_t h = 0; h < next_.size(); ++h) {
    if (!next_[h]->begun.take())
      next_done_[h].get();  // the worker has it
    else
      run(*next_[h]);  // not begun: the worker runs behind (a catch-up); its job will find it taken
    stepped.push_back(std::move(next_[h]->layer));
  }
  next_.clear();
  next_done_.clear();
  return stepped;
}

void WakeHeights::step_all(glm::dvec2 centre) {
  if (next_.empty()) begin_next(centre, false);  // the first step after a restart: this thread steps it
  Stepped stepped = take_next();
  // Three states per layer turn round, none copied here: the one before the last step is free for the next
  // step to be copied into (copying a stepped state on this thread read it from the worker's core: 1-2 ms).
  spare_.resize(layers_.size());
  for (size_t h = 0; h < layers_.size(); ++h) {
    Layer& l = layers_[h];
    spare_[h] = std::move(l.previous);
    l.previous = std::move(l.layer);
    l.layer = std::move(stepped[h]);
  }
  ++steps_done_;
}

void WakeHeights::begin_next(glm::dvec2 centre, bool on_worker) {
  spare_.resize(layers_.size());
  for (size_t h = 0; h < layers_.size(); ++h) {
    auto next = std::make_shared<NextStep>();
    next->hull = h;
    next->layer = std::move(spare_[h]);
    next->origin = window_for(centre);
    next->step = steps_done_;
    next_.push_back(next);
    // Due when t reaches the end of this interval.
    next_done_.push_back(on_worker ? lane_.submit(
                                         [this, next] {
                                           if (next->begun.take()) run(*next);
                                         },
                                         double(steps_done_) * wakes_.step_s())
                                   : std::future<void>{});
  }
}

void WakeHeights::advance(double t, glm::dvec2 centre, long long first_step) {
  if (layers_.empty()) return;
  // The interval [k, k + 1] steps holding t: the layers are brought to step k + 1, the state at k kept.
  const long long k = std::max(wakes_.step_at(t), first_step);
  if (steps_done_ < 0 || first_step != first_step_ || steps_done_ > k + 1) restart(first_step);
  while (steps_done_ < k + 1) step_all(centre);
  // The next step, on the worker, while the bodies take the steps of this interval.
  if (next_.empty()) begin_next(centre, true);
  const double dt = wakes_.step_s();
  const double s = std::clamp((t - double(k) * dt) / dt, 0.0, 1.0), s2 = s * s, s3 = s2 * s;
  // Cubic Hermite through (h, dh/dt) at both ends, and its derivative.
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = (6 * s2 - 6 * s) / dt, d10 = 3 * s2 - 4 * s + 1, d01 = -d00, d11 = 3 * s2 - 2 * s;
  weights_ = {{h00, h10 * dt, h01, h11 * dt}, {d00, d10, d01, d11}};
  origin_ = layers_.front().layer->window();
  const size_t cells = size_t(params_.n) * params_.n;
  if (++advances_ == 0) {  // the stamps wrapped: every cell is stale
    advances_ = 1;
    for (View& v : views_) v.fresh.assign(cells, 0);
  }
  for (View& v : views_)
    if (v.fresh.size() != cells) {
      v.height.assign(cells, 0.0);
      v.rate.assign(cells, 0.0);
      v.fresh.assign(cells, 0);
    }
}

void WakeHeights::refresh(View& v, size_t w) const {
  const int n = int(params_.n);
  const int i = int(w % size_t(n)), j = int(w / size_t(n));
  const size_t c = size_t(((origin_.y + j) % n + n) % n) * n + size_t(((origin_.x + i) % n + n) % n);
  const Weights& q = weights_;
  double height = 0, rate = 0;
  for (const Layer& l : layers_) {
    if (l.vehicle == v.skip) continue;
    const std::complex<double> a = l.previous->state()[c], b = l.layer->state()[c];
    height += q.h[0] * a.real() + q.h[1] * a.imag() + q.h[2] * b.real() + q.h[3] * b.imag();
    rate += q.r[0] * a.real() + q.r[1] * a.imag() + q.r[2] * b.real() + q.r[3] * b.imag();
  }
  v.height[w] = height;
  v.rate[w] = rate;
  v.fresh[w] = advances_;
}

WakeHeights::View& WakeHeights::view(size_t skip) const {
  for (View& v : views_)
    if (v.skip == skip) return v;
  return views_.front();  // a vehicle without a wake skips nothing
}

double WakeHeights::lookup(View& v, bool rate, glm::dvec2 p) const {
  if (v.fresh.empty()) return 0.0;
  const int n = int(params_.n);
  const glm::dvec2 u = p / params_.cell_m - glm::dvec2(origin_);
  if (!(u.x >= -2 && u.y >= -2 && u.x < n + 1 && u.y < n + 1)) return 0.0;  // no wake outside the window
  const int a = int(std::floor(u.x)), b = int(std::floor(u.y));
  const std::array<double, 4> wa = ocean::catmull_rom_weights(u.x - a),
                              wb = ocean::catmull_rom_weights(u.y - b);
  const std::vector<double>& field = rate ? v.rate : v.height;
  double sum = 0;
  if (a >= 1 && b >= 1 && a + 2 < n && b + 2 < n) {
    // Inside the window (nearly every lookup): no tap is cut. The same terms in the same order as below.
    for (int j = 0; j < 4; ++j) {
      const size_t row = size_t(b - 1 + j) * n + size_t(a - 1);
      for (int i = 0; i < 4; ++i)
        if (v.fresh[row + i] != advances_) refresh(v, row + i);
    }
    return inner_sum(field, wa, wb, a, b);
  }
  for (int j = 0; j < 4; ++j) {
    const int cb = b - 1 + j;
    if (cb < 0 || cb >= n) continue;
    double taps[4] = {0, 0, 0, 0};  // cells outside the window count as 0
    for (int i = 0; i < 4; ++i) {
      const int ca = a - 1 + i;
      if (ca < 0 || ca >= n) continue;
      const size_t w = size_t(cb) * n + size_t(ca);
      if (v.fresh[w] != advances_) refresh(v, w);
      taps[i] = field[w];
    }
    sum += wb[j] * row_sum(wa, taps);
  }
  return sum;
}

double WakeHeights::height(glm::dvec2 p, size_t skip_vehicle) const {
  return layers_.empty() ? 0.0 : lookup(view(skip_vehicle), false, p);
}

double WakeHeights::inner_sum(const std::vector<double>& field, const std::array<double, 4>& wa,
                              const std::array<double, 4>& wb, int a, int b) const {
  const size_t n = params_.n;
  double sum = 0;
  for (int j = 0; j < 4; ++j) sum += wb[j] * row_sum(wa, &field[size_t(b - 1 + j) * n + size_t(a - 1)]);
  return sum;
}

std::pair<glm::ivec2, glm::ivec2> WakeHeights::cells_under(glm::dvec2 lo, glm::dvec2 hi) const {
  const int n = int(params_.n);
  // The taps of a point at u reach cells floor(u) - 1 .. floor(u) + 2 (lookup()); a NaN box none.
  const glm::dvec2 u_lo = lo / params_.cell_m - glm::dvec2(origin_),
                   u_hi = hi / params_.cell_m - glm::dvec2(origin_);
  if (!(u_lo.x <= u_hi.x && u_lo.y <= u_hi.y)) return {glm::ivec2(0), glm::ivec2(-1)};
  const glm::dvec2 first = glm::floor(glm::clamp(u_lo, glm::dvec2(-4.0), glm::dvec2(n + 4))) - 1.0,
                   last = glm::floor(glm::clamp(u_hi, glm::dvec2(-4.0), glm::dvec2(n + 4))) + 2.0;
  return {glm::max(glm::ivec2(first), glm::ivec2(0)), glm::min(glm::ivec2(last), glm::ivec2(n - 1))};
}

void WakeHeights::refresh_cells(View& v, std::pair<glm::ivec2, glm::ivec2> cells) const {
  const size_t n = params_.n;
  for (int b = cells.first.y; b <= cells.second.y; ++b)
    for (int a = cells.first.x; a <= cells.second.x; ++a) {
      const size_t w = size_t(b) * n + size_t(a);
      if (v.fresh[w] != advances_) refresh(v, w);
    }
}

void WakeHeights::add_heights(std::span<const glm::dvec2> points, std::span<double> heights,
                              size_t skip_vehicle) const {
  if (layers_.empty()) return;
  View& v = view(skip_vehicle);
  if (v.fresh.empty() || points.empty()) return;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  refresh_cells(v, cells_under(lo, hi));
  const int n = int(params_.n);
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::dvec2 u = points[i] / params_.cell_m - glm::dvec2(origin_);
    if (!(u.x >= 1 && u.y >= 1 && u.x < n - 2 && u.y < n - 2)) {  // near or past the window's edge
      heights[i] += lookup(v, false, points[i]);
      continue;
    }
    // lookup()'s inner case without its freshness checks: every cell the taps reach was just summed.
    const int a = int(std::floor(u.x)), b = int(std::floor(u.y));
    heights[i] +=
        inner_sum(v.height, ocean::catmull_rom_weights(u.x - a), ocean::catmull_rom_weights(u.y - b), a, b);
  }
}

glm::dvec2 WakeHeights::slope(glm::dvec2 p) const {
  const double e = 0.05 * params_.cell_m;
  return glm::dvec2(height(p + glm::dvec2(e, 0)) - height(p - glm::dvec2(e, 0)),
                    height(p + glm::dvec2(0, e)) - height(p - glm::dvec2(0, e))) /
         (2 * e);
}

double WakeHeights::rate(glm::dvec2 p) const {
  return layers_.empty() ? 0.0 : lookup(view(kNoVehicle), true, p);
}

}  // namespace lagoon::world
