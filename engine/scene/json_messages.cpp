// How values, ranges and problems are written for users: numbers, JSON values, bounds, did-you-mean
// suggestions, and the Diagnostics that collects the lines. Declared in scene/json_fields.h.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scene/json_fields.h"

namespace lagoon::scene {
namespace {

using nlohmann::json;

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

// Case-insensitive Levenshtein distance.
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitute = diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

// True if `inner` is `outer` or a field/element below it ("camera.position[1]" is within "camera.position").
bool within(std::string_view inner, std::string_view outer) {
  if (!inner.starts_with(outer)) return false;
  return inner.size() == outer.size() || inner[outer.size()] == '.' || inner[outer.size()] == '[';
}

}  // namespace

std::string format_number(double v) {
  char buf[32];
  if (std::abs(v) < 1e15 && std::floor(v) == v) {
    std::snprintf(buf, sizeof buf, "%.0f", v);  // whole numbers exactly: seeds, sizes
    return buf;
  }
  // The shortest text that reads back to the same value, so a saved scene reloads bit for bit; a value
  // that came from a float is printed as that float (0.1f prints "0.1", not 0.10000000149011612).
  const float f = static_cast<float>(v);
  const auto [end, error] = static_cast<double>(f) == v ? std::to_chars(buf, buf + sizeof buf, f)
                                                        : std::to_chars(buf, buf + sizeof buf, v);
  return error == std::errc() ? std::string(buf, end) : std::string("0");
}

// ---- Bounds ----

Bounds Bounds::between(double lo, double hi) {
  Bounds b;
  b.min = lo;
  b.max = hi;
  return b;
}

Bounds Bounds::above(double lo) {
  Bounds b;
  b.min = lo;
  b.min_open = true;
  return b;
}

Bounds Bounds::at_least(double lo) {
  Bounds b;
  b.min = lo;
  return b;
}

Bounds Bounds::above_up_to(double lo, double hi) {
  Bounds b = between(lo, hi);
  b.min_open = true;
  return b;
}

Bounds Bounds::as_float() const {
  // Ends beyond float's range (and ±inf) stay as they are: converting them would be undefined.
  const auto rounded = [](double x) {
    return std::fabs(x) <= std::numeric_limits<float>::max() ? double(static_cast<float>(x)) : x;
  };
  Bounds b = *this;
  b.min = rounded(min);
  b.max = rounded(max);
  return b;
}

bool Bounds::contains(double v) const {
  const bool min_ok = min_open ? v > min : v >= min;
  const bool max_ok = max_open ? v < max : v <= max;
  return min_ok && max_ok;
}

std::string Bounds::describe() const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max && !min_open && !max_open) return format_number(min) + " to " + format_number(max);
  std::string out;
  if (has_min) out = (min_open ? "> " : ">= ") + format_number(min);
  if (has_max)
    out += (out.empty() ? "" : " and ") + std::string(max_open ? "< " : "<= ") + format_number(max);
  return out.empty() ? "any" : out;
}

void Diagnostics::error(std::string_view path, std::string_view problem, std::string_view fix) {
  std::string line = source_ + ": " + (path.empty() ? std::string("(top level)") : std::string(path)) + ": " +
                     std::string(problem) + "; " + std::string(fix);
  // Either direction: --set camera.fov_deg.x=1 turns camera.fov_deg into an object, reported at fov_deg.
  for (const auto& [override_path, assignment] : overrides_) {
    if (!path.empty() && (within(path, override_path) || within(override_path, path))) {
      line += " (value from --set " + assignment + ")";
      break;
    }
  }
  lines_.push_back(std::move(line));
}

void Diagnostics::file_error(std::string_view problem, std::string_view fix) {
  lines_.push_back(source_ + ": " + std::string(problem) + (fix.empty() ? "" : "; " + std::string(fix)));
}

void Diagnostics::note_override(std::string path, std::string assignment) {
  overrides_.insert(overrides_.begin(), {std::move(path), std::move(assignment)});  // last --set wins
}

Error Diagnostics::to_error() const {
  std::string message;
  for (const std::string& line : lines_) message += (message.empty() ? "" : "\n") + line;
  return Error{message};
}

// ---- values and names ----

std::string describe_value(const json& value) {
  // ensure_ascii + replace: never throws on invalid UTF-8, and truncation cannot split a character.
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {  // dump() would print null
    const double v = value.get<double>();
    return std::isnan(v) ? "NaN" : v > 0 ? "infinity" : "-infinity";
  }
  std::string text = value.dump(-1, ' ', /*ensure_ascii=*/true, json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  if (value.is_number() || value.is_null()) return text;
  return std::string(value.type_name()) + " " + text;
}

std::string closest_match(std::string_view name, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const std::string& candidate : candidates) {
    const size_t d = edit_distance(name, candidate);
    // A third of the length (at least 2) catches typos and swaps without suggesting unrelated fields; a
    // shared prefix of 3+ characters catches a missing or extra unit suffix ("fov" vs "fov_deg").
    const size_t shorter = std::min(name.size(), candidate.size());
    const bool prefix =
        shorter >= 3 && edit_distance(name.substr(0, shorter), candidate.substr(0, shorter)) == 0;
    const bool plausible = d <= std::max<size_t>(2, std::max(name.size(), candidate.size()) / 3) || prefix;
    if (plausible && d < best_distance) best_distance = d, best = candidate;
  }
  return best;
}

}  // namespace lagoon::scene
