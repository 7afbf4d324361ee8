// The water's pressure on a hull: p = ρ·g·(h(x, z) − y) (or ρ·g·(H − y) with a PressureHead) on every part of
// the hull below the water's height h at its (x, z), integrated over the triangles clipped at the waterline,
// with depth taken as linear across each piece. For flat water this is exact: a closed hull gets
// ρ·g·V_submerged upwards, acting at the centre of buoyancy (the waterplane itself carries no pressure, so
// the open cut needs no cap). In waves it is the hydrostatic (Froude–Krylov-like) approximation that games
// and robotics simulators use.
#pragma once
#include <cstdint>
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

namespace lagoon::physics {

// The water's height (m) at (x, z), at the time being simulated.
using WaterHeight = std::function<double(double x, double z)>;
// The same for a batch of (x, z) points: heights[i] at points[i]. A hull asks for hundreds of points a step;
// one call lets the source hoist what every point shares (issue 35: physics at physics rate).
using WaterHeights = std::function<void(std::span<const glm::dvec2> points, std::span<double> heights)>;
// The pressure head H (m) at a point in the water, p = ρ·g·(H − y), where the water knows more than its
// height: linear wave theory lets each wave's share of the pressure fade with depth (physics/airy_wave.h),
// which a hull as deep as the waves are long feels (issue 33: the Task 10 sphere's heave). H = y at the
// surface; without it H is the height above (x, z), the quasi-static approximation.
using PressureHead = std::function<double(double x, double y, double z)>;

struct Wrench {
  glm::dvec3 force{0.0};   // N
  glm::dvec3 torque{0.0};  // N·m about the point given
  double wetted_area = 0;  // m² of hull below the water
};

// `vertices` in world coordinates; `indices` three per triangle, counter-clockwise from outside.
// `water_top`: no height `water` gives is above it (+inf when unknown). Triangles wholly above it are dry
// without asking `water`, which is the step's dearest part: a hull's deck and superstructure cost nothing.
Wrench hydrostatic_wrench(std::span<const glm::dvec3> vertices, std::span<const uint32_t> indices,
                          const WaterHeight& water, glm::dvec3 about, double density, double gravity,
                          double water_top = std::numeric_limits<double>::infinity(),
                          const PressureHead& head = {});

// hydrostatic_wrench for a rigid hull, with what does not change as it moves computed once. A triangle wholly
// under water adds F = −ρg/3·(Σdᵢ)·S and τ = −ρg/12·Σᵢ dᵢ·((rᵢ + Σr) × S) about the centre of mass; with
// rᵢ = R·hᵢ and S = R·S_body both are R times body-frame sums that are linear in the corner depths, so a
// step costs four multiply-adds of precomputed vectors per triangle instead of its cross products (most of
// a body's step). Triangles the waterline cuts are clipped in world coordinates as hydrostatic_wrench does.
// The same wrench to rounding.
class HullPressure {
 public:
  HullPressure() = default;
  // `hull`: the vertices relative to the centre of mass, in body axes; `indices` as for hydrostatic_wrench.
  HullPressure(std::span<const glm::dvec3> hull, std::span<const uint32_t> indices);

  struct Water {
    const WaterHeight* height = nullptr;
    const WaterHeights* heights = nullptr;  // when given, asked instead of `height`, once a step
    const PressureHead* head = nullptr;     // when given, asked instead of both
    double top = std::numeric_limits<double>::infinity();  // as hydrostatic_wrench's water_top
  };
  // `world`: the hull's vertices where the body is (centre + rotation · hull), about the centre.
  Wrench wrench(std::span<const glm::dvec3> world, const glm::dmat3& rotation, glm::dvec3 centre,
                const Water& water, double density, double gravity);

 private:
  // A triangle's corners apart from its precomputed terms: the dry test reads every triangle's corners each
  // step, the terms only the wet ones' (116 bytes a triangle streamed through the cache for nothing).
  struct Corners {
    uint32_t v[3];
  };
  struct Terms {
    double area;
    glm::dvec3 s;       // area vector, body axes
    glm::dvec3 arm[3];  // (hᵢ + Σh) × S, body axes
  };
  std::vector<Corners> corners_;
  std::vector<Terms> terms_;
  // Per step scratch: the triangles that may be wet, the vertices they need and the depths there.
  std::vector<uint32_t> wet_, needed_;
  std::vector<uint8_t> marked_, dry_;  // dry_: a vertex above water.top
  std::vector<glm::dvec2> points_;
  std::vector<double> heights_, depth_;
};

}  // namespace lagoon::physics
