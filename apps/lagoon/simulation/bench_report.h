// What every `lagoon bench` reports with: medians and spreads of timings, rows of the printed table and of
// the --json report (Google Benchmark's shape), the report's context, and --rounds.
#pragma once
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "args.h"
#include "vk/context.h"

namespace lagoon::cli {

using Clock = std::chrono::steady_clock;

struct Spread {
  double median = 0, min = 0, max = 0;
};

// The median of an even count is the mean of the middle two (with 2 rounds, not simply the larger one).
Spread spread(std::vector<double> v);
double median(std::vector<double> v);

// One result in Google Benchmark's shape: real_time is the median over the rounds; min_time and max_time
// show the spread; `measure` says which clock: "gpu timestamps" (device time of the recorded commands) or
// "wall" (host time around submit and wait, what a user waits for).
nlohmann::json result_entry(const std::string& name, const std::vector<double>& ms, const char* measure);

// The report's "context": what the figures were measured on, so reports from two machines can be told
// apart (and a lavapipe figure is never mistaken for a GPU's).
nlohmann::json report_context(const vk::Context& ctx, int rounds);

template <typename F>
double time_ms(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// --rounds, or `fallback`; nullopt (after printing why) when the value is not a whole number in [1, 1000].
std::optional<int> rounds_option(const ParsedArgs& args, int fallback);

// Writes the --json report atomically (no half-written file); false, with the reason on stderr, on failure.
bool write_report(const std::string& path, const nlohmann::json& doc);

// Prints one row of the table and adds it to the report's "benchmarks"; a ratio of 0 is left out.
void report_row(nlohmann::json& results, const std::string& name, const std::vector<double>& ms,
                const char* measure, double ratio);

}  // namespace lagoon::cli
