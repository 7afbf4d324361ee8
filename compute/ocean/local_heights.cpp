#include "ocean/local_heights.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/common.hpp>

#include "ocean/catmull_rom.h"

namespace lagoon::ocean {

LocalHeights::LocalHeights(const OceanParams& params, std::vector<CascadeSpectrum> spectra,
                           LocalHeightsOptions options)
    : LocalHeights(std::make_shared<WaveQuery>(params, std::move(spectra)), options) {}

LocalHeights::LocalHeights(std::shared_ptr<WaveQuery> query, LocalHeightsOptions options)
    : query_(std::move(query)), options_(options) {
  now_.assign(size_t(options_.points_per_side) * options_.points_per_side, 0.0);
}

void LocalHeights::recentre(glm::dvec2 centre) {
  const double s = options_.spacing_m, half = 0.5 * (options_.points_per_side - 1) * s;
  const glm::dvec2 origin = glm::floor((centre - half) / s) * s;
  // The knot ahead moves with the others when it is done; else it is dropped and asked again.
  if (ahead_.heights.valid() && ahead_.heights.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    if (std::vector<double> heights = ahead_.heights.get(); !heights.empty())
      knots_.emplace_back(ahead_index_, std::move(heights));
  ahead_ = {};
  ahead_index_ = std::numeric_limits<long long>::min();
  if (!placed_) {
    origin_ = origin;
    placed_ = true;
    return;
  }
  // The lattice moves by whole points (its origin is a multiple of the spacing): the knots keep the heights
  // of the points both lattices hold and sample only the rest, a strip of about a quarter of it for a body
  // that moved out of the inner half (a boat under way recentres every few seconds, and sampling four whole
  // knots at once stalled its step for ~2 ms). The same heights as sampled whole: each point's sample
  // depends on its position alone.
  const int n = options_.points_per_side;
  const glm::ivec2 shift(glm::round((origin - origin_) / s));
  origin_ = origin;
  // Where each new point was in the old lattice (its index), or the points to sample.
  std::vector<long long> from(size_t(n) * n, -1);
  std::vector<size_t> missing;
  std::vector<glm::dvec2> points;
  for (size_t p = 0; p < from.size(); ++p) {
    const glm::ivec2 at(int(p % size_t(n)), int(p / size_t(n))), old = at + shift;
    if (old.x >= 0 && old.y >= 0 && old.x < n && old.y < n) {
      from[p] = (long long)old.y * n + old.x;
    } else {
      missing.push_back(p);
      points.push_back(origin_ + glm::dvec2(at) * s);
    }
  }
  for (auto& [index, heights] : knots_) {
    std::vector<double> moved(heights.size());
    for (size_t p = 0; p < moved.size(); ++p)
      if (from[p] >= 0) moved[p] = heights[size_t(from[p])];
    if (!points.empty()) {
      const std::vector<WaveSample> samples =
          query_->sample(double(index) * options_.knot_interval_s, points);
      for (size_t m = 0; m < missing.size(); ++m) moved[missing[m]] = samples[m].height;
    }
    heights = std::move(moved);
  }
}

std::vector<glm::dvec2> LocalHeights::lattice_points(size_t first, size_t last) const {
  const size_t n = size_t(options_.points_per_side);
  std::vector<glm::dvec2> points;
  points.reserve(last - first);
  for (size_t p = first; p < last; ++p)
    points.push_back(origin_ + glm::dvec2(p % n, p / n) * options_.spacing_m);
  return points;
}

const std::vector<double>& LocalHeights::knot(long long index) {
  for (const auto& [i, heights] : knots_)
    if (i == index) return heights;
  const size_t count = size_t(options_.points_per_side) * size_t(options_.points_per_side);
  std::vector<double> heights;
  // The knot ahead (a recentre drops it), unless the worker has not begun it: then it is sampled here.
  if (index == ahead_index_ && ahead_.heights.valid()) {
    if (ahead_.heights.wait_for(std::chrono::seconds(0)) == std::future_status::ready || !ahead_.claim())
      heights = ahead_.heights.get();
    ahead_ = {};
  }
  if (heights.size() != count) {
    heights.resize(count);
    const std::vector<WaveSample> samples =
        query_->sample(double(index) * options_.knot_interval_s, lattice_points(0, count));
    for (size_t k = 0; k < samples.size(); ++k) heights[k] = samples[k].height;
  }
  ++knots_sampled_;
  knots_.emplace_back(index, std::move(heights));
  return knots_.back().second;
}

void LocalHeights::sample_ahead(long long index) {
  if (ahead_index_ == index) return;
  for (const auto& [i, heights] : knots_)
    if (i == index) return;
  const size_t count = size_t(options_.points_per_side) * size_t(options_.points_per_side);
  ahead_index_ = index;
  // Due when update() first reads it: at knot index - 2 (it reads k - 1 .. k + 2).
  ahead_ = query_->heights_ahead(double(index) * options_.knot_interval_s, lattice_points(0, count),
                                 double(index - 2) * options_.knot_interval_s);
}

void LocalHeights::update(double time_s, glm::dvec2 centre) {
  const int n = options_.points_per_side;
  const double s = options_.spacing_m;
  // Keep the body keep_inside_m from the edge, or in the lattice's inner half.
  const glm::dvec2 local = (centre - origin_) / s;
  const double margin = options_.keep_inside_m > 0 ? options_.keep_inside_m / s : 0.25 * (n - 1);
  const double lo = margin, hi = (n - 1) - margin;
  const double u = time_s / options_.knot_interval_s;
  const long long k = (long long)std::floor(u);
  const std::array<double, 4> w = catmull_rom_weights(u - double(k));
  // Only the knots k - 1 .. k + 2 are kept, and k + 3 when a recentre moved the knot ahead with them
  // (dropped before a recentre moves them); the missing ones are sampled, then looked up (so no reference
  // outlives a change of the list).
  std::erase_if(knots_, [k](const auto& knot) { return knot.first < k - 1 || knot.first > k + 3; });
  if (!placed_ || local.x < lo || local.y < lo || local.x > hi || local.y > hi) recentre(centre);
  for (int m = 0; m < 4; ++m) knot(k - 1 + m);
  std::array<const std::vector<double>*, 4> at{};
  for (int m = 0; m < 4; ++m) at[m] = &knot(k - 1 + m);
  sample_ahead(k + 3);  // the knot the next interval will need
  for (size_t i = 0; i < now_.size(); ++i)
    now_[i] = w[0] * (*at[0])[i] + w[1] * (*at[1])[i] + w[2] * (*at[2])[i] + w[3] * (*at[3])[i];
  bound_highest();
}

void LocalHeights::bound_highest() {
  // Catmull-Rom's weights sum to 1 with negative lobes of at most 1/8 per axis, so a value lies at most
  // (1 + 1/8)² + (1/8)² - 1 = 0.28 of the range above the highest point it interpolates.
  const auto [lo_it, hi_it] = std::minmax_element(now_.begin(), now_.end());
  highest_ = *hi_it + 0.3 * (*hi_it - *lo_it);
}

std::array<int, 4> LocalHeights::taps_under(glm::dvec2 lo, glm::dvec2 hi) const {
  if (!(lo.x <= hi.x && lo.y <= hi.y)) return {0, 0, -1, -1};  // empty, or NaN
  const int n = options_.points_per_side;
  // height() at local coordinate u reads the points floor(u) - 1 .. floor(u) + 2 (u clamped to the lattice).
  const auto first = [&](double v, double o) {
    return int(std::clamp(std::floor((v - o) / options_.spacing_m), 0.0, double(n - 1))) - 1;
  };
  return {std::max(first(lo.x, origin_.x), 0), std::max(first(lo.y, origin_.y), 0),
          std::min(first(hi.x, origin_.x) + 3, n - 1), std::min(first(hi.y, origin_.y) + 3, n - 1)};
}

void LocalHeights::add(glm::dvec2 lo, glm::dvec2 hi, const ExtraHeights& extra) {
  const auto [x0, z0, x1, z1] = taps_under(lo, hi);
  if (x0 > x1 || z0 > z1) return;
  const size_t n = size_t(options_.points_per_side);
  added_at_.clear();
  for (int j = z0; j <= z1; ++j)
    for (int i = x0; i <= x1; ++i) added_at_.push_back(origin_ + glm::dvec2(i, j) * options_.spacing_m);
  added_.assign(added_at_.size(), 0.0);
  extra(added_at_, added_);
  size_t k = 0;
  for (int j = z0; j <= z1; ++j)
    for (int i = x0; i <= x1; ++i) now_[size_t(j) * n + size_t(i)] += added_[k++];
  bound_highest();
}

double LocalHeights::highest(glm::dvec2 lo, glm::dvec2 hi) const {
  const auto [x0, z0, x1, z1] = taps_under(lo, hi);
  if (x0 > x1 || z0 > z1) return highest_;
  const size_t n = size_t(options_.points_per_side);
  double top = -std::numeric_limits<double>::infinity(), bottom = std::numeric_limits<double>::infinity();
  for (int j = z0; j <= z1; ++j)
    for (int i = x0; i <= x1; ++i) {
      const double v = now_[size_t(j) * n + size_t(i)];
      top = std::max(top, v), bottom = std::min(bottom, v);
    }
  return top + 0.3 * (top - bottom);  // bound_highest()'s overshoot over these points' range
}

double LocalHeights::height(double x, double z) const {
  const int n = options_.points_per_side;
  const glm::dvec2 local =
      glm::clamp((glm::dvec2(x, z) - origin_) / options_.spacing_m, glm::dvec2(0.0), glm::dvec2(n - 1));
  const int ix = std::min(int(local.x), n - 2), iz = std::min(int(local.y), n - 2);
  const std::array<double, 4> wx = catmull_rom_weights(local.x - ix), wz = catmull_rom_weights(local.y - iz);
  // Separably: each row's taps along x, then the rows along z (20 multiply-adds instead of 48 operations;
  // this is the bodies' hottest loop).
  double sum = 0;
  if (ix >= 1 && iz >= 1 && ix + 2 < n && iz + 2 < n) {
    // Inside: no tap needs clamping (the hulls' points almost always are). The same terms in the same
    // order as below, so the same sum to the bit.
    const double* row = now_.data() + size_t(iz - 1) * n + (ix - 1);
    for (int b = 0; b < 4; ++b, row += n)
      sum += wz[b] * (wx[0] * row[0] + wx[1] * row[1] + wx[2] * row[2] + wx[3] * row[3]);
    return sum;
  }
  for (int b = 0; b < 4; ++b) {
    const double* row = now_.data() + size_t(std::clamp(iz - 1 + b, 0, n - 1)) * n;
    const auto at = [&](int a) { return row[std::clamp(ix - 1 + a, 0, n - 1)]; };
    sum += wz[b] * (wx[0] * at(0) + wx[1] * at(1) + wx[2] * at(2) + wx[3] * at(3));
  }
  return sum;
}

void LocalHeights::heights(std::span<const glm::dvec2> points, std::span<double> heights) const {
  for (size_t i = 0; i < points.size(); ++i) heights[i] = height(points[i].x, points[i].y);
}

}  // namespace lagoon::ocean
