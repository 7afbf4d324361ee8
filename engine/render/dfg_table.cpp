#include "render/dfg_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "render/cached_tables.h"

namespace lagoon::render {
namespace {

double radical_inverse(uint32_t bits) {  // van der Corput, for the Hammersley set
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return double(bits) * 2.3283064365386963e-10;
}

}  // namespace

glm::vec2 integrate_dfg(double n_dot_v, double roughness, int samples) {
  const double alpha = std::max(roughness * roughness, 1e-3);
  const double vx = std::sqrt(1.0 - n_dot_v * n_dot_v), vz = n_dot_v;  // v in the x-z plane, n = +z
  double a = 0, b = 0;
  for (int i = 0; i < samples; ++i) {
    // h from the GGX distribution of normals (pdf D(h)(n·h)); l = reflect(−v, h).
    const double u1 = (i + 0.5) / samples, u2 = radical_inverse(uint32_t(i));
    const double cos_h = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
    const double sin_h = std::sqrt(1.0 - cos_h * cos_h), phi = 2.0 * std::numbers::pi * u2;
    const double hx = sin_h * std::cos(phi), hz = cos_h;  // v has no y part: h.y does not enter
    const double v_dot_h = vx * hx + vz * hz;
    const double lz = 2.0 * v_dot_h * hz - vz;
    if (lz <= 0.0 || v_dot_h <= 0.0) continue;
    // f_spec cos / pdf(l) with pdf(l) = D (n·h) / (4 v·h): V · 4 (n·l)(v·h) / (n·h), times F's two parts.
    const double vis = gpu::pbr_v_smith(float(lz), float(n_dot_v), float(alpha));
    const double weight = vis * 4.0 * lz * v_dot_h / cos_h;
    const double fc = std::pow(1.0 - v_dot_h, 5.0);
    a += (1.0 - fc) * weight;
    b += fc * weight;
  }
  return glm::vec2(a / samples, b / samples);
}

const DfgTable& dfg_table() {
  // Once per process, and once per build on a machine (render/cached_tables.h): 1M samples take ~70 ms.
  static const DfgTable table = [] {
    constexpr int n = LAGOON_DFG_SIZE, kSamples = 1024;
    io::ResultKey key = table_key("dfg");
    key.add("size", n).add("samples", kSamples);
    const io::ResultCache cache = io::ResultCache::from_environment();
    DfgTable t;
    if (auto ab = cache.load_vector<glm::vec2>(key, t.ab.size())) {
      std::copy(ab->begin(), ab->end(), t.ab.begin());
      return t;
    }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        t.ab[size_t(j * n + i)] =
            integrate_dfg(std::max(double(i) / (n - 1), 1e-3), double(j) / (n - 1), kSamples);
    cache.store_vector(key, std::vector<glm::vec2>(t.ab.begin(), t.ab.end()));
    return t;
  }();
  return table;
}

glm::vec2 DfgTable::lookup(float n_dot_v, float roughness) const {
  constexpr int n = LAGOON_DFG_SIZE;
  auto axis = [](float x, int& i0, int& i1, float& f) {
    const float p = std::clamp(x, 0.0f, 1.0f) * float(n - 1);
    i0 = int(p);
    i1 = std::min(i0 + 1, n - 1);
    f = p - float(i0);
  };
  int x0, x1, y0, y1;
  float fx, fy;
  axis(n_dot_v, x0, x1, fx);
  axis(roughness, y0, y1, fy);
  auto at = [&](int x, int y) { return ab[size_t(y * n + x)]; };
  return glm::mix(glm::mix(at(x0, y0), at(x1, y0), fx), glm::mix(at(x0, y1), at(x1, y1), fx), fy);
}

}  // namespace lagoon::render
