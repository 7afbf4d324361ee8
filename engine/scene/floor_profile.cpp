#include "scene/floor_profile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <mutex>
#include <tuple>

#include "gltf/gltf_loader.h"
#include "shared/shoaling.h"

namespace lagoon::scene {
namespace {

constexpr size_t kMostGridSamples = 256;  // along each axis of a glTF floor's grid

std::shared_ptr<const ocean::DepthProfile> slope_profile(const Seafloor& floor) {
  const glm::dvec2 near(floor.near), far(floor.far);
  const double length = glm::length(far - near);
  if (!(length > 0)) return nullptr;
  auto profile = std::make_shared<ocean::DepthProfile>();
  profile->origin = near;
  profile->axis = (far - near) / length;
  const size_t n = std::clamp<size_t>(size_t(std::ceil(length / 0.25)) + 1, 2, LAGOON_SHOALING_MAX_SAMPLES);
  profile->spacing_m = length / double(n - 1);
  profile->depth_m.resize(n);
  for (size_t i = 0; i < n; ++i)
    profile->depth_m[i] =
        floor.depth_near_m + (double(floor.depth_far_m) - floor.depth_near_m) * double(i) / double(n - 1);
  return profile;
}

// The highest triangle over each grid node (as physics/mesh_floor.h's floor), where the renderer draws the
// model (identity transform, its nodes' own); ocean.depth_m where none is.
std::shared_ptr<const ocean::DepthProfile> mesh_profile(const std::string& file, double sea_depth_m) {
  auto model = gltf::load_gltf(file);
  if (!model) return nullptr;
  std::vector<glm::dvec3> triangles;
  glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (const gltf::Instance& instance : model->instances)
    for (const gltf::Primitive& p : model->meshes[instance.mesh].primitives)
      for (uint32_t i : p.indices) {
        const glm::dvec3 v(instance.world * glm::vec4(p.positions[i], 1.0f));
        triangles.push_back(v);
        lo = glm::min(lo, glm::dvec2(v.x, v.z));
        hi = glm::max(hi, glm::dvec2(v.x, v.z));
      }
  if (triangles.empty() || !(hi.x > lo.x) || !(hi.y > lo.y)) return nullptr;
  auto profile = std::make_shared<ocean::DepthProfile>();
  profile->axis = {1, 0};
  // A margin of kMargin samples at the sea's depth all round: the waves arrive from there as they are.
  constexpr size_t kMargin = 2;
  const double inner = double(kMostGridSamples - 1 - 2 * kMargin);
  profile->spacing_m = std::max({(hi.x - lo.x) / inner, (hi.y - lo.y) / inner, 0.25});
  lo -= double(kMargin) * profile->spacing_m;
  hi += double(kMargin) * profile->spacing_m;
  profile->origin = lo;
  const size_t nu = std::min(kMostGridSamples, size_t(std::ceil((hi.x - lo.x) / profile->spacing_m)) + 1);
  const size_t nv = std::min(kMostGridSamples, size_t(std::ceil((hi.y - lo.y) / profile->spacing_m)) + 1);
  profile->rows = nv;
  std::vector<double> top(nu * nv, -HUGE_VAL);
  const double d = profile->spacing_m;
  // A hostile file's many large triangles would take hours: past this many node tests the floor is left out
  // (the waves keep ocean.depth_m over it), as for an unreadable one.
  constexpr size_t kMostTests = size_t(1) << 28;
  size_t tests = 0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const glm::dvec3 a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    const double area = (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
    if (std::abs(area) < 1e-12) continue;  // seen edge-on from above: no height of its own
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double z0 = std::min({a.z, b.z, c.z}), z1 = std::max({a.z, b.z, c.z});
    for (size_t j = size_t(std::max(0.0, std::ceil((z0 - lo.y) / d))); j < nv && lo.y + d * double(j) <= z1;
         ++j)
      for (size_t i = size_t(std::max(0.0, std::ceil((x0 - lo.x) / d))); i < nu && lo.x + d * double(i) <= x1;
           ++i) {
        if (++tests > kMostTests) return nullptr;
        const double x = lo.x + d * double(i), z = lo.y + d * double(j);
        // Barycentric weights of (x, z) in the triangle's plan view; inside when none is negative.
        const double wb = ((x - a.x) * (c.z - a.z) - (c.x - a.x) * (z - a.z)) / area;
        const double wc = ((b.x - a.x) * (z - a.z) - (x - a.x) * (b.z - a.z)) / area;
        const double wa = 1 - wb - wc;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
        top[j * nu + i] = std::max(top[j * nu + i], wa * a.y + wb * b.y + wc * c.y);
      }
  }
  profile->depth_m.resize(nu * nv);
  for (size_t c = 0; c < nu * nv; ++c) profile->depth_m[c] = std::isfinite(top[c]) ? -top[c] : sea_depth_m;
  return profile;
}

// A glTF floor is read once per file version: parse_scene runs on every edit in the demo's panel.
std::shared_ptr<const ocean::DepthProfile> cached_mesh_profile(const std::string& file, double sea_depth_m) {
  static std::mutex mutex;
  using Key = std::tuple<std::string, std::uintmax_t, std::filesystem::file_time_type, double>;
  static std::map<Key, std::shared_ptr<const ocean::DepthProfile>> cache;
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return nullptr;
  const auto time = std::filesystem::last_write_time(file, error);
  if (error) return nullptr;
  const Key key{file, size, time, sea_depth_m};
  std::lock_guard lock(mutex);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  if (cache.size() >= 4) cache.clear();
  return cache[key] = mesh_profile(file, sea_depth_m);
}

}  // namespace

std::shared_ptr<const ocean::DepthProfile> floor_profile(const Seafloor& floor, double sea_depth_m) {
  switch (floor.type) {
    case SeafloorType::Slope:
      return slope_profile(floor);
    case SeafloorType::Gltf:
      return cached_mesh_profile(floor.file, sea_depth_m);
    case SeafloorType::None:
      break;
  }
  return nullptr;
}

void attach_floor(Scene& scene) {
  scene.ocean.floor = floor_profile(scene.seafloor, scene.ocean.depth_m);
}

}  // namespace lagoon::scene
