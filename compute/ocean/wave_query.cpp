#include "ocean/wave_query.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <glm/geometric.hpp>
#include <numbers>
#include <thread>

#include "ocean/band_limit.h"
#include "ocean/catmull_rom.h"
#include "ocean/direct_waves.h"
#include "ocean/gerstner.h"
#include "ocean/random_sea.h"
#include "ocean/shoaling.h"
#include "ocean/slope_statistics.h"
#include "ocean/spectral_fields.h"

namespace lagoon::ocean {
namespace {

constexpr Field kFields[] = {Field::Dx,     Field::Height,    Field::Dz,        Field::SlopeX,
                             Field::SlopeZ, Field::VelocityX, Field::VelocityY, Field::VelocityZ};
enum { kDx, kHeight, kDz, kSlopeX, kSlopeZ, kVx, kVy, kVz, kFieldCount };

}  // namespace

double catmull_rom_exponential_error(double theta) {
  double worst = 0;
  for (int i = 0; i <= 256; ++i) {
    const double s = i / 256.0;
    const std::array<double, 4> w = catmull_rom_weights(s);
    std::complex<double> v = 0;
    for (int m = -1; m <= 2; ++m) v += w[m + 1] * std::polar(1.0, theta * m);
    worst = std::max(worst, std::abs(v - std::polar(1.0, theta * s)));
  }
  return worst;
}

double catmull_rom_lebesgue_constant() {
  double worst = 0;
  for (int i = 0; i <= 256; ++i) {
    const std::array<double, 4> w = catmull_rom_weights(i / 256.0);
    worst = std::max(worst, std::abs(w[0]) + std::abs(w[1]) + std::abs(w[2]) + std::abs(w[3]));
  }
  return worst;
}

struct WaveQuery::Grid {
  uint32_t n = 0;
  double texel_m = 0;  // L / N
  std::vector<double> fields[kFieldCount];

  // Sum of the periodic Catmull-Rom interpolants of `count` fields starting at `first`.
  void sample(glm::dvec2 p, int first, int count, double* out) const {
    const double u = p.x / texel_m, v = p.y / texel_m;
    const double fu = std::floor(u), fv = std::floor(v);
    const std::array<double, 4> wu = catmull_rom_weights(u - fu), wv = catmull_rom_weights(v - fv);
    const long iu = long(fu), iv = long(fv), mask = long(n) - 1;  // n is a power of two
    size_t rows[4], cols[4];
    for (int m = 0; m < 4; ++m) {
      rows[m] = size_t((iv + m - 1) & mask) * n;
      cols[m] = size_t((iu + m - 1) & mask);
    }
    for (int f = 0; f < count; ++f) {
      const std::vector<double>& data = fields[first + f];
      double acc = 0;
      for (int a = 0; a < 4; ++a) {
        double row = 0;
        for (int b = 0; b < 4; ++b) row += wu[b] * data[rows[a] + cols[b]];
        acc += wv[a] * row;
      }
      out[f] += acc;
    }
  }
};

WaveQuery::WaveQuery(const OceanParams& params, unsigned threads) : WaveQuery(params, {}, threads) {}

WaveQuery::WaveQuery(const OceanParams& params, std::vector<CascadeSpectrum> spectra, unsigned threads)
    : WaveQuery(params, std::move(spectra), WaveQueryOptions{.threads = threads}) {}

WaveQuery::WaveQuery(const OceanParams& params, std::vector<CascadeSpectrum> spectra,
                     WaveQueryOptions options)
    : params_(params),
      spectra_(std::move(spectra)),
      options_(options),
      fft_(cpu_inverse_fft(options.threads)) {
  if (params.model == SurfaceModel::Springs) {
    springs_ = std::make_unique<SpringGrid>(params);
    cascade_of_ = {0};  // its one grid, never moved (no floor table for the springs)
    return;
  }
  if (std::optional<GerstnerParams> direct = direct_wave_params(params)) {
    // The wavelength cut leaves out a wave whose shortest harmonic is above it, as band_limited a mode.
    std::erase_if(direct->waves, [&](const GerstnerWave& w) {
      return 2 * std::numbers::pi / w.wavelength_m * std::max(w.power, 1u) >= options_.max_wavenumber;
    });
    direct_ = std::make_unique<GerstnerSurface>(*direct);
    return;
  }
  if (spectra_.empty())
    for (uint32_t c = 0; c < params.cascades.size(); ++c)
      spectra_.push_back(make_cascade_spectrum(params, c));
  // Over the floor the random sea's lattices move and its height is limited (ocean/shoaling.h): its
  // significant height and representative waves are the whole spectrum's, as the renderer's. Swell trains
  // over it are summed as model gerstner's waves, and their table holds the sea's too.
  const RandomSea sea = random_sea(params, spectra_);
  if (std::optional<GerstnerParams> swell = swell_wave_params(params, sea)) {
    std::erase_if(swell->waves, [&](const GerstnerWave& w) {
      return 2 * std::numbers::pi / w.wavelength_m >= options_.max_wavenumber;
    });
    if (!swell->waves.empty()) swell_ = std::make_unique<GerstnerSurface>(*swell);
  }
  sea_floor_ = swell_ ? swell_->shared_shoaling() : sea_over_floor(params, sea);
  for (size_t c = 0; c < spectra_.size(); ++c) cascade_of_.push_back(c);
  if (std::isfinite(options_.max_wavenumber)) {
    std::vector<CascadeSpectrum> kept;
    cascade_of_.clear();
    for (size_t c = 0; c < spectra_.size(); ++c)
      if (CascadeSpectrum cut = band_limited(spectra_[c], options_.max_wavenumber); cut.resolution > 0) {
        kept.push_back(std::move(cut));
        cascade_of_.push_back(c);
      }
    spectra_ = std::move(kept);
  }
  for (const CascadeSpectrum& s : spectra_) modes_.push_back(list_modes(s));
  // Interpolation bounds: every mode's largest amplitude |h0(k)| + |h0(-k)| times the 2-D error of its
  // exponential (tensor product: E(θx) + Λ·E(θz)), tabulated over θ to keep construction fast.
  constexpr int kTable = 512;
  std::vector<double> table(kTable + 1);
  for (int i = 0; i <= kTable; ++i) table[i] = catmull_rom_exponential_error(std::numbers::pi * i / kTable);
  auto error_at = [&](double theta) {  // |θ| <= π; linear interpolation of a smooth, increasing table
    const double x = std::min(std::abs(theta), std::numbers::pi) / std::numbers::pi * kTable;
    const int i = std::min(int(x), kTable - 1);
    return table[i] + (table[i + 1] - table[i]) * (x - i) + 1e-12;
  };
  const double lebesgue = catmull_rom_lebesgue_constant();
  double variance_h = 0, variance_d = 0;
  for (const CascadeSpectrum& s : spectra_) {
    const uint32_t n = s.resolution;
    const double dk = 2 * std::numbers::pi / s.patch_size_m, texel = s.patch_size_m / n;
    for (uint32_t iz = 0; iz < n; ++iz)
      for (uint32_t ix = 0; ix < n; ++ix) {
        const size_t i = size_t{iz} * n + ix, mirrored = size_t{(n - iz) % n} * n + (n - ix) % n;
        const double a2 =
            std::norm(std::complex<double>(s.h0[i])) + std::norm(std::complex<double>(s.h0[mirrored]));
        if (a2 == 0) continue;
        const double kx = dk * (ix < n / 2 ? double(ix) : double(ix) - n);
        const double kz = dk * (iz < n / 2 ? double(iz) : double(iz) - n);
        const double e = error_at(kx * texel) + lebesgue * error_at(kz * texel);
        const double k = std::hypot(kx, kz);
        variance_h += a2 * e * e;
        variance_d += a2 * e * e * (kx * kx + kz * kz) / (k * k) / 2;  // per horizontal component, on average
        const double amplitude =
            std::abs(std::complex<double>(s.h0[i])) + std::abs(std::complex<double>(s.h0[mirrored]));
        worst_case_height_ += amplitude * e;
        slope_bound_ += amplitude * k;
      }
  }
  bound_height_ = 5 * std::sqrt(variance_h);
  bound_displacement_ = 5 * std::sqrt(2 * variance_d);  // both components: |(dx, dz)|
}

WaveQuery::~WaveQuery() = default;  // lane_, destroyed first, waits for the jobs that read this

// The grid's heights and vertical velocities at the nodes, and their central-difference slopes (as the GPU's
// springs_assemble.comp takes them); no horizontal motion.
std::shared_ptr<const WaveQuery::Evaluation> WaveQuery::evaluate_springs(double time_s) {
  const std::vector<glm::dvec2> surface = springs_->surface_at(time_s);
  auto grid = std::make_unique<Grid>();
  const uint32_t n = springs_->resolution();
  grid->n = n;
  grid->texel_m = springs_->spacing_m();
  for (auto& f : grid->fields) f.assign(size_t{n} * n, 0.0);
  auto h = [&](uint32_t i, uint32_t j) { return surface[size_t(j % n) * n + i % n].x; };
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const size_t at = size_t{j} * n + i;
      grid->fields[kHeight][at] = surface[at].x;
      grid->fields[kVy][at] = surface[at].y;
      grid->fields[kSlopeX][at] = (h(i + 1, j) - h(i + n - 1, j)) / (2 * grid->texel_m);
      grid->fields[kSlopeZ][at] = (h(i, j + 1) - h(i, j + n - 1)) / (2 * grid->texel_m);
    }
  auto out = std::make_shared<Evaluation>();
  out->time_s = time_s;
  out->grids.push_back(std::move(grid));
  return out;
}

int WaveQuery::field_count() const {
  return options_.heights_only ? kDz + 1 : kFieldCount;  // Dx, height, Dz come first
}

std::shared_ptr<WaveQuery::Evaluation> WaveQuery::empty_evaluation(double time_s) const {
  auto out = std::make_shared<Evaluation>();
  out->time_s = time_s;
  for (const CascadeSpectrum& s : spectra_) {
    auto grid = std::make_unique<Grid>();
    grid->n = s.resolution;
    grid->texel_m = s.patch_size_m / s.resolution;
    out->grids.push_back(std::move(grid));
  }
  return out;
}

// Piece p: cascade p / pairs, fields 2 (p % pairs) and the one after it, packed in one FFT as the whole
// cascade's evaluation packs them (evaluate_fields), so the same numbers to the bit.
void WaveQuery::evaluate_piece(Evaluation& evaluation, int piece) const {
  const int fields = field_count(), pairs = (fields + 1) / 2;
  const int cascade = piece / pairs, first = 2 * (piece % pairs), count = std::min(2, fields - first);
  auto values = evaluate_fields(modes_[size_t(cascade)], evaluation.time_s,
                                std::span(kFields + first, size_t(count)), fft_);
  for (int f = 0; f < count; ++f) evaluation.grids[size_t(cascade)]->fields[first + f] = std::move(values[f]);
}

std::shared_ptr<const WaveQuery::Evaluation> WaveQuery::evaluate_spectra(double time_s) const {
  std::shared_ptr<Evaluation> out = empty_evaluation(time_s);
  const int fields = field_count();
  for (size_t c = 0; c < spectra_.size(); ++c) {  // every field of a cascade at once: its FFTs' threads
    auto values = evaluate_fields(modes_[c], time_s, std::span(kFields, size_t(fields)), fft_);
    for (int f = 0; f < fields; ++f) out->grids[c]->fields[f] = std::move(values[f]);
  }
  finish(*out);
  return out;
}

void WaveQuery::finish(Evaluation& out) const {
  if (options_.heights_only) {
    out.max_slope = slope_bound_;
    return;
  }
  // Largest slope of the summed surface, bounded by the sum of each cascade's largest slope.
  for (const auto& g : out.grids) {
    double m = 0;
    for (size_t i = 0; i < g->fields[kSlopeX].size(); ++i)
      m = std::max(m, std::hypot(g->fields[kSlopeX][i], g->fields[kSlopeZ][i]));
    out.max_slope += m;
  }
}

void WaveQuery::keep(std::shared_ptr<const Evaluation> evaluation) {
  if (recent_.size() == kRecentTimes) recent_.erase(recent_.begin());
  recent_.push_back(std::move(evaluation));
}

WorkerLane& WaveQuery::lane() {
  if (!lane_) lane_ = std::make_unique<WorkerLane>(options_.worker);
  return *lane_;
}

std::shared_ptr<WaveQuery::Pending> WaveQuery::begin_pending(double time_s) const {
  auto pending = std::make_shared<Pending>();
  pending->building = empty_evaluation(time_s);
  pending->pieces = int(spectra_.size()) * ((field_count() + 1) / 2);
  pending->left = pending->pieces;
  return pending;
}

bool WaveQuery::take_piece(Pending& pending) const {
  const int piece = pending.next.fetch_add(1);
  if (piece >= pending.pieces) return false;
  try {
    evaluate_piece(*pending.building, piece);
  } catch (...) {
    std::lock_guard lock(pending.failed_mutex);
    if (!pending.failed) pending.failed = std::current_exception();
  }
  if (pending.left.fetch_sub(1) == 1) {  // the last piece: every field is in
    std::exception_ptr failed;
    {
      std::lock_guard lock(pending.failed_mutex);
      failed = pending.failed;
    }
    if (failed) {
      pending.made.set_exception(failed);
    } else {
      finish(*pending.building);
      pending.made.set_value(pending.building);
    }
  }
  return true;
}

std::shared_ptr<const WaveQuery::Evaluation> WaveQuery::fields_of(Pending& pending) const {
  while (take_piece(pending)) {
  }
  return pending.fields.get();  // waits only for pieces other threads are in
}

std::shared_ptr<WaveQuery::Pending> WaveQuery::pending_at(double time_s) const {
  for (const auto& p : pending_)
    if (p->time_s() == time_s) return p;
  return nullptr;
}

void WaveQuery::prefetch(double time_s, double due_s) {
  if (springs_ || direct_) return;
  if (pending_at(time_s)) return;
  for (const auto& e : recent_)
    if (e->time_s == time_s) return;
  // The finished ones join the recent times, in the order they were asked for; at most kRecentTimes wait.
  while (!pending_.empty() &&
         (pending_.size() >= kRecentTimes ||
          pending_.front()->fields.wait_for(std::chrono::seconds(0)) == std::future_status::ready)) {
    keep(fields_of(*pending_.front()));
    pending_.erase(pending_.begin());
  }
  std::shared_ptr<Pending> pending = begin_pending(time_s);
  pending_.push_back(pending);
  for (int p = 0; p < pending->pieces; ++p) lane().submit([this, pending] { take_piece(*pending); }, due_s);
}

bool WaveQuery::ready(double time_s) const {
  if (direct_) return true;
  if (springs_) return false;
  for (const auto& e : recent_)
    if (e->time_s == time_s) return true;
  const std::shared_ptr<Pending> pending = pending_at(time_s);
  return pending && pending->fields.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

WaveQuery::HeightsAhead WaveQuery::heights_ahead(double time_s, std::vector<glm::dvec2> points,
                                                 double due_s) {
  auto heights_of = [](const std::vector<WaveSample>& samples) {
    std::vector<double> out(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) out[i] = samples[i].height;
    return out;
  };
  HeightsAhead ahead;
  if (springs_ || direct_) {  // sample() itself, on the thread that asks for the answer
    ahead.heights = std::async(std::launch::deferred, [this, time_s, points = std::move(points), heights_of] {
      return heights_of(sample(time_s, points));
    });
    return ahead;
  }
  // The fields: a recent time's, or the pending ones (the pieces nobody has taken evaluated by this job).
  std::shared_ptr<const Evaluation> recent;
  for (const auto& e : recent_)
    if (e->time_s == time_s) recent = e;
  std::shared_ptr<Pending> pending;
  if (!recent) {
    prefetch(time_s, due_s);
    pending = pending_at(time_s);
  }
  ahead.heights = lane().submit(
      [this, recent, pending, points = std::move(points), heights_of, begun = ahead.begun] {
        if (!begun->take()) return std::vector<double>{};  // claimed by the caller
        std::vector<WaveSample> out(points.size());
        sample_range(recent ? *recent : *fields_of(*pending), points, out, 0, points.size());
        return heights_of(out);
      },
      due_s);
  return ahead;
}

void WaveQuery::evaluate(double time_s) {
  if (current_ && current_->time_s == time_s) return;
  if (springs_) {  // stepped in order: never cached
    current_ = evaluate_springs(time_s);
    return;
  }
  for (const auto& e : recent_)
    if (e->time_s == time_s) {
      current_ = e;
      return;
    }
  if (const std::shared_ptr<Pending> pending = pending_at(time_s)) {
    current_ = fields_of(*pending);  // evaluated here if the worker has not begun them (a catch-up)
    std::erase(pending_, pending);
  } else {
    current_ = evaluate_spectra(time_s);
  }
  keep(current_);
}

Shoaling::LatticeMoves WaveQuery::moves(glm::dvec2 p) const {
  if (sea_floor_) return sea_floor_->lattice_moves(p);
  Shoaling::LatticeMoves none;
  none.point.fill(p);
  return none;
}

glm::dvec2 WaveQuery::displacement(const Evaluation& fields, glm::dvec2 p) const {
  double d[3] = {0, 0, 0};
  const Shoaling::LatticeMoves lattices = moves(p);  // each cascade read where its lattice has moved
  for (size_t g = 0; g < fields.grids.size(); ++g)
    fields.grids[g]->sample(lattices.point[cascade_of_[g]], kDx, 3, d);
  glm::dvec2 out = lattices.sea_scale * params_.choppiness * glm::dvec2(d[0], d[2]);
  if (swell_) {
    const glm::dvec3 moved = swell_->at_rest(p, fields.time_s).position;
    out += glm::dvec2(moved.x, moved.z) - p;
  }
  return out;
}

std::vector<WaveSample> WaveQuery::sample(double time_s, std::span<const glm::dvec2> points) {
  if (direct_) {
    std::vector<WaveSample> out;
    out.reserve(points.size());
    for (const glm::dvec2 q : points) out.push_back(direct_->sample(time_s, q.x, q.y));
    return out;
  }
  evaluate(time_s);
  std::vector<WaveSample> out(points.size());
  // Each point is its own: large batches are split between the query's threads (the same answers).
  constexpr size_t kPointsPerThread = 16384;
  const size_t threads =
      std::clamp<size_t>(points.size() / kPointsPerThread, 1, std::max(1u, options_.threads));
  if (threads == 1) {
    sample_range(*current_, points, out, 0, points.size());
    return out;
  }
  std::vector<std::thread> workers;
  const size_t chunk = (points.size() + threads - 1) / threads;
  for (size_t t = 1; t < threads; ++t)
    workers.emplace_back([&, t] {
      sample_range(*current_, points, out, t * chunk, std::min(points.size(), (t + 1) * chunk));
    });
  sample_range(*current_, points, out, 0, chunk);
  for (std::thread& w : workers) w.join();
  return out;
}

void WaveQuery::sample_range(const Evaluation& fields, std::span<const glm::dvec2> points,
                             std::vector<WaveSample>& out, size_t begin, size_t end) const {
  const double bound = bound_height_ + fields.max_slope * 2 * params_.choppiness * bound_displacement_;
  for (size_t i = begin; i < end; ++i) {
    const glm::dvec2 q = points[i];
    // Fixed point of p = q - λD(p): the rest position whose displaced position is q.
    glm::dvec2 p = q;
    bool converged = false;
    for (int iteration = 0; iteration < 32 && !converged; ++iteration) {
      const glm::dvec2 next = q - displacement(fields, p);
      converged = glm::length(next - p) < 1e-6;
      p = next;
    }
    double f[kFieldCount] = {};
    WaveSample& s = out[i];
    s.rest_position = p;
    s.converged = converged;
    // Each cascade read where its lattice has moved over the floor (ocean/shoaling.h), and the sea's height
    // scale there (its own slope is left out).
    const Shoaling::LatticeMoves moved = moves(p);
    const double scale = moved.sea_scale;
    s.error_bound_m = bound * std::max(1.0, scale);  // higher where the sea shoals
    // Swell trains over the sea: their sums at the same rest point, added (their slopes to the sea's).
    GerstnerPoint swell;
    if (swell_) swell = swell_->at_rest(p, fields.time_s);
    if (options_.heights_only) {
      for (size_t g = 0; g < fields.grids.size(); ++g)
        fields.grids[g]->sample(moved.point[cascade_of_[g]], kHeight, 1, &f[kHeight]);
      s.height = scale * f[kHeight] + swell.position.y;
      continue;
    }
    glm::dvec2 sea_slope(0.0);
    for (size_t g = 0; g < fields.grids.size(); ++g) {
      const size_t c = cascade_of_[g];
      double one[kFieldCount] = {};
      fields.grids[g]->sample(moved.point[c], 0, kFieldCount, one);
      for (int k = 0; k < kFieldCount; ++k) f[k] += one[k];  // the same sums as sampling into f
      // Its slopes through the move (the chain rule); not moved: the deep sea's sum, bit for bit.
      const glm::dvec2 own(one[kSlopeX], one[kSlopeZ]);
      sea_slope = sea_floor_ ? sea_slope + sea_floor_->lattice_slope(c, moved, own)
                             : glm::dvec2(f[kSlopeX], f[kSlopeZ]);
    }
    s.height = scale * f[kHeight] + swell.position.y;
    const glm::dvec2 slope = scale * sea_slope - glm::dvec2(swell.normal.x, swell.normal.z) / swell.normal.y;
    s.normal = glm::normalize(glm::dvec3(-slope.x, 1.0, -slope.y));
    s.velocity =
        scale * glm::dvec3(params_.choppiness * f[kVx], f[kVy], params_.choppiness * f[kVz]) + swell.velocity;
  }
}

WaveSample WaveQuery::sample(double time_s, double x, double z) {
  const glm::dvec2 p(x, z);
  return sample(time_s, std::span<const glm::dvec2>(&p, 1))[0];
}

}  // namespace lagoon::ocean
