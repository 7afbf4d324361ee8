// The water's pressure on a hull: p = ρ·g·(h(x, z) − y) (or ρ·g·(H − y) with a PressureHead) on every part of
// the hull below the water's height h at its (x, z), integrated over the triangles clipped at the waterline,
// with depth taken as linear across each piece. For flat water this is exact: a closed hull gets
// ρ·g·V_submerged upwards, acting at the centre of buoyancy (the waterplane itself carries no pressure, so
// the open cut needs no cap). In waves it is the hydrostatic (Froude–Krylov-like) approximation that games
// and robotics simulators use.
#pragma once
#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <span>

namespace lagoon::physics {

// The water's height (m) at (x, z), at the time being simulated.
using WaterHeight = std::function<double(double x, double z)>;
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

}  // namespace lagoon::physics
