// The foam rule of shared/foam_math.h in double precision, for the CPU's users: the reference step
// (ocean/cpu_step.cpp) and the validation's reading of the drawn foam (apps/lagoon/validate_foam.cpp).
#pragma once
#include <algorithm>

namespace lagoon::ocean {
namespace foam_double {
using foam_real = double;
using std::clamp;
using std::max;
#define LAGOON_FN inline
#include "shared/foam_math.h"
#undef LAGOON_FN
}  // namespace foam_double
using foam_double::foam_after_step;
using foam_double::foam_made;

}  // namespace lagoon::ocean
