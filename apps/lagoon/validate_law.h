// One law of `lagoon validate` (issue 33, docs/validation.md): a published relation, Lagoon's measurement of
// the same quantity over a range of conditions, and a tolerance at every point. A law holds when every point
// does; its curve is drawn by validate_plot.h and written to the report by validate_report.h.
#pragma once
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

namespace lagoon::cli {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kG = 9.81;  // m/s², as ocean::kGravity and physics::WaterProperties

struct LawPoint {
  double x = 0;              // the condition: wind speed, depth, wave period, ...
  double reference = 0;      // what the law gives
  double measured = 0;       // what Lagoon does
  double low = 0, high = 0;  // the measured value must lie in [low, high]
  bool holds() const { return measured >= low && measured <= high; }
};

struct Law {
  std::string id;           // "sea-state.pm-hs": what --only and --broken name
  std::string title;        // "Significant wave height at full development"
  std::string source;       // the publication
  std::string measured_on;  // "device" (read back from the GPU) or "cpu" and what
  std::string x_label, y_label;
  std::string tolerance;  // "±10 %"
  bool log_x = false, log_y = false;
  std::vector<LawPoint> points;
  std::string note;  // conditions and remarks for the report

  bool holds() const;
  // The worst point's measured/reference ratio, or its difference for absolute tolerances.
  const LawPoint* worst() const;
};

// Points with a relative tolerance (0.1 = ±10 %), a factor (2 = within [ref/2, ref·2]) or an absolute one.
LawPoint relative_point(double x, double reference, double measured, double tolerance);
LawPoint factor_point(double x, double reference, double measured, double factor);
LawPoint absolute_point(double x, double reference, double measured, double tolerance);
// A one-sided bound: measured <= reference·(1 + slack) (a longer fetch never raises the sea, ...).
LawPoint at_most_point(double x, double reference, double measured, double slack);
// The other side: measured >= reference (foam streaks at least so long, ...).
LawPoint at_least_point(double x, double reference, double measured);

// "lagoon validate: <what> done/total" on stderr, on one line that each call rewrites; a newline after the
// last.
void validate_progress(const char* what, size_t done, size_t total);

// What `lagoon validate` runs with: the short set for `make test` or the full ranges.
struct ValidateOptions {
  bool quick = false;
  // A deliberately broken variant of Lagoon to run the laws against (docs/validation.md lists them): each
  // law must then fail. Empty: Lagoon as it is.
  std::string broken;
  // --only: the laws whose id starts with one of these (all when empty).
  std::vector<std::string> only;
  // Whether a law, or a group of laws by an id prefix, is to be run.
  bool wants(const std::string& id) const;
  // Measurements scaled by √2 ("scale" variant): every tolerance must catch it.
  double scale() const { return broken == "scale" ? 1.4142135623730951 : 1.0; }
};

}  // namespace lagoon::cli
