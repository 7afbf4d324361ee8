#include "world/floating_objects.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <string>
#include <utility>

#include "gltf/gltf_loader.h"
#include "world/floor_height.h"
#include "world/object_pose.h"
#include "world/vehicle_tracks.h"

namespace lagoon::world {
namespace {

// The model's meshes as one triangle soup in its own coordinates, scaled: the body's hull.
Result<physics::TriangleMesh> load_hull(const std::string& file, float scale, const std::string& field) {
  auto model = gltf::load_gltf(file);
  if (!model) return make_error(field + ".file: " + model.error().message);
  physics::TriangleMesh hull;
  for (const gltf::Instance& instance : model->instances)
    for (const gltf::Primitive& p : model->meshes[instance.mesh].primitives) {
      const uint32_t base = uint32_t(hull.vertices.size());
      for (const glm::vec3& v : p.positions)
        hull.vertices.push_back(double(scale) * glm::dvec3(instance.world * glm::vec4(v, 1.0f)));
      for (uint32_t i : p.indices) hull.indices.push_back(base + i);
    }
  return hull;
}

// The body's mass properties: the solid's, with the scene's mass and ballast (parallel-axis theorem for the
// moved centre).
physics::MassProperties body_mass(const physics::TriangleMesh& hull, const scene::HullBody& f) {
  physics::MassProperties m = physics::solid_mass_properties(hull, double(f.density_kg_m3));
  if (f.mass_kg > 0 && m.mass > 0) {
    m.inertia *= double(f.mass_kg) / m.mass;
    m.mass = double(f.mass_kg);
  }
  const glm::dvec3 d(f.centre_of_mass_offset);
  m.centre += d;
  m.inertia += m.mass * (glm::dot(d, d) * glm::dmat3(1.0) - glm::outerProduct(d, d));
  return m;
}

// `floor`: what it rests on if it sinks (none for the vehicles, which follow their tracks).
// The hull is sampled no finer than the water it feels resolves: the sea on its lattice (its shortest wave
// four spacings long: ocean/local_heights.h), with the wakes added at the same points. A sample per spacing
// gives that wave four; the default floor of 0.2 m more than doubled the small buoy's points (issue 35).
physics::FloatingBody make_body(const physics::TriangleMesh& hull, const scene::HullBody& f,
                                physics::FloorHeight floor = {}) {
  return physics::FloatingBody(
      hull, body_mass(hull, f),
      {.linear = f.linear_damping,
       .quadratic = f.quadratic_damping,
       .angular = f.angular_damping,
       .angular_quadratic = f.angular_damping},
      {}, {.sampling = {.min_spacing_m = ocean::LocalHeightsOptions{}.spacing_m}, .floor = std::move(floor)});
}

// A closed hull with a positive volume, or an error naming `field`.
// `owner` names the scene's element ("objects[2]"), `field` the block the error is about.
Result<physics::TriangleMesh> load_closed_hull(const std::string& file, float scale, const scene::HullBody& f,
                                               const std::string& owner, const std::string& field) {
  auto hull = load_hull(file, scale, owner);
  if (!hull) return hull.error();
  const physics::MassProperties mass = physics::solid_mass_properties(*hull, double(f.density_kg_m3));
  if (!(mass.volume > 1e-9))
    return make_error(field + ": the model's mesh encloses no volume (" + std::to_string(mass.volume) +
                      " m^3); a body in the water needs a closed mesh with outward faces");
  return hull;
}

// A lattice of heights around a hull: its centre is kept its horizontal radius plus two spacings from the
// edge (the hull's points and their bicubic taps stay inside), and the lattice recentres after the hull has
// drifted kDriftM. A lattice four radii wide, recentred in its inner half, sampled twice as many points a
// knot (the step's knots were a fifth of it); a recentre now samples only the new strip
// (ocean/local_heights.h).
// How soon a helper's job must be due for the stepping thread to take it (s of simulated time). Half the wake
// layers' step: a job handed over at the start of an interval is the worker's for the first half of it, so a
// live loop (the worker well ahead) never takes one, and a catch-up spreads what the worker has not reached
// over the steps before it is due (harbour, bench bodies: 0.03-0.07 gave the same worst frames; 0.1 took
// the wake steps from the worker as soon as they were handed over).
constexpr double kHelpWithinS = 0.05;

ocean::LocalHeightsOptions lattice_for(const physics::TriangleMesh& hull) {
  constexpr double kDriftM = 1.5;
  ocean::LocalHeightsOptions options;
  double radius = 0;
  for (const glm::dvec3& v : hull.vertices) radius = std::max(radius, std::hypot(v.x, v.z));
  const double s = options.spacing_m;
  options.keep_inside_m = radius + 2 * s;
  // One spacing more: the lattice's origin is the centre's, rounded down to the spacing.
  const int needed = int(std::ceil(2 * (options.keep_inside_m + kDriftM + s) / s)) + 1;
  options.points_per_side = std::max(options.points_per_side, needed);
  return options;
}

// Where `hull` can reach, in world (x, z).
std::pair<glm::dvec2, glm::dvec2> reach_box(const physics::FloatingBody& hull) {
  const glm::dvec2 centre(hull.state().position.x, hull.state().position.z);
  return {centre - hull.reach(), centre + hull.reach()};
}

// The sea's heights under `hull` with the wakes but vehicles[skip]'s own added (each of its points then costs
// one lookup a step instead of two: issue 35), and the bound on them it steps with.
double prepare_water(ocean::LocalHeights& heights, const physics::FloatingBody& hull,
                     const WakeHeights* wakes, size_t skip) {
  const auto [lo, hi] = reach_box(hull);
  if (wakes)
    heights.add(lo, hi, [wakes, skip](std::span<const glm::dvec2> points, std::span<double> out) {
      wakes->add_heights(points, out, skip);
    });
  return heights.highest(lo, hi);
}

long long step_at(double time_s) {
  return (long long)std::floor(std::max(time_s, 0.0) / FloatingObjects::kStepS + 1e-9);
}

}  // namespace

Result<std::unique_ptr<FloatingObjects>> FloatingObjects::create(
    const scene::Scene& scene, const ocean::OceanParams& ocean,
    const std::vector<ocean::CascadeSpectrum>& spectra, VehicleTracks tracks) {
  std::unique_ptr<FloatingObjects> out(new FloatingObjects(scene, ocean, spectra));
  out->tracks_ = tracks_or_fresh(scene, std::move(tracks));
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const scene::Object& object = scene.objects[o];
    if (!object.floating.enabled) continue;
    const std::string owner = "objects[" + std::to_string(o) + "]";
    auto hull = load_closed_hull(object.file, object.scale, object.floating, owner, owner + ".floating");
    if (!hull) return make_error(hull.error().message + ", or set floating.enabled to false");
    out->hulls_.push_back(std::move(*hull));
  }
  if (!out->hulls_.empty()) {
    auto floor = floor_height(scene);
    if (!floor) return floor.error();
    out->floor_ = std::move(*floor);
  }
  for (size_t v = 0; v < scene.vehicles.size(); ++v) {
    const scene::Vehicle& vehicle = scene.vehicles[v];
    if (vehicle.depth_m > 0) continue;
    const std::string owner = "vehicles[" + std::to_string(v) + "]";
    auto hull = load_closed_hull(vehicle.file, vehicle.scale, vehicle.body, owner, owner);
    if (!hull) return make_error(hull.error().message + ", or run it submerged (depth_m > 0)");
    out->vehicle_hulls_.push_back(std::move(*hull));
  }
  out->first_step_ = step_at(scene.bodies_start_s);
  if (scene.wakes.felt_by_bodies && !(out->hulls_.empty() && out->vehicle_hulls_.empty())) {
    auto wakes = VehicleWakes::create(scene, out->tracks_);
    if (!wakes) return wakes.error();
    out->wakes_first_step_ = wakes->first_step_for(out->start_s());
    if (!wakes->empty())
      out->wakes_ = std::make_unique<WakeHeights>(*wakes, scene.wakes.bodies_resolution, out->helper_);
  }
  out->reset();
  return out;
}

void FloatingObjects::reset() {
  bodies_.clear();
  if (!sea_ && !(hulls_.empty() && vehicle_hulls_.empty()))
    sea_ = std::make_shared<ocean::WaveQuery>(
        ocean_, spectra_,
        // One thread: the query evaluates its knots on its background worker (LocalHeights asks for them
        // ahead), where a second thread of normal priority would take the core the steps run on (issue 35).
        ocean::WaveQueryOptions{.threads = 1,
                                .max_wavenumber = ocean::lattice_wavenumber(ocean::LocalHeightsOptions{}),
                                .heights_only = true,
                                .worker = helper_});
  size_t h = 0;
  for (size_t o = 0; o < scene_.objects.size(); ++o) {
    const scene::Object& object = scene_.objects[o];
    if (!object.floating.enabled) continue;
    const physics::TriangleMesh& hull = hulls_[h++];
    const scene::Floating& f = object.floating;
    physics::FloatingBody body = make_body(hull, f, floor_);
    body.place(glm::dvec3(object.position), object_orientation(object));
    body.settle_vertically(0.0);  // at its draught on the mean level, so it does not start with a bounce
    bodies_.push_back({o, double(object.scale), std::move(body),
                       std::make_unique<ocean::LocalHeights>(sea_, lattice_for(hull))});
  }
  vehicles_.clear();
  size_t vh = 0;
  for (size_t v = 0; v < scene_.vehicles.size(); ++v) {
    const scene::Vehicle& vehicle = scene_.vehicles[v];
    if (vehicle.depth_m > 0) {
      vehicles_.push_back(
          {double(vehicle.scale), physics::VehicleMotion(tracks_[v], double(vehicle.depth_m)), nullptr});
      continue;
    }
    const physics::TriangleMesh& hull = vehicle_hulls_[vh++];
    vehicles_.push_back({double(vehicle.scale),
                         physics::VehicleMotion(tracks_[v], make_body(hull, vehicle.body)),
                         std::make_unique<ocean::LocalHeights>(sea_, lattice_for(hull))});
  }
  steps_ = first_step_;
  if (first_step_ > 0)
    for (Vehicle& v : vehicles_) v.motion.reset(start_s());
}

long long FloatingObjects::steps_to(double time_s) const {
  const long long target = std::max(step_at(time_s), first_step_);
  return target < steps_ ? target - first_step_ : target - steps_;
}

double FloatingObjects::hull_seconds_to(double time_s) const {
  size_t hulls = bodies_.size();
  for (const Vehicle& v : vehicles_) hulls += v.heights ? 1 : 0;
  return double(steps_to(time_s)) * kStepS * double(hulls);
}

void FloatingObjects::advance(double time_s) {
  const long long target = std::max(step_at(time_s), first_step_);
  if (target < steps_) reset();
  for (; steps_ < target; ++steps_) {
    const double t = double(steps_) * kStepS;
    if (wakes_) wakes_->advance(t, centre(), wakes_first_step_);
    const WakeHeights* wakes = wakes_.get();
    // First what the hulls share: the sea's knots (one WaveQuery for all), with the wakes added under each
    // hull. Then each hull's step, which reads them.
    for (Body& b : bodies_) {
      const glm::dvec3 at = b.body.state().position;
      b.heights->update(t, glm::dvec2(at.x, at.z));
      b.water_top = prepare_water(*b.heights, b.body, wakes, WakeHeights::kNoVehicle);
    }
    for (size_t i = 0; i < vehicles_.size(); ++i) {
      Vehicle& v = vehicles_[i];
      if (!v.heights) continue;
      const glm::dvec3 at = v.motion.model_origin();
      v.heights->update(t, glm::dvec2(at.x, at.z));
      v.water_top = prepare_water(*v.heights, *v.motion.hull(), wakes, i);
    }
    for (Body& b : bodies_) step_body(b);
    for (size_t i = 0; i < vehicles_.size(); ++i) step_vehicle(i, t);
    // A catch-up runs ahead of the worker: a job due soon that it has not begun (a piece of a knot, a layer's
    // step, a lattice's points, ~1 ms each) is taken here, one a step, rather than all of them when needed.
    helper_->help(t + kHelpWithinS);
  }
}

void FloatingObjects::step_body(Body& b) {
  const ocean::LocalHeights& heights = *b.heights;
  b.body.step(
      kStepS, [&heights](double x, double z) { return heights.height(x, z); }, b.water_top, {},
      [&heights](std::span<const glm::dvec2> points, std::span<double> out) {
        heights.heights(points, out);
      });
}

void FloatingObjects::step_vehicle(size_t i, double t) {
  Vehicle& v = vehicles_[i];
  const ocean::LocalHeights* heights = v.heights.get();
  v.motion.step(
      t, kStepS, [heights](double x, double z) { return heights->height(x, z); },
      heights ? v.water_top : std::numeric_limits<double>::infinity(),
      [heights](std::span<const glm::dvec2> points, std::span<double> out) {
        heights->heights(points, out);
      });
}

glm::dvec2 FloatingObjects::centre() const {
  glm::dvec2 sum(0.0);
  double count = 0;
  for (const Body& b : bodies_) {
    sum += glm::dvec2(b.body.state().position.x, b.body.state().position.z);
    ++count;
  }
  for (const Vehicle& v : vehicles_)
    if (v.heights) {
      sum += glm::dvec2(v.motion.model_origin().x, v.motion.model_origin().z);
      ++count;
    }
  return count > 0 ? sum / count : sum;
}

std::vector<FloatingObjects::Pose> FloatingObjects::poses() const {
  std::vector<Pose> out;
  for (const Body& b : bodies_)
    out.push_back({b.object, object_transform(b.body.model_origin(), b.body.state().orientation, b.scale)});
  for (size_t v = 0; v < vehicles_.size(); ++v)
    out.push_back(
        {scene_.objects.size() + v, object_transform(vehicles_[v].motion.model_origin(),
                                                     vehicles_[v].motion.orientation(), vehicles_[v].scale)});
  return out;
}

const physics::FloatingBody* FloatingObjects::body(size_t object) const {
  for (const Body& b : bodies_)
    if (b.object == object) return &b.body;
  return nullptr;
}

const physics::FloatingBody* FloatingObjects::hull_body(size_t object) const {
  if (object >= scene_.objects.size()) {
    const size_t v = object - scene_.objects.size();
    return v < vehicles_.size() ? vehicles_[v].motion.hull() : nullptr;
  }
  return body(object);
}

std::vector<double> FloatingObjects::water_under(size_t object, const std::vector<glm::dvec2>& points) const {
  const ocean::LocalHeights* heights = nullptr;
  if (object >= scene_.objects.size()) {
    const size_t v = object - scene_.objects.size();
    if (v < vehicles_.size()) heights = vehicles_[v].heights.get();
  } else {
    for (const Body& b : bodies_)
      if (b.object == object) heights = b.heights.get();
  }
  std::vector<double> out;
  if (!heights) return out;
  out.reserve(points.size());
  for (const glm::dvec2& p : points) out.push_back(heights->height(p.x, p.y));
  return out;
}

}  // namespace lagoon::world
