#include "args.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/whole_number.h"

namespace lagoon::cli {

std::optional<std::string> ParsedArgs::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> ParsedArgs::all(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

Result<ParsedArgs> parse_args(const CommandSpec& spec, std::span<const std::string> args) {
  ParsedArgs parsed;
  size_t next_positional = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      parsed.help = true;
      return parsed;
    }
    if (arg.rfind("--", 0) != 0) {
      if (next_positional >= spec.positional.size())
        return make_error("unexpected argument '" + arg + "' (options start with --)");
      parsed.add(spec.positional[next_positional++], arg);
      continue;
    }
    std::string name = arg.substr(2);
    std::optional<std::string> inline_value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    const OptionSpec* option = nullptr;
    for (const auto& o : spec.options)
      if (o.name == name) option = &o;
    if (!option) return make_error("unknown option --" + name + " for '" + spec.name + "'");
    if (option->value_name.empty()) {
      if (inline_value) return make_error("--" + name + " takes no value");
      parsed.add(name, "");
    } else {
      if (!inline_value) {
        if (i + 1 >= args.size()) return make_error("--" + name + " needs a value " + option->value_name);
        inline_value = args[++i];
      }
      if (parsed.has(name) && !option->repeatable) return make_error("--" + name + " is given twice");
      parsed.add(name, *inline_value);
    }
  }
  for (const auto& o : spec.options) {
    if (!o.required || parsed.has(o.name)) continue;
    // A word given by position is named as the usage line shows it ("missing B.png"), not as its --option.
    const bool positional =
        std::find(spec.positional.begin(), spec.positional.end(), o.name) != spec.positional.end();
    return make_error(positional ? "missing " + o.value_name : "missing --" + o.name + " " + o.value_name);
  }
  return parsed;
}

std::string usage(const CommandSpec& spec) {
  std::string out = "usage: " + spec.program + (spec.name.empty() ? "" : " " + spec.name);
  for (const auto& name : spec.positional)
    for (const auto& o : spec.options)
      if (o.name == name) out += " " + o.value_name;
  for (const auto& o : spec.options) {
    if (std::find(spec.positional.begin(), spec.positional.end(), o.name) != spec.positional.end()) continue;
    std::string part = "--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
    out += o.required ? " " + part : " [" + part + "]" + (o.repeatable ? "..." : "");
  }
  out += "\n\n" + spec.summary + "\n\noptions:\n";
  for (const auto& o : spec.options) {
    std::string left = "  --" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
    if (left.size() < 26)
      left.resize(26, ' ');
    else
      left += "\n" + std::string(26, ' ');
    out += left + o.help + "\n";
  }
  out += "  --help                  this text\n";
  if (!spec.details.empty()) out += "\n" + spec.details;
  return out;
}

std::optional<long long> parse_integer(const std::string& text) {
  return parse_whole_number(text);
}

Result<long long> integer_option(const ParsedArgs& args, const std::string& name, long long fallback,
                                 long long lo, long long hi) {
  const auto text = args.get(name);
  if (!text) return fallback;
  const auto v = parse_integer(*text);
  if (!v || *v < lo || *v > hi)
    return Error{"--" + name + " " + *text + " must be a whole number from " + std::to_string(lo) + " to " +
                 std::to_string(hi)};
  return *v;
}

Result<double> number_option(const ParsedArgs& args, const std::string& name, double fallback, double lo,
                             double hi) {
  const auto text = args.get(name);
  if (!text) return fallback;
  const auto v = parse_number(*text);
  if (!v || *v < lo || *v > hi) {
    std::ostringstream bounds;
    bounds << lo << " to " << hi;
    return Error{"--" + name + " " + *text + " must be a number from " + bounds.str()};
  }
  return *v;
}

std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace lagoon::cli
