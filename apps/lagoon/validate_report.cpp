#include "validate_report.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/atomic_file.h"
#include "validate_plot.h"

namespace lagoon::cli {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// The worst point as "reference | Lagoon" cells.
std::pair<std::string, std::string> worst_cells(const Law& law) {
  const LawPoint* w = law.worst();
  if (!w) return {"-", "-"};
  return {number(w->reference), number(w->measured)};
}

std::string markdown(const std::vector<Law>& laws, const ReportContext& c) {
  std::ostringstream md;
  size_t held = 0;
  for (const Law& law : laws) held += law.holds() ? 1 : 0;
  md << "# Lagoon conformance report\n\n"
     << "`lagoon validate" << (c.mode == "quick" ? " --quick" : "")
     << (c.broken.empty() ? "" : " --broken " + c.broken) << "` on **" << c.device << "**, "
     << number(c.seconds) << " s. **" << held << " of " << laws.size() << " laws hold.**\n\n"
     << "Each row shows the point furthest from its law (relative to the tolerance); every point is in "
        "report.json and on the law's plot. How each law is measured: docs/validation.md.\n\n"
     << "| law | reference | Lagoon | tolerance | measured on | verdict |\n|---|---|---|---|---|---|\n";
  for (const Law& law : laws) {
    const auto [ref, got] = worst_cells(law);
    md << "| [" << law.title << "](#" << law.id << ") | " << ref << " | " << got << " | " << law.tolerance
       << " | " << law.measured_on << " | " << (law.holds() ? "holds" : "**FAILS**") << " |\n";
  }
  for (const Law& law : laws) {
    md << "\n## <a id=\"" << law.id << "\"></a>" << law.title << " (`" << law.id << "`)\n\n"
       << "Source: " << law.source << ". Tolerance " << law.tolerance << ". Measured on " << law.measured_on
       << ".\n\n";
    if (!law.note.empty()) md << law.note << "\n\n";
    md << "![" << law.title << "](" << plot_name(law) << ")\n\n| " << law.x_label
       << " | reference | Lagoon | "
       << "allowed | |\n|---|---|---|---|---|\n";
    for (const LawPoint& p : law.points)
      md << "| " << number(p.x) << " | " << number(p.reference) << " | " << number(p.measured) << " | "
         << (p.low < -1e200 ? "≤ " + number(p.high) : number(p.low) + " – " + number(p.high)) << " | "
         << (p.holds() ? "✓" : "✗") << " |\n";
  }
  return md.str();
}

nlohmann::json json_report(const std::vector<Law>& laws, const ReportContext& c) {
  nlohmann::json out{{"device", c.device}, {"mode", c.mode}, {"broken", c.broken}, {"seconds", c.seconds}};
  bool all = true;
  for (const Law& law : laws) {
    nlohmann::json points = nlohmann::json::array();
    for (const LawPoint& p : law.points)
      points.push_back({{"x", p.x},
                        {"reference", p.reference},
                        {"measured", p.measured},
                        {"low", p.low < -1e200 ? nlohmann::json(nullptr) : nlohmann::json(p.low)},
                        {"high", p.high},
                        {"holds", p.holds()}});
    out["laws"].push_back({{"id", law.id},
                           {"title", law.title},
                           {"source", law.source},
                           {"measured_on", law.measured_on},
                           {"x", law.x_label},
                           {"y", law.y_label},
                           {"tolerance", law.tolerance},
                           {"holds", law.holds()},
                           {"note", law.note},
                           {"plot", plot_name(law)},
                           {"points", points}});
    all = all && law.holds();
  }
  out["all_hold"] = all;
  return out;
}

}  // namespace

std::string plot_name(const Law& law) {
  std::string name = law.id;
  for (char& ch : name)
    if (ch == '.') ch = '-';
  return name + ".png";
}

void print_table(const std::vector<Law>& laws) {
  std::printf("%-44s %11s %11s %-14s %s\n", "law", "reference", "Lagoon", "tolerance", "verdict");
  for (const Law& law : laws) {
    const auto [ref, got] = worst_cells(law);
    std::printf("%-44s %11s %11s %-14s %s\n", law.id.c_str(), ref.c_str(), got.c_str(), law.tolerance.c_str(),
                law.holds() ? "holds" : "FAILS");
  }
}

Result<void> write_report(const io::StagedOutput& out, const std::vector<Law>& laws,
                          const ReportContext& context) {
  for (const Law& law : laws)
    if (auto r = io::write_png(out.file(plot_name(law)), law_plot(law)); !r) return r;
  if (auto r = io::write_text_atomic(out.file("report.md"), markdown(laws, context)); !r) return r;
  return io::write_text_atomic(out.file("report.json"), json_report(laws, context).dump(2) + "\n");
}

}  // namespace lagoon::cli
