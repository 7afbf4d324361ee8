// The dynamic wave layer on the GPU (compute/ocean/gpu/dynamic_layer_gpu.h) against its CPU reference in
// double precision (compute/ocean/dynamic_layer.h): 100 steps of two moving hulls, one submerged, with the
// window following them, agree within a relative L2 of 1e-4, and the foam trail within 1e-4; the fields image
// holds the same heights, their central-difference slopes and the foam.
#include "ocean/gpu/dynamic_layer_gpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "support/vk_fixture.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

class DynamicLayerGpuTest : public GpuTest {};

TEST_F(DynamicLayerGpuTest, HundredStepsMatchTheCpuReference) {
  const ocean::DynamicLayerParams params{.n = 128, .cell_m = 0.25, .depth_m = 6.0, .sponge_m = 4};
  ocean::DynamicLayerCpu cpu(params, 2);
  ocean::DynamicLayerGpu gpu(ctx(), params);
  std::vector<ocean::WakeSource> hulls{{.centre = {1000, -490},
                                        .velocity = {-1.5, 0},
                                        .heading = -1.57,
                                        .sigma = {0.6, 0.2},
                                        .depression = 0.2,
                                        .depth = 0.8},
                                       {.centre = {1012, -488},
                                        .velocity = {2.5, 1.0},
                                        .heading = 1.95,  // along its velocity: pi - atan2(1.0, 2.5)
                                        .sigma = {1.2, 0.5},
                                        .depression = 0.25,
                                        .foam_per_s = 6}};
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    for (int s = 0; s < 100; ++s) {
      // Far from the origin, as in a scene, and moving with the surface hull (the second: the GPU puts the
      // sources that leave foam first).
      const glm::ivec2 window(int(std::floor(hulls[1].centre.x / params.cell_m)) - 64,
                              int(std::floor(hulls[1].centre.y / params.cell_m)) - 64);
      cpu.set_window(window);
      gpu.set_window(window);
      cpu.step(1.0 / 30, hulls);
      gpu.record_step(cmd, 1.0 / 30, hulls);
      for (ocean::WakeSource& h : hulls) h.centre += h.velocity / 30.0;
    }
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<std::byte> raw = vk::readback_buffer(ctx(), gpu.state());
  const float* f = reinterpret_cast<const float*>(raw.data());
  double diff = 0, norm = 0, largest = 0;
  for (size_t i = 0; i < cpu.state().size(); ++i) {
    const std::complex<double> g(f[2 * i], f[2 * i + 1]), c = cpu.state()[i];
    diff += std::norm(g - c);
    norm += std::norm(c);
    largest = std::max(largest, std::abs(c.real()));
  }
  const double error = std::sqrt(diff / norm);
  RecordProperty("relative_l2", std::to_string(error));
  EXPECT_GT(largest, 0.02) << "the hulls made no waves: nothing was compared";
  EXPECT_LT(error, 1e-4);

  // The foam trails.
  const std::vector<std::byte> foam_raw = vk::readback_buffer(ctx(), gpu.foam());
  const float* foam = reinterpret_cast<const float*>(foam_raw.data());
  double foam_error = 0, foam_total = 0;
  for (size_t i = 0; i < cpu.foam().size(); ++i) {
    foam_error = std::max(foam_error, std::abs(foam[i] - cpu.foam()[i]));
    foam_total += cpu.foam()[i];
  }
  EXPECT_GT(foam_total, 50.0) << "no trail: nothing was compared";
  EXPECT_LT(foam_error, 1e-4);

  // The fields: h, and the slopes the renderer uses, from the damped state; and the foam.
  const std::vector<std::byte> image =
      vk::readback_image(ctx(), gpu.fields(), VK_IMAGE_LAYOUT_GENERAL, vk::access::kComputeWrite);
  const float* texel = reinterpret_cast<const float*>(image.data());
  const int n = int(params.n);
  double worst_h = 0, worst_slope = 0, steepest = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float* t = texel + 4 * (size_t(j) * n + i);
      const double dx = (cpu.height(i + 1, j) - cpu.height(i - 1, j)) / (2 * params.cell_m);
      const double dz = (cpu.height(i, j + 1) - cpu.height(i, j - 1)) / (2 * params.cell_m);
      worst_h = std::max(worst_h, std::abs(t[0] - cpu.height(i, j)));
      EXPECT_NEAR(t[3], cpu.foam(i, j), 1e-4);
      worst_slope = std::max({worst_slope, std::abs(t[1] - dx), std::abs(t[2] - dz)});
      steepest = std::max({steepest, std::abs(dx), std::abs(dz)});
    }
  EXPECT_LT(worst_h, 1e-4 * largest);
  EXPECT_LT(worst_slope, 1e-3 * steepest);
}

// A catch-up writes the fields image at its last step only (Fields::Keep before): the image a frame draws is
// the one every step would have left, and a kept step leaves it alone while the state moves on.
TEST_F(DynamicLayerGpuTest, ACatchUpWritesTheFieldsOfItsLastStepOnly) {
  const ocean::DynamicLayerParams params{.n = 64, .cell_m = 0.5, .sponge_m = 4};
  ocean::DynamicLayerGpu every(ctx(), params), last(ctx(), params);
  const std::vector<ocean::WakeSource> hull{{.centre = {8, 4},
                                             .velocity = {2, 0},
                                             .heading = 1.57,
                                             .sigma = {1, 0.4},
                                             .depression = 0.2,
                                             .foam_per_s = 4}};
  auto run = [&](ocean::DynamicLayerGpu& layer, int steps, bool keep_all_but_last) {
    ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      for (int s = 0; s < steps; ++s)
        layer.record_step(cmd, 0.1, hull,
                          keep_all_but_last && s + 1 < steps ? ocean::DynamicLayerGpu::Fields::Keep
                                                             : ocean::DynamicLayerGpu::Fields::Write);
      vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
    });
  };
  auto fields = [&](const ocean::DynamicLayerGpu& layer) {
    const std::vector<std::byte> raw =
        vk::readback_image(ctx(), layer.fields(), VK_IMAGE_LAYOUT_GENERAL, vk::access::kComputeWrite);
    const float* f = reinterpret_cast<const float*>(raw.data());
    return std::vector<float>(f, f + raw.size() / sizeof(float));
  };
  run(every, 30, false);
  run(last, 30, true);
  const std::vector<float> a = fields(every), b = fields(last);
  double largest = 0, worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, double(std::abs(a[i])));
    worst = std::max(worst, double(std::abs(a[i] - b[i])));
  }
  EXPECT_GT(largest, 0.01) << "the hull made nothing to compare";
  EXPECT_LT(worst, 1e-6 * largest);
  // One more step that keeps the fields: the image is the previous step's, though the waves moved.
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    last.record_step(cmd, 0.1, hull, ocean::DynamicLayerGpu::Fields::Keep);
    every.record_step(cmd, 0.1, hull);
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<float> kept = fields(last), moved = fields(every);
  double kept_change = 0, moved_change = 0;
  for (size_t i = 0; i < b.size(); ++i) {
    kept_change = std::max(kept_change, double(std::abs(kept[i] - b[i])));
    moved_change = std::max(moved_change, double(std::abs(moved[i] - a[i])));
  }
  EXPECT_LT(kept_change, 1e-7 * largest);
  EXPECT_GT(moved_change, 1e-3 * largest);
}

}  // namespace
}  // namespace lagoon::test
