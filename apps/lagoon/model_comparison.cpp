#include "model_comparison.h"

#include <cmath>
#include <numbers>

#include "bench_report.h"
#include "ocean/direct_waves.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/initial_spectrum.h"
#include "ocean/springs.h"
#include "render/ocean_renderer.h"
#include "vk/gpu_timer.h"

namespace lagoon::cli {
namespace {

std::vector<ocean::HeightGrid> read_heights(const ocean::GpuOcean& gpu) {
  std::vector<ocean::HeightGrid> grids;
  for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
    const ocean::CascadeReadback r = gpu.read_cascade(c);
    ocean::HeightGrid g{.n = r.resolution, .patch_m = gpu.cascade(c).patch_size_m};
    g.height.resize(size_t{r.resolution} * r.resolution);
    for (size_t i = 0; i < g.height.size(); ++i) g.height[i] = r.displacement[i * 4 + 1];
    grids.push_back(std::move(g));
  }
  return grids;
}

// ω of the peak mode by the model's own law: the springs' lattice, or the ω the cascade's modes turn at.
double peak_omega(const ocean::GpuOcean& gpu, const ocean::ModeEnergy& e, glm::dvec2 k) {
  const ocean::OceanParams& p = gpu.params();
  if (p.model == ocean::SurfaceModel::Springs)
    return ocean::springs_omega(p.springs, e.patch_m / e.n, k.x, k.y);
  const ocean::CascadeSpectrum& s = gpu.spectra().front();
  const double dk = 2 * std::numbers::pi / e.patch_m;
  const long ix = std::lround(k.x / dk), iz = std::lround(k.y / dk), n = long(e.n);
  return s.omega[size_t((iz + n) % n) * e.n + size_t((ix + n) % n)];
}

// Waves summed directly (ocean/direct_waves.h) hold no lattice: the peak is the largest wave itself, and the
// tiling is measured on the sum, not on the step's layer (whose grid would wrap onto itself).
struct DirectPeak {
  double wavelength_m = 0, omega = 0;
};
DirectPeak direct_peak(const ocean::GerstnerSurface& s) {
  size_t best = 0;
  for (size_t i = 1; i < s.size(); ++i)
    if (s.params().waves[i].amplitude_m > s.params().waves[best].amplitude_m) best = i;
  return {s.params().waves[best].wavelength_m, s.omega(best)};
}

// The correlation of h(x0) and h(x0 + lag) over 128² rest points of [0, lag)², both axes' lags averaged, as
// ocean::tiling_correlation does for the cascades' grids.
double direct_tiling(const ocean::GerstnerSurface& s, double lag, double time_s) {
  constexpr int kSamples = 128;
  double sum = 0;
  for (const glm::dvec2 step : {glm::dvec2(lag, 0), glm::dvec2(0, lag)}) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (int j = 0; j < kSamples; ++j)
      for (int i = 0; i < kSamples; ++i) {
        const glm::dvec2 x0 = glm::dvec2(i, j) * (lag / kSamples);
        const double a = s.at_rest(x0, time_s).position.y, b = s.at_rest(x0 + step, time_s).position.y;
        sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b;
      }
    const double n = kSamples * kSamples, cov = sab / n - sa * sb / (n * n);
    const double va = saa / n - sa * sa / (n * n), vb = sbb / n - sb * sb / (n * n);
    sum += va > 0 && vb > 0 ? cov / std::sqrt(va * vb) : 1.0;
  }
  return sum / 2;
}

bool has_target_spectrum(const ocean::OceanParams& p) {
  using ocean::SurfaceModel;
  return p.model == SurfaceModel::Fft ||
         (p.model == SurfaceModel::Gerstner && p.gerstner.spectrum_waves > 0) ||
         (p.model == SurfaceModel::Sines && p.sines.spectrum_waves > 0);
}

}  // namespace

StepTime time_model_step(vk::Context& ctx, const ocean::OceanParams& params, int rounds) {
  ocean::GpuOcean gpu(ctx, params);
  vk::GpuTimer timer(ctx, 1);
  const double dt = params.model == ocean::SurfaceModel::Springs ? params.springs.step_s : 1 / 60.0;
  double t = 0;
  StepTime out;
  for (int r = -3; r < rounds; ++r) {  // 3 to warm up (JIT, caches)
    t += dt;
    const double ms = time_ms([&] {
      ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        timer.reset(cmd);
        vk::GpuScope scope(timer, cmd, "ocean step");
        gpu.record_step(cmd, t, dt);
      });
    });
    if (r < 0) continue;
    out.wall_rounds.push_back(ms);
    if (const auto d = timer.results(); !d.empty()) out.device_rounds.push_back(d[0].ms);
  }
  out.wall_ms = median(out.wall_rounds);
  out.device_ms = out.device_rounds.empty() ? out.wall_ms : median(out.device_rounds);
  return out;
}

ModelMeasure measure_model(vk::Context& ctx, const scene::Scene& scene, int rounds) {
  ModelMeasure out;
  out.model = ocean::to_string(scene.ocean.model);
  const StepTime step = time_model_step(ctx, scene.ocean, rounds);
  out.step_ms = step.device_ms;
  out.step_wall_ms = step.wall_ms;

  auto renderer = render::OceanRenderer::create(ctx, scene);
  if (!renderer) throw std::runtime_error(renderer.error().message);
  (*renderer)->render(scene);  // the first frame compiles and warms up
  std::vector<vk::PassTime> timings;
  out.render = (*renderer)->render(scene, &timings);
  for (const vk::PassTime& t : timings)
    if (t.name == "surface") out.surface_ms += t.ms;
  const ocean::GpuOcean& gpu = (*renderer)->ocean();
  const std::vector<ocean::HeightGrid> grids = read_heights(gpu);
  out.hs_m = ocean::significant_height(grids);
  out.spectrum = ocean::mode_energy(grids.front());
  const glm::dvec2 k = ocean::peak_wavevector(out.spectrum);
  out.peak_wavelength_m = 2 * std::numbers::pi / std::hypot(k.x, k.y);
  double omega = peak_omega(gpu, out.spectrum, k);
  out.tiling = ocean::tiling_correlation(grids, grids.front().patch_m);
  if (const ocean::GerstnerSurface* direct =
          ocean::evaluated_directly(scene.ocean) ? gpu.direct_waves() : nullptr) {
    const DirectPeak peak = direct_peak(*direct);
    out.peak_wavelength_m = peak.wavelength_m;
    omega = peak.omega;
    out.tiling = direct_tiling(*direct, grids.front().patch_m, scene.time_s);
  }
  out.peak_period_s = omega > 0 ? 2 * std::numbers::pi / omega : 0.0;
  if (has_target_spectrum(scene.ocean)) {
    const ocean::CascadeBand band = ocean::cascade_bands(scene.ocean).front();
    out.spectrum_error =
        ocean::band_energies(out.spectrum, scene.ocean,
                             std::max(band.k_min, 2 * std::numbers::pi / grids.front().patch_m), band.k_max)
            .relative_error;
  }
  return out;
}

}  // namespace lagoon::cli
