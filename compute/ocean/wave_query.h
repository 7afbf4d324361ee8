// Wave height, normal and surface velocity at any (x, z, t) for physics engines (buoyancy), on the CPU,
// with no frame lag: the query evaluates the same band-limited sum the GPU evaluates, for the time asked.
//
// How: once per distinct time the cascades' fields (height, horizontal displacement, slopes, velocity)
// are evaluated on their grids with an FFT (~tens of ms for 3 x 256²), then every point costs a few
// periodic Catmull-Rom lookups. The horizontal displacement is inverted by fixed-point iteration: the
// answer describes the surface point that the waves move to above (x, z), not the one that rests there.
//
// Models gerstner and sines with their own waves (ocean/direct_waves.h) are answered from GerstnerSurface,
// the direct sums in double precision: bound 0, every time at once.
//
// Model springs has no spectrum: its grid (ocean/springs.h) is stepped to the time asked and sampled the same
// way. Its nodes are the model, so the bound is 0; between them the answer is the Catmull-Rom interpolant.
//
// Error bound (WaveSample::error_bound_m) on the height against the exact band-limited sum:
//   B_h + G · 2λB_D. B_h and B_D bound the interpolation error of the height and of the horizontal
//   displacement: each mode contributes its amplitude times E(k), the largest interpolation error of a
//   complex exponential at its wavenumber; the modes' phases are independent and uniformly random, so the
//   error at a point is a sum of independent terms with standard deviation σ = sqrt(Σ |a_k|² E(k)²) and the
//   bound is 5σ (exceeded with probability ~1e-6 per point). G is the largest slope on the grid at that
//   time; the factor 2 covers the displacement inversion while the horizontal map contracts by 1/2 or
//   better (away from folding crests). worst_case_bound_m() gives the rigorous Σ |a_k| E(k), far larger.
#pragma once
#include <atomic>
#include <exception>
#include <future>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "core/background_worker.h"
#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "ocean/shoaling.h"
#include "ocean/spectral_fields.h"
#include "ocean/springs.h"

namespace lagoon::ocean {

class GerstnerSurface;

struct WaveSample {
  double height = 0;               // m above the mean water level, at the query's (x, z)
  glm::dvec3 normal{0, 1, 0};      // unit surface normal
  glm::dvec3 velocity{0, 0, 0};    // m/s, velocity of the water surface point there
  glm::dvec2 rest_position{0, 0};  // (x, z) of the surface point before horizontal displacement
  double error_bound_m = 0;        // bound on the height error, see above
  bool converged = true;           // false where the inversion did not converge (folded surface)
};

// Where answers still describe the point asked about: beyond 2^32 m (4.3e6 km) a double's spacing exceeds
// 1 µm, and beyond 2^32 s (136 years) that of the time exceeds 1 µs (a phase error below 1e-4 rad for the
// shortest waves Lagoon draws). Further out the inputs themselves are no longer resolved (at 1e30 m the next
// double is 1.4e14 m away), so callers refuse them rather than answer for a different point.
inline constexpr double kWaveQueryMaxCoordinateM = 4294967296.0;
inline constexpr double kWaveQueryMaxTimeS = 4294967296.0;

struct WaveQueryOptions {
  unsigned threads = 2;
  // Waves with |k| >= this are left out (ocean/band_limit.h): the answers, and their bound, are for the sea
  // without them, evaluated on grids that only need to hold the rest (the bodies' buoyancy: issue 14).
  double max_wavenumber = std::numeric_limits<double>::infinity();
  // The height and rest position only (normal and velocity keep their defaults): half the fields to evaluate.
  // The bound's slope term then uses the spectrum's largest possible slope, Σ|a_k| k, not the grid's.
  bool heights_only = false;
  // The thread that evaluates prefetch()'s times and samples heights_ahead()'s points; shared with the
  // caller's other helpers when given (the bodies' sea and wake layers), else the query's own.
  std::shared_ptr<BackgroundWorker> worker;
};

class WaveQuery {
 public:
  explicit WaveQuery(const OceanParams& params, unsigned threads = 2);
  WaveQuery(const OceanParams& params, std::vector<CascadeSpectrum> spectra, unsigned threads = 2);
  WaveQuery(const OceanParams& params, std::vector<CascadeSpectrum> spectra, WaveQueryOptions options);
  ~WaveQuery();

  // Samples every point at `time_s`. The fields for a new time are evaluated first; the last few times'
  // stay cached (kRecentTimes), so callers that return to a recent time do not pay for it again.
  std::vector<WaveSample> sample(double time_s, std::span<const glm::dvec2> points);
  WaveSample sample(double time_s, double x, double z);
  // Starts evaluating the fields for `time_s` on another thread, so that a later sample() at that time finds
  // them ready (or waits only for the rest). The bodies' physics asks for its next time knot this way: the
  // FFTs run while the steps before the knot go on, instead of on one step. The answers are the same to
  // the bit. Nothing for model springs, whose grid steps in order.
  // `due_s`: when the caller will need them, in its own clock; the worker does the soonest of its jobs first.
  void prefetch(double time_s, double due_s = BackgroundWorker::kWhenever);
  // Whether sample() at `time_s` would answer without evaluating or waiting: the time is a recent one, or
  // its prefetch has finished. Always false for model springs.
  bool ready(double time_s) const;
  // sample(time_s, points)'s heights, computed on another thread: the fields for the time as prefetch()
  // evaluates them, then the points. The bodies' next time knot (ocean/local_heights.h) is sampled this way,
  // so no step pays for a knot's thousands of points. The same heights to the bit. The query must outlive
  // the future. For models springs, gerstner and sines, the answer is sampled when asked for.
  struct HeightsAhead {
    std::future<std::vector<double>> heights;
    // The sampling, taken by whoever begins it (core/background_worker.h): a caller that claims it samples
    // the heights itself, and the future then gives none.
    std::shared_ptr<Claim> begun = std::make_shared<Claim>();
    bool claim() { return begun->take(); }
  };
  HeightsAhead heights_ahead(double time_s, std::vector<glm::dvec2> points,
                             double due_s = BackgroundWorker::kWhenever);

  static constexpr size_t kRecentTimes = 5;  // the bodies' four knots in use and the next one

  // The interpolation bounds B_h and B_D (time-independent, 5σ) and the rigorous worst case for the height.
  double height_interpolation_bound_m() const { return bound_height_; }
  double displacement_interpolation_bound_m() const { return bound_displacement_; }
  double worst_case_bound_m() const { return worst_case_height_; }

 private:
  struct Grid;
  // The fields of every cascade at one time, and the largest slope the bound uses.
  struct Evaluation {
    double time_s = 0;
    std::vector<std::unique_ptr<Grid>> grids;
    double max_slope = 0;
  };
  // A prefetched time's fields, evaluated in pieces (a cascade's pair of fields packed in one FFT, about a
  // millisecond each) by whoever takes them: the worker's jobs, a sampling job, or the caller in a
  // catch-up that overtook the worker. No one thread carries a whole knot when the others need it.
  struct Pending {
    std::shared_ptr<Evaluation> building;  // its grids made, their fields filled by the pieces
    int pieces = 0;
    std::atomic<int> next{0};  // the next piece to take
    std::atomic<int> left{0};  // pieces not yet finished: the one that finishes the last hands them over
    std::mutex failed_mutex;
    std::exception_ptr failed;
    std::promise<std::shared_ptr<const Evaluation>> made;
    std::shared_future<std::shared_ptr<const Evaluation>> fields = made.get_future().share();
    double time_s() const { return building->time_s; }
  };
  std::shared_ptr<Pending> begin_pending(double time_s) const;
  // Runs one piece not yet taken; false when none is left.
  bool take_piece(Pending& pending) const;
  // The pending fields, their pieces not yet taken evaluated here.
  std::shared_ptr<const Evaluation> fields_of(Pending& pending) const;
  // The evaluation's grids, sized and without fields, and the piece count: (cascades) x (field pairs).
  std::shared_ptr<Evaluation> empty_evaluation(double time_s) const;
  int field_count() const;
  void evaluate_piece(Evaluation& evaluation, int piece) const;
  void finish(Evaluation& evaluation) const;  // the largest slope, once every field is in
  // The pending time `time_s`, or null.
  std::shared_ptr<Pending> pending_at(double time_s) const;
  WorkerLane& lane();
  void evaluate(double time_s);
  // Reads only what construction set, so it may run on another thread while the query answers.
  std::shared_ptr<const Evaluation> evaluate_spectra(double time_s) const;
  std::shared_ptr<const Evaluation> evaluate_springs(double time_s);
  void keep(std::shared_ptr<const Evaluation> evaluation);
  glm::dvec2 displacement(const Evaluation& fields, glm::dvec2 p) const;
  // Where each cascade is read for the rest position p, and the random sea's height scale there (1 and p
  // itself where no floor changes the sea): one lookup of the floor's table.
  Shoaling::LatticeMoves moves(glm::dvec2 p) const;
  // sample()'s answers for points[begin, end), from `fields`. Reads nothing that changes after
  // construction, so it may run on another thread.
  void sample_range(const Evaluation& fields, std::span<const glm::dvec2> points,
                    std::vector<WaveSample>& out, size_t begin, size_t end) const;

  OceanParams params_;
  std::unique_ptr<SpringGrid> springs_;        // model springs: the grid itself, stepped to each time asked
  std::unique_ptr<GerstnerSurface> direct_;    // waves evaluated directly: their sums
  std::unique_ptr<GerstnerSurface> swell_;     // swell trains over the cascades' sea
  std::shared_ptr<const Shoaling> sea_floor_;  // the random sea's depth-limited height, where a floor is
  std::vector<CascadeSpectrum> spectra_;
  std::vector<size_t> cascade_of_;  // each of spectra_'s cascade: whose lattice it moves with over the floor
  std::vector<SpectrumModes> modes_;  // spectra_'s modes, listed once: what each evaluation visits
  WaveQueryOptions options_;
  InverseFft2d fft_;        // plans shared by every evaluation, on any thread
  double slope_bound_ = 0;  // Σ |a_k| |k| over every mode: no slope of the surface exceeds it
  std::shared_ptr<const Evaluation> current_;              // what sample() answers from
  std::vector<std::shared_ptr<const Evaluation>> recent_;  // the last kRecentTimes, oldest first
  // prefetch()'s times not yet kept among the recent ones, oldest first (shared with heights_ahead()'s jobs).
  // A new prefetch does not wait for the ones before it: in a catch-up the worker runs behind the caller.
  std::vector<std::shared_ptr<Pending>> pending_;
  double bound_height_ = 0, bound_displacement_ = 0, worst_case_height_ = 0;
  // Evaluates prefetch()'s times and samples heights_ahead()'s points; made at the first of them (on
  // options_.worker, or a worker of its own). Last: its jobs read the rest, so it waits for them before the
  // rest goes.
  std::unique_ptr<WorkerLane> lane_;
};

// Largest error of periodic Catmull-Rom interpolation of e^{iθm} (unit samples), |θ| <= π, and the
// interpolator's Lebesgue constant: the ingredients of the bound, exposed for tests.
double catmull_rom_exponential_error(double theta);
double catmull_rom_lebesgue_constant();

}  // namespace lagoon::ocean
