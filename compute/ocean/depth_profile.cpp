#include "ocean/depth_profile.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lagoon::ocean {

double DepthProfile::s_of(glm::dvec2 xz) const {
  return glm::dot(xz - origin, axis);
}

double DepthProfile::depth_at(double s) const {
  if (depth_m.empty()) return 0.0;
  const double t = std::clamp(s / spacing_m, 0.0, double(depth_m.size() - 1));
  const size_t i = std::min(size_t(t), depth_m.size() - 1);
  const size_t j = std::min(i + 1, depth_m.size() - 1);
  return depth_m[i] + (depth_m[j] - depth_m[i]) * (t - double(i));
}

double DepthProfile::shallowest_m() const {
  return depth_m.empty() ? HUGE_VAL : *std::min_element(depth_m.begin(), depth_m.end());
}

}  // namespace lagoon::ocean
