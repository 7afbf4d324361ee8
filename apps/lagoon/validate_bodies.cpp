#include "validate_bodies.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <string>

#include "physics/airy_wave.h"
#include "physics/floating_body.h"
#include "physics/hydrostatics.h"
#include "physics/sphere_mesh.h"

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

// The IEA OES Task 10 floating sphere (Wendt et al. 2019): R = 5 m, half immersed (m = 261.8 t in fresh
// water), heaving only, with the heave added mass and radiation damping (physics/heave_radiation.h) and no
// hand-tuned damping.
constexpr double kSphereRadius = 5.0, kFresh = 1000.0;

physics::FloatingBody task10_sphere(const ValidateOptions& o) {
  const physics::TriangleMesh hull = physics::uv_sphere(kSphereRadius, 32);
  physics::BodyOptions options = body_options(o);
  options.radiation.enabled = o.broken != "no-radiation";
  physics::FloatingBody body(hull, physics::solid_mass_properties(hull, 0.5 * kFresh),
                             physics::Damping{0, 0, 0, 0}, physics::WaterProperties{kFresh, kG},
                             std::move(options));
  body.place({0, 0, 0}, glm::dquat(1, 0, 0, 0));
  return body;
}

// Hulme (1982) for the floating hemisphere in heave, deep water: μ = A / (ρ ⅔πa³) and ν = B / (ρ ⅔πa³ ω)
// against ka = ω²a/g (transcribed in LHEEA/Hulme_Heaving_Sphere, comparison/HulmeResult.dat).
struct HulmeRow {
  double ka, mu, nu;
};
constexpr HulmeRow kHulme[] = {
    {0.0, 0.8310, 0.0},    {0.05, 0.8764, 0.1036}, {0.1, 0.8627, 0.1816}, {0.2, 0.7938, 0.2793},
    {0.3, 0.7157, 0.3254}, {0.4, 0.6452, 0.3410},  {0.5, 0.5861, 0.3391}, {0.6, 0.5381, 0.3271},
    {0.7, 0.4999, 0.3098}, {0.8, 0.4698, 0.2899},  {0.9, 0.4464, 0.2691}, {1.0, 0.4284, 0.2484},
    {1.2, 0.4047, 0.2096}, {1.4, 0.3924, 0.1756},  {1.6, 0.3871, 0.1469}, {1.8, 0.3864, 0.1229},
    {2.0, 0.3884, 0.1031}, {2.5, 0.3988, 0.0674},  {3.0, 0.4111, 0.0452}, {4.0, 0.4322, 0.0219},
    {5.0, 0.4471, 0.0116}, {6.0, 0.4574, 0.0066},  {7.0, 0.4647, 0.0040}, {8.0, 0.4700, 0.0026},
    {9.0, 0.4740, 0.0017}, {10.0, 0.4771, 0.0012}};

HulmeRow hulme(double ka) {
  for (size_t i = 1; i < std::size(kHulme); ++i)
    if (ka <= kHulme[i].ka) {
      const HulmeRow &a = kHulme[i - 1], &b = kHulme[i];
      const double f = (ka - a.ka) / (b.ka - a.ka);
      return {ka, a.mu + f * (b.mu - a.mu), a.nu + f * (b.nu - a.nu)};
    }
  return kHulme[std::size(kHulme) - 1];
}

// Linear potential theory's heave RAO of the sphere at wave period T: Hulme's added mass and damping, the
// excitation from the damping by the Haskind relation (deep water, axisymmetric: |X|² = 2ρg³B/ω³).
double linear_rao(double period) {
  const double w = 2 * kPi / period, a = kSphereRadius, volume = 2.0 / 3.0 * kPi * a * a * a;
  const HulmeRow h = hulme(w * w * a / kG);
  const double m = kFresh * volume, added = h.mu * kFresh * volume, damping = h.nu * kFresh * volume * w;
  const double c = kFresh * kG * kPi * a * a;
  const double excitation = std::sqrt(2 * kFresh * kG * kG * kG * damping / (w * w * w));
  const double re = c - w * w * (m + added), im = w * damping;
  return excitation / std::sqrt(re * re + im * im);
}

// The heave amplitude over the wave's in a regular wave of 0.2 % steepness (the OES runs'), after the
// start-up: the wave grows in over 3 periods, the last 6 of 20 are measured.
double sphere_rao(double period, const ValidateOptions& o) {
  physics::FloatingBody body = task10_sphere(o);
  const double w = 2 * kPi / period, k = w * w / kG;
  physics::AiryWave wave{.amplitude = 0.002 * kPi / k, .wavenumber = k, .gravity = kG};
  const double amp = wave.amplitude;
  double lo = 1e300, hi = -1e300;
  const bool dynamic = o.broken != "quasi-static";
  for (double t = 0; t < 20 * period; t += 1.0 / 120) {
    wave.amplitude = std::min(t / (3 * period), 1.0) * amp;
    const auto height = [&](double x, double z) { return wave.height(x, z, t); };
    const auto head = [&](double x, double y, double z) { return wave.pressure_head(x, y, z, t); };
    body.step(1.0 / 120, height, std::numeric_limits<double>::infinity(),
              dynamic ? physics::PressureHead(head) : physics::PressureHead());
    if (t > 14 * period)
      lo = std::min(lo, body.state().position.y), hi = std::max(hi, body.state().position.y);
  }
  return 0.5 * (hi - lo) / amp * o.scale();
}

// The free-decay period from 1 m above equilibrium: the mean time between downward crossings of the
// still-water level over the first three swings.
double sphere_decay_period(const ValidateOptions& o) {
  physics::FloatingBody body = task10_sphere(o);
  body.place({0, 1.0, 0}, glm::dquat(1, 0, 0, 0));
  std::vector<double> crossings;
  double last = 1.0;
  const auto still = [](double, double) { return 0.0; };
  for (int i = 1; i < 120 * 60 && crossings.size() < 4; ++i) {
    body.step(1.0 / 120, still);
    const double y = body.state().position.y;
    if (last > 0 && y <= 0) crossings.push_back((i - 1 + last / (last - y)) / 120.0);
    last = y;
  }
  if (crossings.size() < 2) return 0.0;  // it never swung back: the law fails
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1) * o.scale();
}

std::vector<Law> task10(const ValidateOptions& o) {
  const std::string source = "IEA OES Task 10 (Wendt et al. 2019); Hulme 1982";
  Law stiffness{.id = "bodies.sphere-stiffness",
                .title = "Heave stiffness of the Task 10 sphere",
                .source = "hydrostatics: rho g pi R^2 (Wendt et al. 2019's K33)",
                .measured_on = "cpu: physics/hydrostatics.h on the sphere's mesh",
                .x_label = "displacement from equilibrium (m)",
                .y_label = "stiffness (MN/m)",
                .tolerance = "±1 %",
                .note =
                    "R = 5 m, 32 rings x 64 sectors; the change in buoyancy over a small displacement "
                    "from the half-immersed equilibrium, in fresh water."};
  const physics::TriangleMesh hull = physics::uv_sphere(kSphereRadius, 32);
  const auto still = [](double, double) { return 0.0; };
  auto buoyancy = [&](double dy) {
    std::vector<glm::dvec3> at = hull.vertices;
    for (glm::dvec3& v : at) v.y += dy;
    return physics::hydrostatic_wrench(at, hull.indices, still, {0, dy, 0}, kFresh, kG).force.y;
  };
  const double exact = kFresh * kG * kPi * kSphereRadius * kSphereRadius;
  for (double d : {0.01, 0.05, 0.1}) {
    const double k = (buoyancy(-d) - buoyancy(d)) / (2 * d);
    stiffness.points.push_back(relative_point(d, exact / 1e6, k / 1e6 * o.scale(), 0.01));
  }
  // The linear heave oscillator with Hulme's coefficients at resonance: ka = 3 / (2 (1 + μ(ka))).
  double ka = 1.0;
  for (int i = 0; i < 50; ++i) ka = 1.5 / (1.0 + hulme(ka).mu);
  const double natural = 2 * kPi / std::sqrt(ka * kG / kSphereRadius);
  Law decay{.id = "bodies.sphere-decay",
            .title = "Free-decay period of the Task 10 sphere",
            .source = source,
            .measured_on = "cpu: physics/floating_body.h with physics/heave_radiation.h",
            .x_label = "release height (m)",
            .y_label = "period (s)",
            .tolerance = "±10 %",
            .note =
                "Released from 1 m above equilibrium in still fresh water (the OES decay case), no "
                "hand-tuned damping; the mean time between downward crossings over three swings. "
                "Reference: the natural period of linear theory with Hulme's added mass at its own "
                "frequency, " +
                std::to_string(natural).substr(0, 4) +
                " s (the OES codes' decay curves swing at about 4.4 s)."};
  decay.points.push_back(relative_point(1.0, natural, sphere_decay_period(o), 0.10));
  Law rao{.id = "bodies.sphere-rao",
          .title = "Heave RAO of the Task 10 sphere",
          .source = source,
          .measured_on = decay.measured_on,
          .x_label = "wave period (s)",
          .y_label = "heave amplitude / wave amplitude",
          .tolerance = "±20 %",
          .note =
              "Regular waves of 0.2 % steepness in deep fresh water, the last 6 of 20 periods. "
              "Reference: linear potential theory, Hulme's added mass and damping at each frequency "
              "and the excitation from the damping by the Haskind relation, |X|^2 = 2 rho g^3 B / "
              "omega^3 (it reproduces the OES codes' RAO: 0.11 at 3 s, 1.86 at 4.4 s, 1.03 at 8 s)."};
  for (double period : o.quick ? std::vector<double>{4.4}
                               : std::vector<double>{3.0, 3.5, 4.0, 4.4, 5.0, 6.0, 7.0, 8.0, 9.0, 11.0})
    rao.points.push_back(relative_point(period, linear_rao(period), sphere_rao(period, o), 0.20));
  return {stiffness, decay, rao};
}

}  // namespace

std::vector<Law> body_laws(const ValidateOptions& o) {
  std::vector<Law> laws;
  if (o.wants("bodies.archimedes")) laws.push_back(archimedes(o));
  if (o.wants("bodies.box-heave") || o.wants("bodies.tessellation"))
    for (Law& law : heave(o)) laws.push_back(std::move(law));
  if (o.wants("bodies.floor")) laws.push_back(floor_contact(o));
  if (o.wants("bodies.sphere"))
    for (Law& law : task10(o)) laws.push_back(std::move(law));
  return laws;
}

}  // namespace lagoon::cli
