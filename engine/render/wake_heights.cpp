#include "render/wake_heights.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "ocean/catmull_rom.h"

namespace lagoon::render {
namespace {

ocean::DynamicLayerParams coarse(ocean::DynamicLayerParams p, uint32_t resolution) {
  p.cell_m *= double(p.n) / double(resolution);  // the same window width
  p.n = resolution;
  return p;
}

}  // namespace

WakeHeights::WakeHeights(VehicleWakes wakes, uint32_t resolution)
    : wakes_(std::move(wakes)), params_(coarse(wakes_.params(), resolution)) {
  if (wakes_.empty()) return;
  const size_t hulls = wakes_.sources(0.0).size();
  views_.push_back({kNoVehicle, {}, {}});
  for (size_t h = 0; h < hulls; ++h) {
    layers_.push_back({wakes_.vehicle_of(h), nullptr, {}});
    views_.push_back({wakes_.vehicle_of(h), {}, {}});
  }
}

void WakeHeights::restart(long long first_step) {
  for (Layer& l : layers_) {
    l.layer = std::make_unique<ocean::DynamicLayerCpu>(params_);
    l.before = l.layer->state();
  }
  first_step_ = first_step;
  steps_done_ = first_step;
}

void WakeHeights::step_all(glm::dvec2 centre) {
  const int half = int(params_.n / 2);
  const glm::ivec2 origin(int(std::floor(centre.x / params_.cell_m)) - half,
                          int(std::floor(centre.y / params_.cell_m)) - half);
  const std::vector<ocean::WakeSource> sources = wakes_.sources(double(steps_done_) * wakes_.step_s());
  for (size_t h = 0; h < layers_.size(); ++h) {
    Layer& l = layers_[h];
    l.before = l.layer->state();
    l.layer->set_window(origin);
    l.layer->step(wakes_.step_s(), std::span(&sources[h], 1));
  }
  ++steps_done_;
}

void WakeHeights::advance(double t, glm::dvec2 centre, long long first_step) {
  if (layers_.empty()) return;
  // The interval [k, k + 1] steps holding t: the layers are brought to step k + 1, the state at k kept.
  const long long k = std::max(wakes_.step_at(t), first_step);
  if (steps_done_ < 0 || first_step != first_step_ || steps_done_ > k + 1) restart(first_step);
  while (steps_done_ < k + 1) step_all(centre);
  const double dt = wakes_.step_s();
  const double s = std::clamp((t - double(k) * dt) / dt, 0.0, 1.0), s2 = s * s, s3 = s2 * s;
  // Cubic Hermite through (h, dh/dt) at both ends, and its derivative.
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = (6 * s2 - 6 * s) / dt, d10 = 3 * s2 - 4 * s + 1, d01 = -d00, d11 = 3 * s2 - 2 * s;
  const int n = int(params_.n);
  origin_ = layers_.front().layer->window();
  for (View& v : views_) {
    v.height.assign(size_t(n) * n, 0.0);
    v.rate.assign(size_t(n) * n, 0.0);
  }
  for (const Layer& l : layers_) {
    const std::vector<std::complex<double>>& after = l.layer->state();
    for (int j = 0; j < n; ++j) {
      const size_t row = size_t(((origin_.y + j) % n + n) % n) * n;
      for (int i = 0; i < n; ++i) {
        const size_t c = row + size_t(((origin_.x + i) % n + n) % n), w = size_t(j) * n + i;
        const std::complex<double> a = l.before[c], b = after[c];
        const double h = h00 * a.real() + h10 * dt * a.imag() + h01 * b.real() + h11 * dt * b.imag();
        const double r = d00 * a.real() + d10 * a.imag() + d01 * b.real() + d11 * b.imag();
        for (View& v : views_)
          if (v.skip != l.vehicle) {
            v.height[w] += h;
            v.rate[w] += r;
          }
      }
    }
  }
  // A lookup weighs 16 cells by Catmull-Rom weights whose magnitudes add up to at most 1.25² (fewer
  // near the window's edge, where the cells outside count as 0).
  for (View& v : views_) {
    double largest = 0;
    for (double h : v.height) largest = std::max(largest, std::abs(h));
    v.highest = 1.5625 * largest;
  }
}

double WakeHeights::highest(size_t skip_vehicle) const {
  return layers_.empty() ? 0.0 : view(skip_vehicle).highest;
}

const WakeHeights::View& WakeHeights::view(size_t skip) const {
  for (const View& v : views_)
    if (v.skip == skip) return v;
  return views_.front();  // a vehicle without a wake skips nothing
}

double WakeHeights::lookup(const std::vector<double>& field, glm::dvec2 p) const {
  if (field.empty()) return 0.0;
  const int n = int(params_.n);
  const glm::dvec2 u = p / params_.cell_m - glm::dvec2(origin_);
  if (!(u.x >= -2 && u.y >= -2 && u.x < n + 1 && u.y < n + 1)) return 0.0;  // no wake outside the window
  const int a = int(std::floor(u.x)), b = int(std::floor(u.y));
  const std::array<double, 4> wa = ocean::catmull_rom_weights(u.x - a),
                              wb = ocean::catmull_rom_weights(u.y - b);
  double sum = 0;
  for (int j = 0; j < 4; ++j) {
    const int cb = b - 1 + j;
    if (cb < 0 || cb >= n) continue;
    for (int i = 0; i < 4; ++i) {
      const int ca = a - 1 + i;
      if (ca >= 0 && ca < n) sum += wa[i] * wb[j] * field[size_t(cb) * n + size_t(ca)];
    }
  }
  return sum;
}

double WakeHeights::height(glm::dvec2 p, size_t skip_vehicle) const {
  return layers_.empty() ? 0.0 : lookup(view(skip_vehicle).height, p);
}

glm::dvec2 WakeHeights::slope(glm::dvec2 p) const {
  const double e = 0.05 * params_.cell_m;
  return glm::dvec2(height(p + glm::dvec2(e, 0)) - height(p - glm::dvec2(e, 0)),
                    height(p + glm::dvec2(0, e)) - height(p - glm::dvec2(0, e))) /
         (2 * e);
}

double WakeHeights::rate(glm::dvec2 p) const {
  return layers_.empty() ? 0.0 : lookup(view(kNoVehicle).rate, p);
}

}  // namespace lagoon::render
