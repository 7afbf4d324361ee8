#include "ocean/model_constraints.h"

namespace lagoon::ocean {

std::span<const ModelConstraint> model_constraints(SurfaceModel model) {
  // Sines (seed 001, eqs. 1-3) has no horizontal displacement: choppiness would scale nothing but would
  // fold the normals and the Jacobian the other passes derive from it.
  static const ModelConstraint sines[] = {
      {"choppiness", &OceanParams::choppiness, 0.0,
       "eqs. 1-3 move the surface only up and down (use model gerstner for moving crests)"}};
  if (model == SurfaceModel::Sines) return sines;
  return {};
}

}  // namespace lagoon::ocean
