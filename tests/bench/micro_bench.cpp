// Google Benchmark programs for the CPU hot paths the physics and the set-up run every frame or every step
// (`lagoon bench` measures whole frames and GPU passes; these measure one function each, so a change to one
// can be compared side by side with the build before it: docs/building.md, "Benchmarks"). Speed is never
// asserted in a test; ctest only runs each of these once (bench.Micro) so they keep building and running.
#include <benchmark/benchmark.h>

#include <complex>
#include <random>
#include <vector>

#include "fft/cpu_fft.h"
#include "ocean/dynamic_layer.h"
#include "ocean/initial_spectrum.h"
#include "ocean/local_heights.h"
#include "ocean/wave_query.h"
#include "physics/hydrostatics.h"

namespace lagoon {
namespace {

// The default sea's three cascades of 256² (what every scene's set-up builds).
void BM_CascadeSpectra(benchmark::State& state) {
  const ocean::OceanParams p;
  for (auto _ : state)
    for (uint32_t c = 0; c < p.cascades.size(); ++c)
      benchmark::DoNotOptimize(ocean::make_cascade_spectrum(p, c));
}
BENCHMARK(BM_CascadeSpectra)->Unit(benchmark::kMillisecond);

// One n x n complex double transform (WaveQuery's fields, the CPU wake layer).
void BM_CpuFft2d(benchmark::State& state) {
  const uint32_t n = uint32_t(state.range(0));
  const fft::CpuFft2d fft(n, true);
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  std::vector<std::complex<double>> data(size_t(n) * n);
  for (auto& c : data) c = {g(rng), g(rng)};
  for (auto _ : state) {
    fft.transform(data, 1);
    benchmark::DoNotOptimize(data.data());
  }
}
BENCHMARK(BM_CpuFft2d)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);

// One step of the CPU wake layer (the heights the bodies feel, world/wake_heights.h) with a hull under way.
void BM_DynamicLayerStep(benchmark::State& state) {
  ocean::DynamicLayerParams p;
  p.n = uint32_t(state.range(0));
  p.cell_m = 128.0 / p.n;
  ocean::DynamicLayerCpu layer(p, 1);
  layer.set_foam(false);
  ocean::WakeSource s;
  s.velocity = {0.0, -4.0};
  s.sigma = {2.0, 1.0};
  s.depression = 0.3;
  s.depth = 0.5;
  double t = 0;
  for (auto _ : state) {
    s.centre = s.velocity * t;
    layer.step(0.1, std::span(&s, 1));
    t += 0.1;
  }
}
BENCHMARK(BM_DynamicLayerStep)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

// The exact sea at one point (WaveQuery: every mode of every cascade), at a new time each call.
void BM_WaveQuerySample(benchmark::State& state) {
  const ocean::OceanParams p;
  ocean::WaveQuery query(p, 1);
  double t = 3.0;
  for (auto _ : state) benchmark::DoNotOptimize(query.sample(t += 0.2, 1.5, -2.5));
}
BENCHMARK(BM_WaveQuerySample)->Unit(benchmark::kMillisecond);

// One knot of the sea the bodies feel (world/floating_objects.cpp's query: band-limited to the lattice's
// waves, heights and displacements only): the fields a new time costs, at a new time each call.
void BM_WaveQueryKnot(benchmark::State& state) {
  const ocean::OceanParams p;
  ocean::WaveQuery query(
      p, ocean::make_cascade_spectra(p),
      ocean::WaveQueryOptions{
          .threads = 1, .max_wavenumber = ocean::lattice_wavenumber({}), .heights_only = true});
  double t = 3.0;
  for (auto _ : state) benchmark::DoNotOptimize(query.sample(t += 0.2, 1.5, -2.5));
}
BENCHMARK(BM_WaveQueryKnot)->Unit(benchmark::kMillisecond);

// A body's heights from its local lattice (ocean/local_heights.h): the bicubic lookup a hull's vertices make.
void BM_LocalHeights(benchmark::State& state) {
  const ocean::OceanParams p;
  ocean::LocalHeights local(p, ocean::make_cascade_spectra(p), {});
  local.update(2.0, {0.0, 0.0});
  std::vector<glm::dvec2> points;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) points.push_back({-2.0 + 0.25 * i + 0.01 * j, -2.0 + 0.25 * j});
  std::vector<double> heights(points.size());
  for (auto _ : state) {
    local.heights(points, heights);
    benchmark::DoNotOptimize(heights.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(points.size()));
}
BENCHMARK(BM_LocalHeights);

// A 4 x 2 x 1 m box, each face cut into m x m squares (2 m² triangles), half in a gently waving sea.
void box(int m, std::vector<glm::dvec3>& vertices, std::vector<uint32_t>& indices) {
  const glm::dvec3 half(2.0, 0.5, 1.0);
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const uint32_t first = uint32_t(vertices.size());
      for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= m; ++i) {
          glm::dvec3 q(0.0);
          q[axis] = sign * half[axis];
          q[u] = (-1.0 + 2.0 * i / m) * half[u];
          q[v] = (-1.0 + 2.0 * j / m) * half[v];
          vertices.push_back(q);
        }
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          const uint32_t a = first + uint32_t(j * (m + 1) + i), b = a + 1, c = a + uint32_t(m + 1), d = c + 1;
          // Outward normals: the (u, v) winding flips with the face's sign.
          if (sign > 0)
            indices.insert(indices.end(), {a, b, d, a, d, c});
          else
            indices.insert(indices.end(), {a, d, b, a, c, d});
        }
    }
}

void BM_HullPressure(benchmark::State& state) {
  std::vector<glm::dvec3> hull;
  std::vector<uint32_t> indices;
  box(int(state.range(0)), hull, indices);
  physics::HullPressure pressure(hull, indices);
  const physics::WaterHeights heights = [](std::span<const glm::dvec2> points, std::span<double> out) {
    for (size_t i = 0; i < points.size(); ++i) out[i] = 0.2 * std::sin(0.7 * points[i].x + 0.3 * points[i].y);
  };
  physics::HullPressure::Water water{.heights = &heights, .top = 0.2};
  const glm::dmat3 rotation(1.0);
  const glm::dvec3 centre(0.0);
  for (auto _ : state) benchmark::DoNotOptimize(pressure.wrench(hull, rotation, centre, water, 1025.0, 9.81));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(indices.size() / 3));
}
BENCHMARK(BM_HullPressure)->Arg(1)->Arg(8)->Arg(32);

}  // namespace
}  // namespace lagoon

BENCHMARK_MAIN();
