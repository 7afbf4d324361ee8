#include "physics/mesh_floor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lagoon::physics {
namespace {

// Height at (x, z) of the triangle's plane where (x, z) lies inside its projection (edges included).
bool height_over(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double x, double z,
                 double& y) {
  const double det = (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
  if (std::abs(det) < 1e-18) return false;  // vertical: no height of its own
  const double u = ((x - a.x) * (c.z - a.z) - (c.x - a.x) * (z - a.z)) / det;
  const double v = ((b.x - a.x) * (z - a.z) - (x - a.x) * (b.z - a.z)) / det;
  constexpr double eps = 1e-9;
  if (u < -eps || v < -eps || u + v > 1 + eps) return false;
  y = a.y + u * (b.y - a.y) + v * (c.y - a.y);
  return true;
}

}  // namespace

MeshFloor::MeshFloor(std::vector<glm::dvec3> vertices, std::vector<uint32_t> indices)
    : vertices_(std::move(vertices)), indices_(std::move(indices)) {
  if (indices_.size() < 3 || vertices_.empty()) {
    indices_.clear();
    return;
  }
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const glm::dvec3& v : vertices_) lo = glm::min(lo, {v.x, v.z}), hi = glm::max(hi, {v.x, v.z});
  // About one triangle a cell on average, at most 1024 cells a side.
  const double area = std::max((hi.x - lo.x) * (hi.y - lo.y), 1e-6);
  cell_m_ =
      std::max(std::sqrt(area / double(indices_.size() / 3)), std::max(hi.x - lo.x, hi.y - lo.y) / 1024);
  cell_m_ = std::max(cell_m_, 1e-3);
  origin_ = lo;
  nx_ = int((hi.x - lo.x) / cell_m_) + 1;
  nz_ = int((hi.y - lo.y) / cell_m_) + 1;
  cells_.resize(size_t(nx_) * size_t(nz_));
  for (size_t t = 0; t + 2 < indices_.size(); t += 3) {
    glm::dvec2 tlo(1e300), thi(-1e300);
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3& v = vertices_[indices_[t + k]];
      tlo = glm::min(tlo, {v.x, v.z}), thi = glm::max(thi, {v.x, v.z});
    }
    const int i0 = std::clamp(int((tlo.x - origin_.x) / cell_m_), 0, nx_ - 1);
    const int i1 = std::clamp(int((thi.x - origin_.x) / cell_m_), 0, nx_ - 1);
    const int j0 = std::clamp(int((tlo.y - origin_.y) / cell_m_), 0, nz_ - 1);
    const int j1 = std::clamp(int((thi.y - origin_.y) / cell_m_), 0, nz_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) cells_[size_t(j) * size_t(nx_) + size_t(i)].push_back(uint32_t(t));
  }
}

double MeshFloor::height(double x, double z) const {
  double best = -std::numeric_limits<double>::infinity();
  if (indices_.empty()) return best;
  const double fi = (x - origin_.x) / cell_m_, fj = (z - origin_.y) / cell_m_;
  if (!(fi >= 0 && fj >= 0 && fi < nx_ && fj < nz_)) return best;
  for (uint32_t t : cell(int(fi), int(fj))) {
    double y;
    if (height_over(vertices_[indices_[t]], vertices_[indices_[t + 1]], vertices_[indices_[t + 2]], x, z, y))
      best = std::max(best, y);
  }
  return best;
}

}  // namespace lagoon::physics
