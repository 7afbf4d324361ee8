#include "ocean/depth_profile.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace lagoon::ocean {

glm::dvec2 DepthProfile::local(glm::dvec2 xz) const {
  return {glm::dot(xz - origin, axis), glm::dot(xz - origin, across())};
}

double DepthProfile::depth_at(glm::dvec2 s) const {
  const size_t nu = columns(), nv = rows;
  if (nu == 0) return 0.0;
  auto axis_at = [&](double t, size_t n, size_t& i, size_t& next, double& f) {
    t = std::clamp(t / spacing_m, 0.0, double(n - 1));
    i = std::min(size_t(t), n - 1);
    next = std::min(i + 1, n - 1);
    f = t - double(i);
  };
  size_t i0, i1, j0, j1;
  double fu, fv;
  axis_at(s.x, nu, i0, i1, fu);
  axis_at(s.y, nv, j0, j1, fv);
  const double a = depth(i0, j0) + (depth(i1, j0) - depth(i0, j0)) * fu;
  const double b = depth(i0, j1) + (depth(i1, j1) - depth(i0, j1)) * fu;
  return a + (b - a) * fv;
}

double DepthProfile::shallowest_m() const {
  return depth_m.empty() ? HUGE_VAL : *std::min_element(depth_m.begin(), depth_m.end());
}

}  // namespace lagoon::ocean
