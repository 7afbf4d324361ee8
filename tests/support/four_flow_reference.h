// An independent numerical solution of the four-flow boundary-value problem (seed eqs. 4 and 7), the
// reference for compute/optics/four_flow: multiple shooting on a uniform grid with the transfer matrix
// exp(K Δτ) of the constant-coefficient 4x4 system (Taylor series with scaling and squaring, no
// eigenvectors), and the continuity plus boundary equations solved as banded linear systems.
#pragma once
#include <array>
#include <vector>

#include "optics/four_flow.h"

namespace lagoon::test {

struct FourFlowProfile {
  double step = 0;                          // Δτ between nodes
  std::vector<std::array<double, 4>> flow;  // (G+, G−, F+, F−) at τ = i Δτ, i = 0..segments
};

// segments is rounded up to an even count of at most 0.5 optical depths each, so the middle node is τ0/2.
FourFlowProfile solve_four_flow_reference(const optics::FourFlowInput& input, int segments = 2);

}  // namespace lagoon::test
