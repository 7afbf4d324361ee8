#include "physics/hydrostatics.h"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

namespace lagoon::physics {
namespace {

struct Point {
  glm::dvec3 p;
  double depth;  // below the water, > 0 when submerged
};

// The pressure on one triangle whose depth is linear between its corners, all >= 0. With area vector
// S = A·n (outward): F = −ρg·∫d dA·n = −ρg·mean(d)·S, and ∫(p − c)·d dA = A/12·(Σ rᵢdᵢ + Σrᵢ·Σdᵢ) for linear
// r and d, so τ = −ρg/12·(Σ rᵢdᵢ + Σrᵢ·Σdᵢ) × S.
void add_triangle(const Point& a, const Point& b, const Point& c, glm::dvec3 about, double rho_g,
                  Wrench& out) {
  const glm::dvec3 s = 0.5 * glm::cross(b.p - a.p, c.p - a.p);
  const double sum_d = a.depth + b.depth + c.depth;
  const glm::dvec3 ra = a.p - about, rb = b.p - about, rc = c.p - about;
  out.force += -rho_g * sum_d / 3.0 * s;
  const glm::dvec3 first_moment = ra * a.depth + rb * b.depth + rc * c.depth + (ra + rb + rc) * sum_d;
  out.torque += glm::cross(-rho_g / 12.0 * first_moment, s);
  out.wetted_area += glm::length(s);
}

}  // namespace

Wrench hydrostatic_wrench(std::span<const glm::dvec3> vertices, std::span<const uint32_t> indices,
                          const WaterHeight& water, glm::dvec3 about, double density, double gravity,
                          double water_top, const PressureHead& head) {
  Wrench out;
  const double rho_g = density * gravity;
  // The water's height once per vertex (a closed mesh has about half as many vertices as triangles, and
  // each is a corner of about six), and only for the triangles that can reach the water: the lookup is the
  // step's dearest part. NaN: not looked up yet.
  std::vector<double> depth(vertices.size(), std::numeric_limits<double>::quiet_NaN());
  auto depth_at = [&](uint32_t v) {
    if (!std::isnan(depth[v])) return depth[v];
    const glm::dvec3& p = vertices[v];
    depth[v] = (head ? head(p.x, p.y, p.z) : water(p.x, p.z)) - p.y;
    return depth[v];
  };
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    if (vertices[indices[t]].y > water_top && vertices[indices[t + 1]].y > water_top &&
        vertices[indices[t + 2]].y > water_top)
      continue;  // dry whatever the water does
    std::array<Point, 3> corner;
    int under = 0;
    for (int k = 0; k < 3; ++k) {
      corner[k] = {vertices[indices[t + k]], depth_at(indices[t + k])};
      under += corner[k].depth > 0 ? 1 : 0;
    }
    if (under == 0) continue;
    // Clip the triangle to depth >= 0 (Sutherland–Hodgman against one plane): at most four corners.
    std::array<Point, 4> poly;
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const Point& cur = corner[k];
      const Point& next = corner[(k + 1) % 3];
      if (cur.depth >= 0) poly[n++] = cur;
      if ((cur.depth > 0) != (next.depth > 0) && cur.depth != next.depth && n < 4) {
        const double f = cur.depth / (cur.depth - next.depth);
        if (f > 0 && f < 1) poly[n++] = {cur.p + f * (next.p - cur.p), 0.0};
      }
    }
    for (int k = 1; k + 1 < n; ++k) add_triangle(poly[0], poly[k], poly[k + 1], about, rho_g, out);
  }
  return out;
}

}  // namespace lagoon::physics
