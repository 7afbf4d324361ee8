#include "scene/floor_profile.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "shared/shoaling.h"

namespace lagoon::scene {

std::shared_ptr<const ocean::DepthProfile> floor_profile(const Seafloor& floor) {
  if (floor.type != SeafloorType::Slope) return nullptr;
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

}  // namespace lagoon::scene
