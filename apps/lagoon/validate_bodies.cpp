#include "validate_bodies.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/floating_body.h"

namespace lagoon::cli {
namespace {

constexpr double kRho = 1025.0;

// A closed box centred on the origin, each face split into n×n quads (2n² triangles), wound outward.
physics::TriangleMesh box(glm::dvec3 size, int n) {
  physics::TriangleMesh mesh;
  const glm::dvec3 h = 0.5 * size;
  auto face = [&](glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v) {  // u × v points outward
    const uint32_t base = uint32_t(mesh.vertices.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        mesh.vertices.push_back(origin + u * (double(i) / n) + v * (double(j) / n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
        mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
      }
  };
  const glm::dvec3 x{size.x, 0, 0}, y{0, size.y, 0}, z{0, 0, size.z};
  face({-h.x, -h.y, -h.z}, y, x);  // -z
  face({-h.x, -h.y, h.z}, x, y);   // +z
  face({-h.x, -h.y, -h.z}, z, y);  // -x
  face({h.x, -h.y, -h.z}, y, z);   // +x
  face({-h.x, -h.y, -h.z}, x, z);  // -y
  face({-h.x, h.y, -h.z}, z, x);   // +y
  return mesh;
}

physics::BodyOptions body_options(const ValidateOptions& o) {
  physics::BodyOptions options;
  if (o.broken == "vertex-buoyancy") options.sampling.spacing_m = -1.0;
  return options;
}

physics::FloatingBody make_body(const physics::TriangleMesh& hull, double density,
                                physics::BodyOptions options) {
  return physics::FloatingBody(hull, physics::solid_mass_properties(hull, density), physics::Damping{},
                               physics::WaterProperties{kRho, kG}, std::move(options));
}

double lowest_y(const physics::FloatingBody& body, const physics::TriangleMesh& hull) {
  double lowest = 1e300;
  for (const glm::dvec3& v : hull.vertices)
    lowest = std::min(lowest, (body.model_origin() + body.state().orientation * v).y);
  return lowest;
}

// Archimedes: a 2 × 1 × 2 m box of density ρ_b floats with draught 1 m · ρ_b/ρ.
Law archimedes(const ValidateOptions& o) {
  Law law{.id = "bodies.archimedes",
          .title = "Archimedes' draught",
          .source = "Archimedes' principle",
          .measured_on = "cpu: physics/floating_body.h in still water",
          .x_label = "density / water's",
          .y_label = "draught (m) of a 1 m high box",
          .tolerance = "±1 %",
          .note =
              "A 2 x 1 x 2 m box, one quad per face, settled in still water at level 0 (the hull's "
              "pressure integral and a bisection on its weight)."};
  const physics::TriangleMesh hull = box({2, 1, 2}, 1);
  for (double ratio : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    physics::FloatingBody body = make_body(hull, ratio * kRho, body_options(o));
    body.place({0, 0, 0}, glm::dquat(1, 0, 0, 0));
    body.settle_vertically(0.0);
    law.points.push_back(relative_point(ratio, ratio * 1.0, -lowest_y(body, hull) * o.scale(), 0.01));
  }
  return law;
}

// A body of length L in a long-crested regular wave of amplitude a along its length, heaving freely: its
// heave amplitude over a, after the start-up has died away.
double heave_ratio(double length, int quads, double wavelength, const ValidateOptions& o) {
  const physics::TriangleMesh hull = box({length, 0.2, 2.0}, quads);
  physics::FloatingBody body = make_body(hull, 0.5 * kRho, body_options(o));
  body.place({0, 0, 0}, glm::dquat(1, 0, 0, 0));
  body.settle_vertically(0.0);
  const double k = 2 * kPi / wavelength, w = std::sqrt(kG * k), a = 0.05, period = 2 * kPi / w;
  const double dt = 1.0 / 120.0;
  double lo = 1e300, hi = -1e300;
  for (double t = 0; t < 12 * period; t += dt) {
    const double ramp = std::min(t / (2 * period), 1.0);  // the wave grows in over two periods
    body.step(dt, [&](double x, double) { return ramp * a * std::cos(k * x - w * t); });
    if (t > 6 * period)
      lo = std::min(lo, body.state().position.y), hi = std::max(hi, body.state().position.y);
  }
  return 0.5 * (hi - lo) / a * o.scale();
}

// Quasi-static Froude–Krylov heave of a wall-sided box: the buoyancy's excitation averaged over the length,
// sinc(kL/2), through the undamped heave oscillator ω_n² = ρ g A_wp / m (no added mass: ω ≪ ω_n here).
double froude_krylov(double length, double wavelength) {
  const double k = 2 * kPi / wavelength, x = k * length / 2, w2 = kG * k;
  const double wn2 = kRho * kG * length * 2.0 / (0.5 * kRho * length * 0.2 * 2.0);
  return std::abs((x == 0 ? 1.0 : std::sin(x) / x) / (1.0 - w2 / wn2));
}

std::vector<Law> heave(const ValidateOptions& o) {
  Law law{.id = "bodies.box-heave",
          .title = "Heave of boxes in a regular wave",
          .source = "quasi-static Froude-Krylov theory, sinc(kL/2)",
          .measured_on = "cpu: physics/floating_body.h in an Airy wave",
          .x_label = "box length L (m), wave 20 m",
          .y_label = "heave amplitude / wave amplitude",
          .tolerance = "±0.05",
          .note =
              "L x 0.2 x 2 m boxes of half the water's density, one quad per face, in a 20 m wave of 5 cm "
              "along their length; amplitude over wave periods 6-12. Reference sinc(kL/2)/(1 - ω²/ω_n²), "
              "ω_n² = ρgA_wp/m."};
  const double wavelength = 20.0;
  for (double length :
       o.quick ? std::vector<double>{5, 10, 20} : std::vector<double>{2, 5, 8, 10, 14, 20, 26}) {
    law.points.push_back(absolute_point(length, froude_krylov(length, wavelength),
                                        heave_ratio(length, 1, wavelength, o), 0.05));
  }
  Law same{.id = "bodies.tessellation",
           .title = "Heave whatever the tessellation",
           .source = "the same hull must move the same (issue 33)",
           .measured_on = "cpu: physics/floating_body.h in an Airy wave",
           .x_label = "triangles per face",
           .y_label = "heave / heave with 800 per face",
           .tolerance = "±2 %",
           .log_x = true,
           .note =
               "The 10 m box of bodies.box-heave with 1, 2, 5 and 20 quads along each face's side (2 to 800 "
               "triangles per face)."};
  const double finest = heave_ratio(10.0, 20, wavelength, o);
  for (int quads : o.quick ? std::vector<int>{1, 5} : std::vector<int>{1, 2, 5, 10}) {
    const double r = heave_ratio(10.0, quads, wavelength, o) / finest;  // the scale variant cancels here
    same.points.push_back(relative_point(2.0 * quads * quads, 1.0, r * o.scale(), 0.02));
  }
  return {law, same};
}

// Bodies and the floor: a dense buoy dropped onto a flat and a sloping floor comes to rest on it; a light
// box released on the floor rises and floats at its draught.
Law floor_contact(const ValidateOptions& o) {
  Law law{
      .id = "bodies.floor",
      .title = "Bodies rest on the floor, light ones rise from it",
      .source = "contact: no penetration; Archimedes",
      .measured_on = "cpu: physics/floating_body.h with a floor",
      .x_label = "case (1 flat, 2 slope 15°: dense; 3: light on the floor)",
      .y_label = "gap to the floor / to the floating level (m)",
      .tolerance = "±0.05 m",
      .note =
          "Cases 1-2: a 1 m box of 20000 kg/m³ dropped from the surface onto a floor 6 m down (flat, then "
          "sloping 15°), after 30 s: its lowest point's height above the floor under it. Case 3: a 2 x 0.5 x "
          "2 m raft of 500 kg/m³ released resting on the flat floor, after 30 s: its lowest point's depth "
          "against its still-water draught."};
  const physics::TriangleMesh hull = box({1, 1, 1}, 1);
  const double depth = 6.0, slope = std::tan(15.0 * kPi / 180.0);
  const auto flat = [depth](double, double) { return -depth; };
  const auto sloped = [depth, slope](double x, double) { return -depth + slope * x; };
  const auto still = [](double, double) { return 0.0; };
  auto run = [&](double density, const physics::FloorHeight& floor, double start_y) {
    physics::BodyOptions options = body_options(o);
    if (o.broken != "no-floor") options.floor = floor;
    physics::FloatingBody body = make_body(hull, density, options);
    body.place({0, start_y, 0}, glm::dquat(1, 0, 0, 0));
    for (double t = 0; t < 30.0; t += 1.0 / 120.0) body.step(1.0 / 120.0, still);
    return body;
  };
  {
    const physics::FloatingBody b = run(20000, flat, -0.5);
    law.points.push_back(absolute_point(1, 0.0, (lowest_y(b, hull) + depth) * o.scale(), 0.05));
  }
  {
    const physics::FloatingBody b = run(20000, sloped, -0.5);
    // The floor under its lowest corner: the box rests tilted on the slope.
    double gap = 1e300;
    for (const glm::dvec3& v : hull.vertices) {
      const glm::dvec3 p = b.model_origin() + b.state().orientation * v;
      gap = std::min(gap, p.y - sloped(p.x, p.z));
    }
    law.points.push_back(absolute_point(2, 0.0, gap * o.scale(), 0.05));
  }
  {
    // Flat (2 x 0.5 x 2 m) so that it floats upright: a cube of half the water's density would roll onto
    // an edge (metacentric height < 0 for 0.21 < ρ_b/ρ < 0.79).
    const physics::TriangleMesh raft = box({2, 0.5, 2}, 1);
    physics::BodyOptions options = body_options(o);
    if (o.broken != "no-floor") options.floor = flat;
    physics::FloatingBody b = make_body(raft, 500, options);
    b.place({0, -depth + 0.25, 0}, glm::dquat(1, 0, 0, 0));
    for (double t = 0; t < 30.0; t += 1.0 / 120.0) b.step(1.0 / 120.0, still);
    law.points.push_back(absolute_point(3, -0.5 * 500.0 / kRho, lowest_y(b, raft) * o.scale(), 0.05));
  }
  return law;
}

}  // namespace

std::vector<Law> body_laws(const ValidateOptions& o) {
  std::vector<Law> laws;
  if (o.wants("bodies.archimedes")) laws.push_back(archimedes(o));
  if (o.wants("bodies.box-heave") || o.wants("bodies.tessellation"))
    for (Law& law : heave(o)) laws.push_back(std::move(law));
  if (o.wants("bodies.floor")) laws.push_back(floor_contact(o));
  return laws;
}

}  // namespace lagoon::cli
