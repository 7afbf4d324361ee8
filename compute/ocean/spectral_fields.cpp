#include "ocean/spectral_fields.h"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

#include "fft/cpu_fft.h"

namespace lagoon::ocean {

std::complex<double> field_spectrum(const CascadeSpectrum& s, uint32_t ix, uint32_t iz, double time_s,
                                    Field field) {
  const uint32_t n = s.resolution;
  const size_t i = size_t{iz} * n + ix, mirrored = size_t{(n - iz) % n} * n + (n - ix) % n;
  const std::complex<double> h0 = s.h0[i], h0m = std::conj(std::complex<double>(s.h0[mirrored]));
  const double omega = s.omega[i];
  const std::complex<double> e = std::polar(1.0, -omega * time_s);  // e^{-iωt}
  const std::complex<double> h = h0 * e + h0m * std::conj(e);
  const std::complex<double> dh_dt =
      std::complex<double>(0, -omega) * h0 * e + std::complex<double>(0, omega) * h0m * std::conj(e);
  const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
  const double kx = dk * (ix < n / 2 ? double(ix) : double(ix) - n);
  const double kz = dk * (iz < n / 2 ? double(iz) : double(iz) - n);
  const double k = std::hypot(kx, kz), inv_k = k > 0 ? 1.0 / k : 0.0;
  const std::complex<double> I(0, 1);
  switch (field) {
    case Field::Dx:
      return I * (kx * inv_k) * h;
    case Field::Height:
      return h;
    case Field::Dz:
      return I * (kz * inv_k) * h;
    case Field::SlopeX:
      return I * kx * h;
    case Field::SlopeZ:
      return I * kz * h;
    case Field::DxDx:
      return -kx * kx * inv_k * h;
    case Field::DzDz:
      return -kz * kz * inv_k * h;
    case Field::DxDz:
      return -kx * kz * inv_k * h;
    case Field::VelocityX:
      return I * (kx * inv_k) * dh_dt;
    case Field::VelocityY:
      return dh_dt;
    case Field::VelocityZ:
      return I * (kz * inv_k) * dh_dt;
  }
  return 0.0;
}

InverseFft2d cpu_inverse_fft(unsigned threads) {
  // One plan per size, shared by every call (plans are immutable once built).
  auto plans = std::make_shared<std::map<uint32_t, std::unique_ptr<fft::CpuFft2d>>>();
  auto mutex = std::make_shared<std::mutex>();
  return [plans, mutex, threads](std::vector<std::complex<double>>& data, uint32_t n, uint32_t batches) {
    const fft::CpuFft2d* plan;
    {
      std::lock_guard lock(*mutex);
      auto& slot = (*plans)[n];
      if (!slot) slot = std::make_unique<fft::CpuFft2d>(n, true);
      plan = slot.get();
    }
    plan->transform(data, batches, threads);
  };
}

std::vector<std::vector<double>> evaluate_fields(const CascadeSpectrum& s, double time_s,
                                                 std::span<const Field> fields, const InverseFft2d& fft) {
  const uint32_t n = s.resolution;
  const size_t plane = size_t{n} * n;
  const uint32_t batches = uint32_t((fields.size() + 1) / 2);
  std::vector<std::complex<double>> data(plane * batches);
  for (uint32_t b = 0; b < batches; ++b) {
    const Field a = fields[2 * b];
    const bool has_b = 2 * b + 1 < fields.size();
    for (uint32_t iz = 0; iz < n; ++iz)
      for (uint32_t ix = 0; ix < n; ++ix) {
        std::complex<double> v = field_spectrum(s, ix, iz, time_s, a);
        if (has_b) v += std::complex<double>(0, 1) * field_spectrum(s, ix, iz, time_s, fields[2 * b + 1]);
        data[plane * b + size_t{iz} * n + ix] = v;
      }
  }
  fft(data, n, batches);
  std::vector<std::vector<double>> out(fields.size(), std::vector<double>(plane));
  for (size_t f = 0; f < fields.size(); ++f)
    for (size_t i = 0; i < plane; ++i) {
      const std::complex<double> v = data[plane * (f / 2) + i];
      out[f][i] = f % 2 == 0 ? v.real() : v.imag();
    }
  return out;
}

}  // namespace lagoon::ocean
