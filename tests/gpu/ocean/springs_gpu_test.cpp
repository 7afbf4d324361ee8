// Model springs on the GPU (ocean/gpu/springs_gpu.h): after 100 steps with drops, a moving gust and the
// driven column, the first cascade's height equals the CPU double reference (ocean/springs.h) to a relative
// L2 of 1e-5, its normal is the grid's central differences, the other cascades stay still, and going back in
// time starts again from rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ocean/gpu/gpu_ocean.h"
#include "ocean/springs.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using SpringsGpuTest = GpuTest;

ocean::OceanParams excited_grid() {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Springs;
  p.choppiness = 0;
  p.cascades = {{128, 128}, {16, 64}};
  p.springs.drops = {{.x_m = 40, .z_m = 70, .time_s = 0, .radius_m = 3, .speed_mps = 1.5},
                     {.x_m = 100, .z_m = 20, .time_s = 10, .radius_m = 5, .speed_mps = -1}};
  p.springs.gusts = {{.x_m = 60,
                      .z_m = 60,
                      .time_s = 5,
                      .duration_s = 8,
                      .radius_m = 6,
                      .force_n = 3,
                      .direction_deg = 30,
                      .speed_mps = 2}};
  p.springs.boundary_amplitude_m = 0.3;
  p.springs.boundary_period_s = 7;
  return p;
}

// Relative L2 of the GPU's heights against the CPU's at `time_s`.
double height_error(const ocean::CascadeReadback& r, const std::vector<glm::dvec2>& cpu) {
  double diff = 0, norm = 0;
  for (size_t i = 0; i < cpu.size(); ++i) {
    diff += std::pow(r.displacement[i * 4 + 1] - cpu[i].x, 2);
    norm += cpu[i].x * cpu[i].x;
  }
  return std::sqrt(diff / norm);
}

TEST_F(SpringsGpuTest, HundredStepsMatchTheCpuReference) {
  const ocean::OceanParams p = excited_grid();
  auto gpu = ocean::GpuOcean::create(ctx(), p);
  ASSERT_TRUE(gpu) << gpu.error().message;
  ocean::SpringGrid cpu(p);
  const double t = 99.5 * p.springs.step_s;  // 100 steps, the picture half a step before the last
  // Two records: the state carries over between them.
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, 20.1, 0.0); });
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, t - 20.1); });
  const std::vector<glm::dvec2> expected = cpu.surface_at(t);
  ASSERT_EQ(cpu.steps(), 100u);
  const ocean::CascadeReadback r = (*gpu)->read_cascade(0);
  const double error = height_error(r, expected);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", error);
  RecordProperty("relative_l2_after_100_steps", text);
  EXPECT_LT(error, 1e-5);

  double worst_normal = 0, worst_horizontal = 0;
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      auto h = [&](int a, int b) { return expected[size_t((b + 128) % 128) * 128 + (a + 128) % 128].x; };
      const glm::dvec3 n =
          glm::normalize(glm::dvec3(-(h(i + 1, j) - h(i - 1, j)) / 2, 1, -(h(i, j + 1) - h(i, j - 1)) / 2));
      const float* got = &r.normal_jacobian[(size_t(j) * 128 + i) * 4];
      worst_normal = std::max(worst_normal, glm::length(glm::dvec3(got[0], got[1], got[2]) - n));
      EXPECT_FLOAT_EQ(got[3], 1.0f);  // J: the nodes move only vertically
      const float* d = &r.displacement[(size_t(j) * 128 + i) * 4];
      worst_horizontal = std::max({worst_horizontal, double(std::abs(d[0])), double(std::abs(d[2]))});
    }
  EXPECT_LT(worst_normal, 1e-5);
  EXPECT_EQ(worst_horizontal, 0.0);
  const ocean::CascadeReadback still = (*gpu)->read_cascade(1);
  double largest = 0;
  for (float v : still.displacement) largest = std::max(largest, double(std::abs(v)));
  EXPECT_EQ(largest, 0.0) << "the second cascade must stay still";
}

TEST_F(SpringsGpuTest, GoingBackInTimeStartsAgainFromRest) {
  const ocean::OceanParams p = excited_grid();
  auto gpu = ocean::GpuOcean::create(ctx(), p);
  ASSERT_TRUE(gpu) << gpu.error().message;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, 30.0, 0.0); });
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, 12.2, 0.0); });
  ocean::SpringGrid cpu(p);
  EXPECT_LT(height_error((*gpu)->read_cascade(0), cpu.surface_at(12.2)), 1e-5);
}

}  // namespace
}  // namespace lagoon::test
