// The bar chart of lagoon bench effects (effects.png), drawn by Lagoon itself like the thesis's figures
// 4.3-4.7: one bar per test at its mean frame rate, a whisker from its minimum to its maximum, labelled.
#pragma once
#include <string>
#include <vector>

#include "core/result.h"
#include "io/png.h"

namespace lagoon::cli {

struct EffectBar {
  std::string name;
  double min_fps = 0, avg_fps = 0, max_fps = 0;
};

// Fails when there is nothing to draw or a value is not a positive finite rate.
Result<io::Image8> effects_chart(const std::vector<EffectBar>& bars, const std::string& device);

}  // namespace lagoon::cli
