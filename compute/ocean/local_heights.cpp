#include "ocean/local_heights.h"

#include <algorithm>
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
  const double time = double(index) * options_.knot_interval_s;
  std::vector<double> heights(count);
  size_t done = 0;
  if (index == ahead_index_) {  // what sample_ahead already has
    heights = std::move(ahead_);
    done = ahead_done_;
    ahead_index_ = std::numeric_limits<long long>::min();
  }
  if (done < count) {
    const std::vector<WaveSample> samples = query_->sample(time, lattice_points(done, count));
    for (size_t k = 0; k < samples.size(); ++k) heights[done + k] = samples[k].height;
  }
  ++knots_sampled_;
  knots_.emplace_back(index, std::move(heights));
  return knots_.back().second;
}

void LocalHeights::sample_ahead(long long index) {
  const size_t count = size_t(options_.points_per_side) * size_t(options_.points_per_side);
  if (ahead_index_ != index) {
    ahead_index_ = index;
    ahead_.assign(count, 0.0);
    ahead_done_ = 0;
  }
  const double time = double(index) * options_.knot_interval_s;
  if (ahead_done_ == count || !query_->ready(time)) return;
  const size_t end = std::min(count, ahead_done_ + (count + kShares - 1) / kShares);
  const std::vector<WaveSample> samples = query_->sample(time, lattice_points(ahead_done_, end));
  for (size_t k = 0; k < samples.size(); ++k) ahead_[ahead_done_ + k] = samples[k].height;
  ahead_done_ = end;
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
  // Only the knots k - 1 .. k + 2 are kept (dropped before a recentre moves them); the missing ones are
  // sampled, then looked up (so no reference outlives a change of the list).
  std::erase_if(knots_, [k](const auto& knot) { return knot.first < k - 1 || knot.first > k + 2; });
  if (!placed_ || local.x < lo || local.y < lo || local.x > hi || local.y > hi) recentre(centre);
  for (int m = 0; m < 4; ++m) knot(k - 1 + m);
  std::array<const std::vector<double>*, 4> at{};
  for (int m = 0; m < 4; ++m) at[m] = &knot(k - 1 + m);
  query_->prefetch(double(k + 3) * options_.knot_interval_s);  // the knot the next interval will need
  sample_ahead(k + 3);
  for (size_t i = 0; i < now_.size(); ++i)
    now_[i] = w[0] * (*at[0])[i] + w[1] * (*at[1])[i] + w[2] * (*at[2])[i] + w[3] * (*at[3])[i];
  // Catmull-Rom's weights sum to 1 with negative lobes of at most 1/8 per axis, so a value lies at most
  // (1 + 1/8)² + (1/8)² - 1 = 0.28 of the range above the highest point it interpolates.
  const auto [lo_it, hi_it] = std::minmax_element(now_.begin(), now_.end());
  highest_ = *hi_it + 0.3 * (*hi_it - *lo_it);
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
