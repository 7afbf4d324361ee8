#include "validate_law.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lagoon::cli {

bool Law::holds() const {
  return !points.empty() && std::all_of(points.begin(), points.end(), [](const LawPoint& p) {
    return std::isfinite(p.measured) && p.holds();
  });
}

const LawPoint* Law::worst() const {
  const LawPoint* worst = nullptr;
  double worst_excess = -1e300;
  for (const LawPoint& p : points) {
    // How far outside (or how close to the edge) of its band, in band half-widths.
    const double half = std::max(0.5 * (p.high - p.low), 1e-300), mid = 0.5 * (p.high + p.low);
    const double excess = std::isfinite(p.measured) ? std::abs(p.measured - mid) / half : 1e300;
    if (excess > worst_excess) worst_excess = excess, worst = &p;
  }
  return worst;
}

bool ValidateOptions::wants(const std::string& id) const {
  if (only.empty()) return true;
  for (const std::string& o : only)
    if (id.rfind(o, 0) == 0 || o.rfind(id, 0) == 0) return true;
  return false;
}

LawPoint relative_point(double x, double reference, double measured, double tolerance) {
  const double a = reference * (1.0 - tolerance), b = reference * (1.0 + tolerance);
  return {x, reference, measured, std::min(a, b), std::max(a, b)};
}

LawPoint factor_point(double x, double reference, double measured, double factor) {
  return {x, reference, measured, reference / factor, reference * factor};
}

LawPoint absolute_point(double x, double reference, double measured, double tolerance) {
  return {x, reference, measured, reference - tolerance, reference + tolerance};
}

LawPoint at_most_point(double x, double reference, double measured, double slack) {
  return {x, reference, measured, -1e300, reference * (1.0 + slack)};
}

LawPoint at_least_point(double x, double reference, double measured) {
  return {x, reference, measured, reference, 1e300};
}

void validate_progress(const char* what, size_t done, size_t total) {
  std::fprintf(stderr, "\rlagoon validate: %s %zu/%zu%s", what, done, total, done == total ? "\n" : "");
}

}  // namespace lagoon::cli
