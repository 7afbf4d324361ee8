// FieldCheck (lagoon soak's NaN/Inf check) against a CPU count over the read-back fields, on a clean ocean
// and on one whose spectrum holds a NaN in a single mode of one cascade.
#include "ocean/gpu/field_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ocean/initial_spectrum.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class FieldCheckTest : public GpuTest {
 protected:
  static ocean::OceanParams params() {
    ocean::OceanParams p;
    p.cascades = {{500.0, 64}, {50.0, 64}, {5.0, 128}};
    return p;
  }

  // Steps `gpu` twice, counting on the GPU after each step; returns the count and the CPU count of the
  // last step's mip 0 over the three textures of every cascade.
  std::pair<uint64_t, uint64_t> run(ocean::GpuOcean& gpu) {
    ocean::FieldCheck check(ctx());
    ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      gpu.record_step(cmd, 1.0, 0.0);
      check.record(cmd, gpu);
    });
    EXPECT_EQ(check.take(), cpu_count(gpu)) << "after the first step";
    ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      gpu.record_step(cmd, 1.5, 0.5);
      check.record(cmd, gpu);
    });
    return {check.take(), cpu_count(gpu)};
  }

  static uint64_t cpu_count(ocean::GpuOcean& gpu) {
    uint64_t count = 0;
    for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
      const ocean::CascadeReadback r = gpu.read_cascade(c);
      for (size_t t = 0; t < r.displacement.size() / 4; ++t) {
        bool finite = true;
        for (size_t k = 0; k < 4; ++k)
          finite = finite && std::isfinite(r.displacement[4 * t + k]) &&
                   std::isfinite(r.normal_jacobian[4 * t + k]) && std::isfinite(r.jacobian_terms[4 * t + k]);
        count += finite ? 0 : 1;
      }
    }
    return count;
  }
};

TEST_F(FieldCheckTest, CountsNothingOnAHealthyOcean) {
  ocean::GpuOcean gpu(ctx(), params());
  const auto [gpu_count, cpu] = run(gpu);
  EXPECT_EQ(cpu, 0u);
  EXPECT_EQ(gpu_count, 0u);
}

TEST_F(FieldCheckTest, CountsEveryTexelOfACascadeWhoseSpectrumHoldsANaN) {
  const ocean::OceanParams p = params();
  std::vector<ocean::CascadeSpectrum> spectra;
  for (uint32_t c = 0; c < 3; ++c) spectra.push_back(ocean::make_cascade_spectrum(p, c));
  // One mode of the middle cascade: the inverse FFT spreads it over all of that cascade's samples.
  spectra[1].h0[3 * 64 + 5] = {std::numeric_limits<float>::quiet_NaN(), 0.0f};
  ocean::GpuOcean gpu(ctx(), p, spectra);
  const auto [gpu_count, cpu] = run(gpu);
  EXPECT_EQ(cpu, 64u * 64u);
  EXPECT_EQ(gpu_count, cpu);
}

}  // namespace
}  // namespace lagoon::test
