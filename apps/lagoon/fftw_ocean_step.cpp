#include "fftw_ocean_step.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <thread>

namespace lagoon::cli {

FftwOceanStep::FftwOceanStep(const ocean::OceanParams& params,
                             const std::vector<ocean::CascadeSpectrum>& spectra, int threads)
    : params_(params), threads_(threads) {
  static std::once_flag once;
  std::call_once(once, [] { fftwf_init_threads(); });
  fftwf_plan_with_nthreads(threads);
  for (const auto& s : spectra) {
    Cascade c;
    c.n = s.resolution;
    c.dk = float(2 * std::numbers::pi / s.patch_size_m);
    const size_t texels = size_t{c.n} * c.n;
    c.pairs.resize(texels * 4);
    c.omega = s.omega;
    for (uint32_t iz = 0; iz < c.n; ++iz)
      for (uint32_t ix = 0; ix < c.n; ++ix) {
        const size_t i = size_t{iz} * c.n + ix, m = size_t{(c.n - iz) % c.n} * c.n + (c.n - ix) % c.n;
        c.pairs[4 * i] = s.h0[i].real();
        c.pairs[4 * i + 1] = s.h0[i].imag();
        c.pairs[4 * i + 2] = s.h0[m].real();
        c.pairs[4 * i + 3] = -s.h0[m].imag();
      }
    c.fields = fftwf_alloc_complex(texels * 4);
    const int dims[2] = {int(c.n), int(c.n)};
    c.plan = fftwf_plan_many_dft(2, dims, 4, c.fields, nullptr, 1, int(texels), c.fields, nullptr, 1,
                                 int(texels), FFTW_BACKWARD, FFTW_MEASURE);
    c.displacement.assign(texels * 4, 0.0f);
    c.normal_jacobian.resize(texels * 4);
    c.jacobian_terms.resize(texels * 4);
    cascades_.push_back(std::move(c));
  }
}

FftwOceanStep::~FftwOceanStep() {
  for (auto& c : cascades_) {
    fftwf_destroy_plan(c.plan);
    fftwf_free(c.fields);
  }
}

void FftwOceanStep::evolve(Cascade& c, float t, uint32_t row_begin, uint32_t row_end) {
  const uint32_t n = c.n;
  const size_t plane = size_t{n} * n;
  for (uint32_t iz = row_begin; iz < row_end; ++iz) {
    const float kz = c.dk * float(iz < n / 2 ? int(iz) : int(iz) - int(n));
    for (uint32_t ix = 0; ix < n; ++ix) {
      const size_t i = size_t{iz} * n + ix;
      const float kx = c.dk * float(ix < n / 2 ? int(ix) : int(ix) - int(n));
      const float k = std::sqrt(kx * kx + kz * kz), inv_k = k > 0 ? 1 / k : 0;
      const float co = std::cos(c.omega[i] * t), si = std::sin(c.omega[i] * t);
      const float* p = &c.pairs[4 * i];
      // h = h0·e^{-iωt} + h0m·e^{iωt}
      const float hr = p[0] * co + p[1] * si + p[2] * co - p[3] * si;
      const float hi = p[1] * co - p[0] * si + p[3] * co + p[2] * si;
      const float ihr = -hi, ihi = hr;  // i·h
      const float dxr = ihr * kx * inv_k, dxi = ihi * kx * inv_k, dzr = ihr * kz * inv_k,
                  dzi = ihi * kz * inv_k;
      const float sxr = ihr * kx, sxi = ihi * kx, szr = ihr * kz, szi = ihi * kz;
      const float a = -kx * kx * inv_k, b = -kz * kz * inv_k, d = -kx * kz * inv_k;
      c.fields[i][0] = dxr - hi, c.fields[i][1] = dxi + hr;
      c.fields[plane + i][0] = dzr - sxi, c.fields[plane + i][1] = dzi + sxr;
      c.fields[2 * plane + i][0] = szr - a * hi, c.fields[2 * plane + i][1] = szi + a * hr;
      c.fields[3 * plane + i][0] = b * hr - d * hi, c.fields[3 * plane + i][1] = b * hi + d * hr;
    }
  }
}

void FftwOceanStep::assemble(Cascade& c, float decay, size_t begin, size_t end) {
  const float lambda = float(params_.choppiness), threshold = float(params_.foam.threshold);
  const size_t plane = size_t{c.n} * c.n;
  for (size_t i = begin; i < end; ++i) {
    const float h = c.fields[i][1], sx = c.fields[plane + i][1], sz = c.fields[2 * plane + i][0];
    const float jxx = 1 + lambda * c.fields[2 * plane + i][1], jzz = 1 + lambda * c.fields[3 * plane + i][0];
    const float jxz = lambda * c.fields[3 * plane + i][1];
    const float jacobian = jxx * jzz - jxz * jxz;
    const float foam =
        std::max(c.displacement[4 * i + 3] * decay, std::clamp(threshold - jacobian, 0.0f, 1.0f));
    const float inv_len = 1 / std::sqrt(sx * sx + 1 + sz * sz);
    float* out = &c.displacement[4 * i];
    out[0] = lambda * c.fields[i][0], out[1] = h, out[2] = lambda * c.fields[plane + i][0], out[3] = foam;
    float* nj = &c.normal_jacobian[4 * i];
    nj[0] = -sx * inv_len, nj[1] = inv_len, nj[2] = -sz * inv_len, nj[3] = jacobian;
    float* terms = &c.jacobian_terms[4 * i];
    terms[0] = jxx - 1, terms[1] = jzz - 1, terms[2] = jxz, terms[3] = foam;
  }
}

void FftwOceanStep::step(float t, float dt) {
  const float decay = std::exp(-float(params_.foam.decay_per_s) * dt);
  // The whole step uses the threads, not only FFTW: a fair baseline for the GPU.
  auto parallel = [&](size_t count, auto&& work) {
    if (threads_ <= 1) return work(size_t{0}, count);
    std::vector<std::thread> pool;
    for (int i = 1; i < threads_; ++i)
      pool.emplace_back(work, count * i / threads_, count * (i + 1) / threads_);
    work(size_t{0}, count / threads_);
    for (auto& th : pool) th.join();
  };
  for (Cascade& c : cascades_) {
    parallel(c.n, [&](size_t a, size_t b) { evolve(c, t, uint32_t(a), uint32_t(b)); });
    fftwf_execute(c.plan);
    parallel(size_t{c.n} * c.n, [&](size_t a, size_t b) { assemble(c, decay, a, b); });
  }
}

}  // namespace lagoon::cli
