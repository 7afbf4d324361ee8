#include "render/surface_fields.h"

#include <algorithm>

#include "ocean/direct_waves.h"
#include "shared/direct_waves.h"
#include "shared/sediment.h"
#include "shared/shoaling.h"
#include "shared/surface.h"

namespace lagoon::render {

std::vector<vk::Binding> surface_field_bindings(const SurfaceFields& fields, const Samplers& samplers) {
  std::vector<vk::Binding> bindings;
  const ocean::GpuOcean& ocean = fields.ocean;
  for (uint32_t slot = 0; slot < LAGOON_MAX_CASCADES; ++slot) {
    const ocean::CascadeTextures t = ocean.cascade(std::min(slot, ocean.cascade_count() - 1));
    bindings.push_back(
        vk::bind(LAGOON_SURFACE_BIND_DISPLACEMENT, sampled(*t.displacement, samplers.repeat), slot));
    bindings.push_back(
        vk::bind(LAGOON_SURFACE_BIND_JACOBIAN_TERMS, sampled(*t.jacobian_terms, samplers.repeat), slot));
    bindings.push_back(
        vk::bind(LAGOON_SURFACE_BIND_NORMAL_JACOBIAN, sampled(*t.normal_jacobian, samplers.repeat), slot));
  }
  // Repeat addressing: the layer's storage is toroidal (ocean/dynamic_layer.h).
  bindings.push_back(vk::bind(LAGOON_SURFACE_BIND_WAKES, sampled(fields.wakes.fields(), samplers.repeat)));
  bindings.push_back(vk::bind(LAGOON_SURFACE_BIND_SHOALING, ocean.shoaling_gpu().table()));
  return bindings;
}

std::vector<vk::SpecConstant> with_surface_field_specs(std::vector<vk::SpecConstant> own,
                                                       const SurfaceFields& fields) {
  // A sea summed where it is drawn samples no cascade (the step's layer is for export and read-backs).
  const bool direct = ocean::evaluated_directly(fields.ocean.params());
  own.push_back({LAGOON_SPEC_CASCADE_COUNT, direct ? 0u : fields.ocean.cascade_count()});
  const ocean::GerstnerSurface* waves = fields.ocean.direct_waves();
  own.push_back({LAGOON_SPEC_DIRECT_WAVES,
                 waves ? uint32_t(std::min<size_t>(waves->size(), LAGOON_DIRECT_MAX_WAVES)) : 0u});
  own.push_back({LAGOON_SURFACE_SPEC_WAKES, fields.wakes.active() ? 1u : 0u});
  own.push_back({LAGOON_SURFACE_SPEC_SHOALING, fields.ocean.shoaling_gpu().mode()});
  own.push_back({LAGOON_SURFACE_SPEC_SEDIMENT, fields.sediment ? 1u : 0u});
  return own;
}

}  // namespace lagoon::render
