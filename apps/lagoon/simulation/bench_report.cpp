#include "bench_report.h"

#include <algorithm>
#include <cstdio>
#include <span>

#include "io/atomic_file.h"
#include "vk/device_select.h"

namespace lagoon::cli {

// The median of an even count is the mean of the middle two (with 2 rounds, not simply the larger one).
Spread spread(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  const size_t mid = v.size() / 2;
  const double median = v.size() % 2 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
  return {median, v.front(), v.back()};
}

double median(std::vector<double> v) {
  return spread(std::move(v)).median;
}

// One result in Google Benchmark's shape: real_time is the median over the rounds; min_time and max_time
// show the spread; `measure` says which clock: "gpu timestamps" (device time of the recorded commands) or
// "wall" (host time around submit and wait, what a user waits for).
nlohmann::json result_entry(const std::string& name, const std::vector<double>& ms, const char* measure) {
  const Spread s = spread(ms);
  return {{"name", name},      {"run_type", "iteration"}, {"iterations", ms.size()}, {"real_time", s.median},
          {"min_time", s.min}, {"max_time", s.max},       {"time_unit", "ms"},       {"measure", measure}};
}

// The report's "context": what the figures were measured on, so reports from two machines can be told
// apart (and a lavapipe figure is never mistaken for a GPU's).
nlohmann::json report_context(const vk::Context& ctx, int rounds) {
  const vk::DeviceInfo& info = ctx.device_info();
  return {{"device", info.name},
          {"device_type", info.type},
          {"driver_name", info.driver_name},
          {"driver_info", info.driver_info},
          {"driver_version", info.driver_version},
          {"vulkan_api_version", vk::api_version_string(info.api_version)},
          {"rounds", rounds}};
}

// --rounds, or `fallback`; nullopt (after printing why) when the value is not a whole number in [1, 1000].
std::optional<int> rounds_option(const ParsedArgs& args, int fallback) {
  const auto rounds = integer_option(args, "rounds", fallback, 1, 1000);
  if (!rounds) {
    std::fprintf(stderr, "lagoon bench: %s\n", rounds.error().message.c_str());
    return std::nullopt;
  }
  return int(*rounds);
}

// Writes the --json report atomically (no half-written file); false, with the reason on stderr, on failure.
bool write_report(const std::string& path, const nlohmann::json& doc) {
  const std::string text = doc.dump(2) + "\n";
  if (auto written = io::write_text_atomic(path, text); !written) {
    std::fprintf(stderr, "lagoon bench: %s\n", written.error().message.c_str());
    return false;
  }
  return true;
}

// Prints one row of the table and adds it to the report's "benchmarks"; a ratio of 0 is left out.
void report_row(nlohmann::json& results, const std::string& name, const std::vector<double>& ms,
                const char* measure, double ratio) {
  std::printf("%-44s %12.3f %12s\n", name.c_str(), median(ms),
              ratio > 0 ? (std::to_string(ratio).substr(0, 6) + "x").c_str() : "");
  nlohmann::json entry = result_entry(name, ms, measure);
  if (ratio > 0) entry["ratio_gpu_over_cpu"] = ratio;
  results.push_back(entry);
}

}  // namespace lagoon::cli
