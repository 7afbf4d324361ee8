// The sea floor as the waves feel it (issue 37, docs/ocean.md "Waves over the floor"): the water's depth
// along one horizontal axis, the same along the other. The slope floor is exactly this (world/floor_profile.h
// samples it); it is what the waves' transformation over the floor (ocean/shoaling.h) is computed on.
// Plain data, no Vulkan.
#pragma once
#include <cmath>
#include <glm/vec2.hpp>
#include <vector>

namespace lagoon::ocean {

struct DepthProfile {
  glm::dvec2 origin{0.0};       // world (x, z) of the first sample, s = 0
  glm::dvec2 axis{0.0, 1.0};    // unit vector along which the depth changes; s = (x - origin)·axis
  double spacing_m = 1.0;       // between samples, > 0
  std::vector<double> depth_m;  // below the mean water level at s = i · spacing_m (< 0: dry land); held
                                // constant beyond both ends

  double s_of(glm::dvec2 xz) const;
  double depth_at(double s) const;  // linear between samples
  double length_m() const { return depth_m.empty() ? 0.0 : spacing_m * double(depth_m.size() - 1); }
  double shallowest_m() const;
};

}  // namespace lagoon::ocean
