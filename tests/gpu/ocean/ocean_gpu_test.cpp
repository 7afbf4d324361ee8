// The GPU ocean step against its CPU double-precision reference (FFTW) and against physics.
#include "ocean/gpu/gpu_ocean.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/cpu_step.h"
#include "ocean/spectrum.h"
#include "support/fftw_reference.h"
#include "support/vk_fixture.h"
#include "vk/transfer.h"

#include <cstring>
#include <glm/gtc/packing.hpp>

namespace lagoon::test {
namespace {

using ocean::OceanParams;

class OceanGpu : public GpuTest {
 protected:
  // Runs the steps on the GPU and returns the readback of every cascade after the last one.
  std::vector<ocean::CascadeReadback> run_gpu(ocean::GpuOcean& gpu_ocean,
                                              std::initializer_list<double> times) {
    double previous = 0;
    for (double t : times) {
      ctx().submit_and_wait([&](VkCommandBuffer cmd) { gpu_ocean.record_step(cmd, t, t - previous); });
      previous = t;
    }
    std::vector<ocean::CascadeReadback> out;
    for (uint32_t c = 0; c < gpu_ocean.cascade_count(); ++c) out.push_back(gpu_ocean.read_cascade(c));
    return out;
  }
};

ocean::InverseFft2d fftw_inverse() {
  return [](std::vector<std::complex<double>>& data, uint32_t n, uint32_t batches) {
    fftw_2d(data, int(n), int(batches), true);
  };
}

// Relative L2 error of component `comp` (of 4) between GPU floats and CPU doubles.
double component_error(const std::vector<float>& gpu, const std::vector<double>& cpu, int comp) {
  double diff = 0, ref = 0;
  for (size_t i = comp; i < cpu.size(); i += 4) {
    diff += (gpu[i] - cpu[i]) * (gpu[i] - cpu[i]);
    ref += cpu[i] * cpu[i];
  }
  return std::sqrt(diff / ref);
}

OceanParams test_params() {
  OceanParams p;
  p.choppiness = 1.5;
  p.foam.threshold = 0.9;  // enough foam that its comparison means something
  p.foam.decay_per_s = 0.7;
  // Three resolutions, one of them twice: exercises grouping and the radix-4 and radix-8 remainders.
  p.cascades = {{1000.0, 128}, {100.0, 128}, {12.0, 64}};
  return p;
}

class OceanGpuVariant : public OceanGpu, public ::testing::WithParamInterface<ocean::FftVariant> {};

TEST_P(OceanGpuVariant, EveryFieldMatchesTheCpuReference) {
  OceanParams params = test_params();
  if (GetParam() == ocean::FftVariant::Workgroup) params.cascades.push_back({1.5, 512});  // 3 stages, radix 2
  ocean::GpuOcean gpu_ocean(ctx(), params, GetParam());
  ocean::CpuOceanStep cpu(params, gpu_ocean.spectra(), fftw_inverse());
  // Times are exact in float, so both sides evolve to the same instant; the second step decays foam.
  const auto gpu = run_gpu(gpu_ocean, {1.25, 1.75, 2.5});
  double previous = 0;
  for (double t : {1.25, 1.75, 2.5}) cpu.step(t, t - previous), previous = t;

  const char* names[3][4] = {
      {"dx", "height", "dz", "foam"}, {"nx", "ny", "nz", "jacobian"}, {"dDx/dx", "dDz/dz", "dDx/dz", "foam"}};
  for (size_t c = 0; c < gpu.size(); ++c) {
    for (int comp = 0; comp < 4; ++comp) {
      // The foam's fade rounds (foam + 0.4) (shared/foam.h), not the foam alone: 3e-5 for it.
      EXPECT_LT(component_error(gpu[c].displacement, cpu.cascades()[c].displacement, comp),
                comp == 3 ? 3e-5 : 1e-5)
          << "cascade " << c << " " << names[0][comp];
      EXPECT_LT(component_error(gpu[c].normal_jacobian, cpu.cascades()[c].normal_jacobian, comp), 1e-5)
          << "cascade " << c << " " << names[1][comp];
      // Half floats: 11-bit mantissas.
      EXPECT_LT(component_error(gpu[c].jacobian_terms, cpu.cascades()[c].jacobian_terms, comp), 1e-3)
          << "cascade " << c << " " << names[2][comp];
    }
  }
  // The comparison above is only meaningful with foam present and waves that compress the surface.
  double foam = 0;
  for (size_t i = 3; i < gpu[0].displacement.size(); i += 4) foam += gpu[0].displacement[i];
  EXPECT_GT(foam, 0.0);
}

// A still frame's warm-up (GpuOcean::Step::WarmUp) brings only the foam to its time, skipping what nobody
// samples: the foam after warm-up steps and a full one is the CPU reference's after the same steps.
TEST_P(OceanGpuVariant, WarmUpStepsGiveTheFoamOfFullSteps) {
  const OceanParams params = test_params();
  ocean::GpuOcean gpu_ocean(ctx(), params, GetParam());
  ocean::CpuOceanStep cpu(params, gpu_ocean.spectra(), fftw_inverse());
  double previous = 0;
  for (double t : {1.25, 1.75, 2.0}) {
    ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      gpu_ocean.record_step(cmd, t, t - previous, nullptr, ocean::GpuOcean::Step::WarmUp);
    });
    cpu.step(t, t - previous), previous = t;
  }
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { gpu_ocean.record_step(cmd, 2.5, 0.5); });
  cpu.step(2.5, 0.5);
  std::vector<ocean::CascadeReadback> gpu;
  for (uint32_t c = 0; c < gpu_ocean.cascade_count(); ++c) gpu.push_back(gpu_ocean.read_cascade(c));
  double foam = 0;
  for (size_t c = 0; c < gpu.size(); ++c) {
    EXPECT_LT(component_error(gpu[c].displacement, cpu.cascades()[c].displacement, 3), 1e-5)
        << "cascade " << c << " foam";
    EXPECT_LT(component_error(gpu[c].jacobian_terms, cpu.cascades()[c].jacobian_terms, 3), 1e-3)
        << "cascade " << c << " foam (half floats)";
    for (size_t i = 3; i < gpu[c].displacement.size(); i += 4) foam += gpu[c].displacement[i];
  }
  EXPECT_GT(foam, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Variants, OceanGpuVariant,
                         ::testing::Values(ocean::FftVariant::Stockham, ocean::FftVariant::Workgroup),
                         [](const auto& info) {
                           return info.param == ocean::FftVariant::Stockham ? "Stockham" : "Workgroup";
                         });

// Every texel of a mip level as floats (RGBA32F or RGBA16F), all layers.
std::vector<float> read_level(vk::Context& ctx, const vk::Image& image, uint32_t mip) {
  const vk::Access writer{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT};
  const std::vector<std::byte> bytes = vk::readback_image(ctx, image, VK_IMAGE_LAYOUT_GENERAL, writer, mip);
  std::vector<float> out;
  if (image.format() == VK_FORMAT_R16G16B16A16_SFLOAT) {
    out.resize(bytes.size() / 2);
    for (size_t i = 0; i < out.size(); ++i) {
      uint16_t h = 0;
      std::memcpy(&h, bytes.data() + 2 * i, 2);
      out[i] = glm::unpackHalf1x16(h);
    }
  } else {
    out.resize(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), bytes.size());
  }
  return out;
}

TEST_F(OceanGpu, MipLevelsAreTheMeanOfTheirParents) {
  const OceanParams params = test_params();
  ocean::GpuOcean gpu_ocean(ctx(), params);
  run_gpu(gpu_ocean, {1.5});
  const ocean::CascadeTextures t = gpu_ocean.cascade(0);
  for (const vk::Image* image : {t.displacement, t.normal_jacobian, t.jacobian_terms}) {
    const bool half = image->format() == VK_FORMAT_R16G16B16A16_SFLOAT;
    for (uint32_t mip : {1u, 2u, image->mip_levels() - 1}) {
      const std::vector<float> parent = read_level(ctx(), *image, mip - 1),
                               level = read_level(ctx(), *image, mip);
      const uint32_t n = std::max(image->extent().width >> mip, 1u), pn = n * 2;
      const uint32_t layers = image->layers();
      ASSERT_EQ(level.size(), size_t(n) * n * 4 * layers);
      double diff = 0, ref = 0;
      for (uint32_t layer = 0; layer < layers; ++layer)
        for (uint32_t z = 0; z < n; ++z)
          for (uint32_t x = 0; x < n; ++x)
            for (uint32_t c = 0; c < 4; ++c) {
              auto at = [&](uint32_t px, uint32_t pz) {
                return double(parent[((size_t(layer) * pn + pz) * pn + px) * 4 + c]);
              };
              const double mean = 0.25 * (at(2 * x, 2 * z) + at(2 * x + 1, 2 * z) + at(2 * x, 2 * z + 1) +
                                          at(2 * x + 1, 2 * z + 1));
              const double got = level[((size_t(layer) * n + z) * n + x) * 4 + c];
              diff += (got - mean) * (got - mean);
              ref += mean * mean;
            }
      EXPECT_LT(std::sqrt(diff / std::max(ref, 1e-30)), half ? 2e-3 : 1e-6) << "mip " << mip;
    }
  }
}

TEST_F(OceanGpu, RepeatedRunsAreBitIdentical) {
  const OceanParams params = test_params();
  ocean::GpuOcean a(ctx(), params), b(ctx(), params);
  const auto ra = run_gpu(a, {3.0}), rb = run_gpu(b, {3.0});
  for (size_t c = 0; c < ra.size(); ++c) {
    EXPECT_EQ(ra[c].displacement, rb[c].displacement) << "cascade " << c;
    EXPECT_EQ(ra[c].normal_jacobian, rb[c].normal_jacobian) << "cascade " << c;
    EXPECT_EQ(ra[c].jacobian_terms, rb[c].jacobian_terms) << "cascade " << c;
  }
}

TEST_F(OceanGpu, LoopPeriodRepeatsTheFields) {
  OceanParams params = test_params();
  params.loop_period_s = 20.0;
  ocean::GpuOcean gpu_ocean(ctx(), params);
  auto height = [](const ocean::CascadeReadback& r) {
    std::vector<double> h;
    for (size_t i = 1; i < r.displacement.size(); i += 4) h.push_back(r.displacement[i]);
    return h;
  };
  auto rel = [](const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0, n = 0;
    for (size_t i = 0; i < a.size(); ++i) d += (a[i] - b[i]) * (a[i] - b[i]), n += b[i] * b[i];
    return std::sqrt(d / n);
  };
  const auto h0 = height(run_gpu(gpu_ocean, {1.5})[0]);
  const auto h1 = height(run_gpu(gpu_ocean, {21.5})[0]);
  const auto half = height(run_gpu(gpu_ocean, {11.5})[0]);
  EXPECT_LT(rel(h1, h0), 1e-4);   // float ω·t over one period: ~1e-5
  EXPECT_GT(rel(half, h0), 0.3);  // and the fields did change in between
}

// One wave mode alone: its complex amplitude must rotate by -ω(k)·t, ω from the closed-form dispersion law.
struct ModeCase {
  const char* name;
  double depth_m, patch_m;
  uint32_t n, mode;
  double (*omega)(double k, double depth);
};

class SingleMode : public OceanGpu, public ::testing::WithParamInterface<ModeCase> {};

TEST_P(SingleMode, AdvancesInPhaseByOmegaT) {
  const ModeCase mc = GetParam();
  OceanParams params;
  params.depth_m = mc.depth_m;
  params.cascades = {{mc.patch_m, mc.n}};
  params.choppiness = 0;
  ocean::CascadeSpectrum s = ocean::make_cascade_spectrum(params, 0);
  const uint32_t n = mc.n, ix = mc.mode, iz = 0;
  const size_t index = size_t{iz} * n + ix;
  const std::complex<float> amplitude(0.25f, 0.1f);
  std::fill(s.h0.begin(), s.h0.end(), std::complex<float>(0));
  s.h0[index] = amplitude;
  const double k = 2 * std::numbers::pi * mc.mode / mc.patch_m;
  const double omega = mc.omega(k, mc.depth_m);
  ASSERT_NEAR(s.omega[index], omega, 1e-5 * omega) << "the physics' ω(k) differs from the closed form";
  ocean::GpuOcean gpu_ocean(ctx(), params, {s});
  for (double t : {0.0, 0.37, 1.9}) {
    const auto r = run_gpu(gpu_ocean, {t})[0];
    // Project the height on e^{ik·x}: the mode's coefficient h0·e^{-iωt} (the conjugate mode gives
    // e^{-ik·x}).
    std::complex<double> c = 0;
    for (uint32_t z = 0; z < n; ++z)
      for (uint32_t x = 0; x < n; ++x)
        c += double(r.displacement[(size_t{z} * n + x) * 4 + 1]) *
             std::polar(1.0, -2 * std::numbers::pi * double(ix * x) / n);
    c /= double(n) * n;
    const std::complex<double> expected = std::complex<double>(amplitude) * std::polar(1.0, -omega * t);
    EXPECT_NEAR(std::abs(c - expected), 0.0, 1e-5) << mc.name << " t = " << t;
  }
}

double deep(double k, double) {
  return std::sqrt(9.81 * k);
}
double finite(double k, double d) {
  return std::sqrt(9.81 * k * std::tanh(k * d));
}
double capillary(double k, double) {
  return std::sqrt(9.81 * k * (1 + k * k * 0.074 / (1000 * 9.81)));
}

INSTANTIATE_TEST_SUITE_P(Dispersion, SingleMode,
                         ::testing::Values(ModeCase{"deep", 1000, 100, 64, 5, deep},
                                           ModeCase{"finite_depth", 2, 400, 64, 3, finite},
                                           ModeCase{"capillary", 1000, 0.1, 64, 9, capillary}),
                         [](const auto& info) { return std::string(info.param.name); });

// Significant wave height of the generated surface against the spectrum integrated over the resolved bands.
TEST_F(OceanGpu, SignificantWaveHeightMatchesTheSpectrum) {
  OceanParams params;
  params.choppiness = 0;
  params.cascades = {{800.0, 128}, {80.0, 128}, {8.0, 128}};
  const auto bands = ocean::cascade_bands(params);
  // Independent quadrature of Ψ over the union of the bands, in polar coordinates.
  double integral = 0;
  const int radial = 6000, angular = 720;
  const double k_lo = bands.front().k_min, k_hi = bands.back().k_max;
  const double log_lo = std::log(std::max(k_lo, 1e-4)), log_hi = std::log(k_hi);
  for (int i = 0; i < radial; ++i) {
    const double k = std::exp(log_lo + (i + 0.5) * (log_hi - log_lo) / radial);
    const double dk = k * (log_hi - log_lo) / radial;
    for (int a = 0; a < angular; ++a) {
      const double theta = (a + 0.5) * 2 * std::numbers::pi / angular;
      integral += ocean::directional_spectrum(params, k * std::sin(theta), k * std::cos(theta)) * k * dk *
                  (2 * std::numbers::pi / angular);
    }
  }
  const double hs_expected = 4 * std::sqrt(integral);
  double variance_sum = 0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    params.seed = uint32_t(seed);
    ocean::GpuOcean gpu_ocean(ctx(), params);
    for (const auto& r : run_gpu(gpu_ocean, {0.5})) {
      double sum = 0, sum2 = 0;
      const size_t texels = r.displacement.size() / 4;
      for (size_t i = 0; i < texels; ++i)
        sum += r.displacement[4 * i + 1], sum2 += std::pow(r.displacement[4 * i + 1], 2);
      variance_sum += sum2 / texels - std::pow(sum / texels, 2);  // disjoint bands: variances add
    }
  }
  const double hs = 4 * std::sqrt(variance_sum / seeds);
  EXPECT_NEAR(hs / hs_expected, 1.0, 0.05) << "Hs " << hs << " m, expected " << hs_expected << " m";
}

}  // namespace
}  // namespace lagoon::test

namespace lagoon::test {
namespace {

// Several steps recorded into one command buffer (as a warm-up does) must be correctly synchronised: the
// validation layer's synchronization checks run in every test and fail it on a hazard.
TEST_F(OceanGpu, StepsRecordedBackToBackAreSynchronised) {
  ocean::GpuOcean gpu_ocean(ctx(), test_params());
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    for (int i = 0; i < 3; ++i) gpu_ocean.record_step(cmd, 0.1 * i, 0.1);
  });
  EXPECT_GT(gpu_ocean.read_cascade(0).displacement.size(), 0u);
}

}  // namespace
}  // namespace lagoon::test
