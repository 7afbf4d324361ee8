#include "physics/hydrostatics.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

namespace lagoon::physics {
namespace {

// The pressure on one triangle (corners a, b, c at depths da, db, dc, all >= 0) whose depth is linear
// between its corners. With area vector S = A·n (outward): F = −ρg·∫d dA·n = −ρg·mean(d)·S, and
// ∫(p − c)·d dA = A/12·(Σ rᵢdᵢ + Σrᵢ·Σdᵢ) for linear r and d, so τ = −ρg/12·(Σ rᵢdᵢ + Σrᵢ·Σdᵢ) × S.
// Points and depths are passed apart: copying {point, depth} pairs through the stack stalled the loads that
// read them back (store forwarding), a third of the step.
void add_triangle(const glm::dvec3& a, double da, const glm::dvec3& b, double db, const glm::dvec3& c,
                  double dc, glm::dvec3 about, double rho_g, Wrench& out) {
  const glm::dvec3 s = 0.5 * glm::cross(b - a, c - a);
  const double sum_d = da + db + dc;
  const glm::dvec3 ra = a - about, rb = b - about, rc = c - about;
  out.force += -rho_g * sum_d / 3.0 * s;
  const glm::dvec3 first_moment = ra * da + rb * db + rc * dc + (ra + rb + rc) * sum_d;
  out.torque += glm::cross(-rho_g / 12.0 * first_moment, s);
  out.wetted_area += glm::length(s);
}

// A triangle the waterline cuts: clipped to depth >= 0 (Sutherland–Hodgman against one plane, at most four
// corners), then integrated as above.
void add_clipped(const glm::dvec3& p0, double d0, const glm::dvec3& p1, double d1, const glm::dvec3& p2,
                 double d2, glm::dvec3 about, double rho_g, Wrench& out) {
  const glm::dvec3* corner[3] = {&p0, &p1, &p2};
  const double depth_of[3] = {d0, d1, d2};
  glm::dvec3 poly[4];
  double poly_depth[4];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    const double dc = depth_of[k], dn = depth_of[next];
    if (dc >= 0) {
      poly[n] = *corner[k];
      poly_depth[n++] = dc;
    }
    if ((dc > 0) != (dn > 0) && dc != dn && n < 4) {
      const double f = dc / (dc - dn);
      if (f > 0 && f < 1) {
        poly[n] = *corner[k] + f * (*corner[next] - *corner[k]);
        poly_depth[n++] = 0.0;
      }
    }
  }
  for (int k = 1; k + 1 < n; ++k)
    add_triangle(poly[0], poly_depth[0], poly[k], poly_depth[k], poly[k + 1], poly_depth[k + 1], about, rho_g,
                 out);
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
    const uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
    const glm::dvec3 &p0 = vertices[i0], &p1 = vertices[i1], &p2 = vertices[i2];
    if (p0.y > water_top && p1.y > water_top && p2.y > water_top) continue;  // dry whatever the water does
    const double d0 = depth_at(i0), d1 = depth_at(i1), d2 = depth_at(i2);
    if (!(d0 > 0 || d1 > 0 || d2 > 0)) continue;
    if (d0 > 0 && d1 > 0 && d2 > 0) {  // wholly under: the clip below would keep it as it is
      add_triangle(p0, d0, p1, d1, p2, d2, about, rho_g, out);
      continue;
    }
    add_clipped(p0, d0, p1, d1, p2, d2, about, rho_g, out);
  }
  return out;
}

HullPressure::HullPressure(std::span<const glm::dvec3> hull, std::span<const uint32_t> indices)
    : marked_(hull.size(), 0), dry_(hull.size(), 0), depth_(hull.size(), 0.0) {
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const Corners corners{{indices[t], indices[t + 1], indices[t + 2]}};
    const glm::dvec3 &a = hull[corners.v[0]], &b = hull[corners.v[1]], &c = hull[corners.v[2]];
    Terms terms{};
    terms.s = 0.5 * glm::cross(b - a, c - a);
    terms.area = glm::length(terms.s);
    const glm::dvec3 sum = a + b + c;
    for (int k = 0; k < 3; ++k) terms.arm[k] = glm::cross(hull[corners.v[k]] + sum, terms.s);
    corners_.push_back(corners);
    terms_.push_back(terms);
  }
}

Wrench HullPressure::wrench(std::span<const glm::dvec3> world, const glm::dmat3& rotation, glm::dvec3 centre,
                            const Water& water, double density, double gravity) {
  // The triangles that can reach the water, and the vertices whose depth they need (once each).
  wet_.clear();
  needed_.clear();
  for (size_t v = 0; v < world.size(); ++v) dry_[v] = world[v].y > water.top ? 1 : 0;
  for (size_t t = 0; t < corners_.size(); ++t) {
    const uint32_t* v = corners_[t].v;
    if (dry_[v[0]] & dry_[v[1]] & dry_[v[2]]) continue;
    wet_.push_back(uint32_t(t));
    for (int k = 0; k < 3; ++k)
      if (!marked_[v[k]]) marked_[v[k]] = 1, needed_.push_back(v[k]);
  }
  for (uint32_t v : needed_) marked_[v] = 0;
  if (water.head) {
    for (uint32_t v : needed_) depth_[v] = (*water.head)(world[v].x, world[v].y, world[v].z) - world[v].y;
  } else if (water.heights) {
    points_.resize(needed_.size());
    heights_.resize(needed_.size());
    for (size_t i = 0; i < needed_.size(); ++i) points_[i] = {world[needed_[i]].x, world[needed_[i]].z};
    (*water.heights)(points_, heights_);
    for (size_t i = 0; i < needed_.size(); ++i) depth_[needed_[i]] = heights_[i] - world[needed_[i]].y;
  } else {
    for (uint32_t v : needed_) depth_[v] = (*water.height)(world[v].x, world[v].z) - world[v].y;
  }

  Wrench out;
  const double rho_g = density * gravity;
  glm::dvec3 force(0.0), torque(0.0);  // body axes, without −ρg/3 and −ρg/12
  for (uint32_t t : wet_) {
    const uint32_t* v = corners_[t].v;
    const double d0 = depth_[v[0]], d1 = depth_[v[1]], d2 = depth_[v[2]];
    if (!(d0 > 0 || d1 > 0 || d2 > 0)) continue;
    if (d0 > 0 && d1 > 0 && d2 > 0) {
      const Terms& tri = terms_[t];
      force += (d0 + d1 + d2) * tri.s;
      torque += d0 * tri.arm[0] + d1 * tri.arm[1] + d2 * tri.arm[2];
      out.wetted_area += tri.area;
      continue;
    }
    add_clipped(world[v[0]], d0, world[v[1]], d1, world[v[2]], d2, centre, rho_g, out);
  }
  out.force += rotation * (-rho_g / 3.0 * force);
  out.torque += rotation * (-rho_g / 12.0 * torque);
  return out;
}

}  // namespace lagoon::physics
