#include "render/cascade_bindings.h"

#include <algorithm>

#include "shared/surface.h"

namespace lagoon::render {

std::vector<vk::Binding> cascade_bindings(const ocean::GpuOcean& ocean, const Samplers& samplers) {
  std::vector<vk::Binding> bindings;
  for (uint32_t slot = 0; slot < LAGOON_MAX_CASCADES; ++slot) {
    const ocean::CascadeTextures t = ocean.cascade(std::min(slot, ocean.cascade_count() - 1));
    bindings.push_back(
        vk::bind(LAGOON_SURFACE_BIND_DISPLACEMENT, sampled(*t.displacement, samplers.repeat), slot));
    bindings.push_back(
        vk::bind(LAGOON_SURFACE_BIND_JACOBIAN_TERMS, sampled(*t.jacobian_terms, samplers.repeat), slot));
    bindings.push_back(
        vk::bind(LAGOON_SURFACE_BIND_NORMAL_JACOBIAN, sampled(*t.normal_jacobian, samplers.repeat), slot));
  }
  return bindings;
}

vk::SpecConstant cascade_count_spec(const ocean::GpuOcean& ocean) {
  return {LAGOON_SPEC_CASCADE_COUNT, ocean.cascade_count()};
}

}  // namespace lagoon::render
