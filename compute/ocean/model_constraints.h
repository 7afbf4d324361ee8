// What a surface model needs of the other ocean fields (docs/models.md), in one table that the scene
// loader (an override that picks a model), the demo's model selector and `lagoon compare` all apply, and that
// validate_ocean_params() enforces for a scene file that picks the model itself.
#pragma once
#include <span>

#include "ocean/ocean_params.h"

namespace lagoon::ocean {

struct ModelConstraint {
  const char* field;            // the OceanParams field, as the scene names it under "ocean."
  double OceanParams::*member;  // that field
  double value;                 // what the model needs it to be
  const char* reason;           // why, for messages: "eqs. 1-3 move the surface only up and down"
};

// Empty for a model that needs nothing of the others' fields.
std::span<const ModelConstraint> model_constraints(SurfaceModel model);

}  // namespace lagoon::ocean
