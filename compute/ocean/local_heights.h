// The sea's height around a floating body, for its buoyancy at every physics step (issue 14). WaveQuery's
// FFT per new time (15-30 ms on 2 cores) is too slow for 120 steps a second, so the heights are sampled from
// WaveQuery only at time knots (every knot_interval_s) on a small square lattice around the body, and in
// between interpolated: Catmull-Rom through four knots in time, bicubic Catmull-Rom in space. The lattice
// is fixed in the world (its origin a multiple of the spacing) and moves only when the body nears its edge,
// which re-samples the knots. Waves much shorter than the spacing are not resolved: they average out over a
// hull of several spacings.
#pragma once
#include <array>
#include <functional>
#include <future>
#include <glm/vec2.hpp>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "ocean/wave_query.h"

namespace lagoon::ocean {

struct LocalHeightsOptions {
  int points_per_side = 16;      // lattice points along each side
  double spacing_m = 0.5;        // between them
  double knot_interval_s = 0.2;  // between WaveQuery evaluations
  // How close to the lattice's edge the centre given to update() may come before the lattice recentres on
  // it (m); 0: a quarter of the lattice's width (it stays in the inner half).
  double keep_inside_m = 0;
};

// The shortest waves a lattice resolves are 4 spacings long (2 m by default); a WaveQuery for the lattice can
// leave shorter ones out (WaveQueryOptions::max_wavenumber): sampled on the lattice they would only alias,
// and evaluating the rest is several times cheaper.
inline double lattice_wavenumber(const LocalHeightsOptions& o) {
  return 2 * 3.14159265358979323846 / (4 * o.spacing_m);
}

class LocalHeights {
 public:
  LocalHeights(const OceanParams& params, std::vector<CascadeSpectrum> spectra, LocalHeightsOptions options);
  // Sharing one WaveQuery between the bodies of a scene: bodies stepped together ask for the same knot
  // times, so the sea's fields are evaluated once per knot for all of them.
  LocalHeights(std::shared_ptr<WaveQuery> query, LocalHeightsOptions options);

  // Makes height() answer at time t around `centre` (the body's position): samples the knots it lacks.
  void update(double time_s, glm::dvec2 centre);
  // The displaced surface's height at (x, z) at the last update's time. Outside the lattice: its edge value.
  double height(double x, double z) const;
  // height() at each of `points` (x, z) into `heights`: a hull's points in one call.
  void heights(std::span<const glm::dvec2> points, std::span<double> heights) const;
  // Heights at (x, z) points, added into `heights` (heights[i] += at points[i]): another source of water
  // height over the sea, such as the vehicles' wakes.
  using ExtraHeights = std::function<void(std::span<const glm::dvec2> points, std::span<double> heights)>;
  // Adds `extra` at the lattice points that height() reads for (x, z) in the box [lo, hi], until the next
  // update: a hull inside the box then looks its water up once instead of once per source (issue 35). The
  // sum is interpolated as the sea is; outside the box height() answers the sea alone.
  void add(glm::dvec2 lo, glm::dvec2 hi, const ExtraHeights& extra);
  // No height() at the last update's time is above this: the lattice's highest point plus the most the
  // bicubic interpolation can overshoot it (0.28 of the lattice's range).
  double highest() const { return highest_; }
  // No height() at the last update's time at (x, z) in the box [lo, hi] is above this: the same bound over
  // the lattice points its taps read. Under a hull, lower than highest() wherever the lattice's highest
  // crest is not under it, which spares the hull the lookups of triangles that are surely dry (issue 35).
  double highest(glm::dvec2 lo, glm::dvec2 hi) const;

  // How many knots were sampled from WaveQuery so far (each costs one evaluation of the sea's fields).
  int knots_sampled() const { return knots_sampled_; }
  const LocalHeightsOptions& options() const { return options_; }

 private:
  void recentre(glm::dvec2 centre);
  std::vector<glm::dvec2> lattice_points(size_t first, size_t last) const;
  const std::vector<double>& knot(long long index);
  // Has knot `index` sampled on another thread (ocean/wave_query.h heights_ahead) unless it is known or
  // already asked for.
  void sample_ahead(long long index);
  // highest_ from now_.
  void bound_highest();
  // The lattice points (x0, z0, x1, z1, inclusive) that height() reads for points in the box [lo, hi]; none
  // (x0 > x1) when the box is empty or NaN.
  std::array<int, 4> taps_under(glm::dvec2 lo, glm::dvec2 hi) const;

  std::shared_ptr<WaveQuery> query_;
  LocalHeightsOptions options_;
  glm::dvec2 origin_{0.0};  // the lattice point (0, 0), world xz
  bool placed_ = false;
  // The knots k - 1 .. k + 2 around the last update's time (index, heights on the lattice).
  std::vector<std::pair<long long, std::vector<double>>> knots_;
  // The knot after the four in use, sampled on another thread while the steps before it go on, so that no
  // step samples a whole knot (a hull's lattice has up to thousands of points, each ~1 µs: issue 35), and
  // its index. A recentre moves it with the other knots when it is done and drops it otherwise.
  long long ahead_index_ = std::numeric_limits<long long>::min();
  WaveQuery::HeightsAhead ahead_;
  std::vector<double> now_;           // the lattice at the last update's time
  std::vector<glm::dvec2> added_at_;  // add()'s scratch: its points and their extra heights
  std::vector<double> added_;
  double highest_ = 0;
  int knots_sampled_ = 0;
};

}  // namespace lagoon::ocean
