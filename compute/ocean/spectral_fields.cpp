#include "ocean/spectral_fields.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

#include "fft/cpu_fft.h"

namespace lagoon::ocean {

namespace {

// What every field of one mode is built from, computed once per mode and time.
struct ModeState {
  std::complex<double> h, dh_dt;
  double kx, kz, inv_k;
};

ModeState mode_state(const ModeConstants& c, double time_s) {
  const std::complex<double> e = std::polar(1.0, -c.omega * time_s);  // e^{-iωt}
  ModeState m;
  m.h = c.h0 * e + c.h0m * std::conj(e);
  m.dh_dt =
      std::complex<double>(0, -c.omega) * c.h0 * e + std::complex<double>(0, c.omega) * c.h0m * std::conj(e);
  m.kx = c.kx;
  m.kz = c.kz;
  m.inv_k = c.inv_k;
  return m;
}

ModeState mode_state(const CascadeSpectrum& s, uint32_t ix, uint32_t iz, double time_s) {
  return mode_state(mode_constants(s, ix, iz), time_s);
}

bool has_amplitude(const CascadeSpectrum& s, uint32_t ix, uint32_t iz) {
  const uint32_t n = s.resolution;
  return s.h0[size_t{iz} * n + ix] != std::complex<float>(0) ||
         s.h0[size_t{(n - iz) % n} * n + (n - ix) % n] != std::complex<float>(0);
}

std::complex<double> field_of(const ModeState& m, Field field) {
  const std::complex<double> I(0, 1);
  switch (field) {
    case Field::Dx:
      return I * (m.kx * m.inv_k) * m.h;
    case Field::Height:
      return m.h;
    case Field::Dz:
      return I * (m.kz * m.inv_k) * m.h;
    case Field::SlopeX:
      return I * m.kx * m.h;
    case Field::SlopeZ:
      return I * m.kz * m.h;
    case Field::DxDx:
      return -m.kx * m.kx * m.inv_k * m.h;
    case Field::DzDz:
      return -m.kz * m.kz * m.inv_k * m.h;
    case Field::DxDz:
      return -m.kx * m.kz * m.inv_k * m.h;
    case Field::VelocityX:
      return I * (m.kx * m.inv_k) * m.dh_dt;
    case Field::VelocityY:
      return m.dh_dt;
    case Field::VelocityZ:
      return I * (m.kz * m.inv_k) * m.dh_dt;
  }
  return 0.0;
}

// The fields of `fields` from each mode's state, two real fields packed per complex inverse FFT, then
// unpacked: one plane per field. `each_mode(visit)` calls visit(folded index, state) for every mode.
template <typename EachMode>
std::vector<std::vector<double>> fields_from_modes(uint32_t m, std::span<const Field> fields,
                                                   const InverseFft2d& fft, EachMode each_mode) {
  const size_t plane = size_t{m} * m;
  const uint32_t batches = uint32_t((fields.size() + 1) / 2);
  std::vector<std::complex<double>> data(plane * batches);
  each_mode([&](size_t folded, const ModeState& mode) {
    for (uint32_t b = 0; b < batches; ++b) {
      std::complex<double> v = field_of(mode, fields[2 * b]);
      if (2 * b + 1 < fields.size()) v += std::complex<double>(0, 1) * field_of(mode, fields[2 * b + 1]);
      data[plane * b + folded] += v;
    }
  });
  fft(data, m, batches);
  // Each field's plane made once (not copied from a prototype: that copy was 8 % of a knot, issue 35).
  std::vector<std::vector<double>> out(fields.size());
  for (size_t f = 0; f < fields.size(); ++f) {
    out[f].resize(plane);
    const std::complex<double>* v = data.data() + plane * (f / 2);
    double* o = out[f].data();
    if (f % 2 == 0)
      for (size_t i = 0; i < plane; ++i) o[i] = v[i].real();
    else
      for (size_t i = 0; i < plane; ++i) o[i] = v[i].imag();
  }
  return out;
}

}  // namespace

std::complex<double> field_spectrum(const CascadeSpectrum& s, uint32_t ix, uint32_t iz, double time_s,
                                    Field field) {
  return field_of(mode_state(s, ix, iz, time_s), field);
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
  return evaluate_fields_on_lattice(s, time_s, fields, fft, 1);
}

std::vector<std::vector<double>> evaluate_fields_on_lattice(const CascadeSpectrum& s, double time_s,
                                                            std::span<const Field> fields,
                                                            const InverseFft2d& fft, uint32_t stride) {
  const uint32_t n = s.resolution, m = n / std::max(stride, 1u);
  return fields_from_modes(m, fields, fft, [&](auto visit) {
    for (uint32_t iz = 0; iz < n; ++iz)
      for (uint32_t ix = 0; ix < n; ++ix)
        if (has_amplitude(s, ix, iz))  // else outside the band (data is zero-initialised)
          visit(size_t{iz % m} * m + ix % m, mode_state(s, ix, iz, time_s));
  });
}

ModeConstants mode_constants(const CascadeSpectrum& s, uint32_t ix, uint32_t iz) {
  const uint32_t n = s.resolution;
  const size_t i = size_t{iz} * n + ix, mirrored = size_t{(n - iz) % n} * n + (n - ix) % n;
  const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
  ModeConstants c;
  c.h0 = s.h0[i];
  c.h0m = std::conj(std::complex<double>(s.h0[mirrored]));
  c.omega = s.omega[i];
  c.kx = dk * (ix < n / 2 ? double(ix) : double(ix) - n);
  c.kz = dk * (iz < n / 2 ? double(iz) : double(iz) - n);
  const double k = std::hypot(c.kx, c.kz);
  c.inv_k = k > 0 ? 1.0 / k : 0.0;
  return c;
}

SpectrumModes list_modes(const CascadeSpectrum& s) {
  SpectrumModes out;
  out.resolution = s.resolution;
  for (uint32_t iz = 0; iz < s.resolution; ++iz)
    for (uint32_t ix = 0; ix < s.resolution; ++ix)
      if (has_amplitude(s, ix, iz)) {
        out.index.push_back(iz * s.resolution + ix);
        out.constants.push_back(mode_constants(s, ix, iz));
      }
  return out;
}

std::vector<std::vector<double>> evaluate_fields(const SpectrumModes& modes, double time_s,
                                                 std::span<const Field> fields, const InverseFft2d& fft) {
  return fields_from_modes(modes.resolution, fields, fft, [&](auto visit) {
    for (size_t j = 0; j < modes.index.size(); ++j)
      visit(modes.index[j], mode_state(modes.constants[j], time_s));
  });
}

}  // namespace lagoon::ocean
