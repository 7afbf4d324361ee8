// A small, strict command-line parser: every option is declared once with its help text, so `--help`
// and the errors come from the same table. Unknown options, missing values and stray words are usage errors.
#pragma once
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.h"

namespace lagoon::cli {

struct OptionSpec {
  std::string name;        // "scene" for --scene
  std::string value_name;  // "FILE"; empty for a flag
  std::string help;
  bool required = false;
  bool repeatable = false;
};

struct CommandSpec {
  std::string name;                // "render"
  std::string program = "lagoon";  // what the usage line starts with; "lagoon-demo" with an empty name
  std::string summary;             // one line
  std::vector<OptionSpec> options;
  // Options that may also be given as plain words, in this order ("lagoon bench compute").
  std::vector<std::string> positional;
  std::string details;  // extra paragraphs for --help (environment, examples)
};

class ParsedArgs {
 public:
  bool help = false;
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  std::optional<std::string> get(const std::string& name) const;
  std::vector<std::string> all(const std::string& name) const;
  void add(const std::string& name, std::string value) { values_[name].push_back(std::move(value)); }

 private:
  std::map<std::string, std::vector<std::string>> values_;
};

// Accepts "--name value" and "--name=value". "--help"/"-h" sets help and skips the required checks.
Result<ParsedArgs> parse_args(const CommandSpec& spec, std::span<const std::string> args);
std::string usage(const CommandSpec& spec);

// Strict numbers: the whole text must be the number ("12px" and "" are errors).
std::optional<long long> parse_integer(const std::string& text);
std::optional<double> parse_number(const std::string& text);

// --name as a whole number in [lo, hi], or `fallback` when absent. The error reads
// "--name VALUE must be a whole number from LO to HI" (the caller prefixes the command).
Result<long long> integer_option(const ParsedArgs& args, const std::string& name, long long fallback,
                                 long long lo, long long hi);
// The same for a number (decimals allowed): "--name VALUE must be a number from LO to HI".
Result<double> number_option(const ParsedArgs& args, const std::string& name, double fallback, double lo,
                             double hi);

}  // namespace lagoon::cli
