// lagoon compare-images: how far apart two renders are (PSNR, share of differing pixels, largest channel
// difference), with an exit code scripts can act on. It judges with io/image_compare.h, the same code as
// the golden-image tests, so "the CLI says they match" and "the test says they match" cannot disagree.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "io/image_compare.h"
#include "io/png.h"

namespace lagoon::cli {
namespace {

// The defaults are the agreement Lagoon promises between devices (io::kDeviceAgreement).
constexpr int kDefaultTolerance = io::kDeviceAgreement.channel_tolerance;
constexpr double kDefaultMaxFraction = io::kDeviceAgreement.max_differing_fraction;
constexpr double kDefaultMinPsnr = io::kDeviceAgreement.min_psnr_db;

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// True when `option` parsed; otherwise prints its message (which names the option and its range).
template <typename T>
bool parsed(const Result<T>& option) {
  if (!option) std::fprintf(stderr, "lagoon compare-images: %s\n", option.error().message.c_str());
  return bool(option);
}

// The bounds from --tolerance, --max-fraction and --min-psnr; nullopt after printing why (a usage error).
std::optional<io::CompareOptions> bounds_from_args(const ParsedArgs& args) {
  const auto tolerance = integer_option(args, "tolerance", kDefaultTolerance, 0, 255);
  const auto fraction = number_option(args, "max-fraction", kDefaultMaxFraction, 0.0, 1.0);
  const auto psnr = number_option(args, "min-psnr", kDefaultMinPsnr, 0.0, 200.0);
  if (!parsed(tolerance) || !parsed(fraction) || !parsed(psnr)) return std::nullopt;
  return io::CompareOptions{
      .channel_tolerance = int(*tolerance), .max_differing_fraction = *fraction, .min_psnr_db = *psnr};
}

bool names_png(const std::string& path) {
  return path.size() > 4 && path.substr(path.size() - 4) == ".png";
}

// nullopt after printing the reason; read_png's message names the file and what is wrong with it.
std::optional<io::Image8> load(const std::string& path) {
  auto image = io::read_png(path);
  if (!image) {
    std::fprintf(stderr, "lagoon compare-images: %s\n", image.error().message.c_str());
    return std::nullopt;
  }
  return std::move(*image);
}

std::string psnr_text(double psnr_db) {
  if (std::isinf(psnr_db)) return "inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", psnr_db);
  return text;
}

// One line per bound that failed, naming the option that sets it; empty when the images agree.
std::vector<std::string> failed_bounds(const io::CompareResult& r) {
  std::vector<std::string> failed;
  char line[256];
  if (!r.within_psnr()) {
    std::snprintf(line, sizeof line, "PSNR %s dB is below --min-psnr %g", psnr_text(r.psnr_db).c_str(),
                  r.options.min_psnr_db);
    failed.push_back(line);
  }
  if (!r.within_fraction()) {
    std::snprintf(line, sizeof line,
                  "fraction of differing pixels %.6g (%llu pixels) is above --max-fraction %g",
                  r.differing_fraction, static_cast<unsigned long long>(r.differing_pixels),
                  r.options.max_differing_fraction);
    failed.push_back(line);
  }
  return failed;
}

void print_text(const std::string& a, const std::string& b, const io::CompareResult& r,
                const std::optional<std::string>& diff) {
  std::printf("%s vs %s: %ux%u\n", a.c_str(), b.c_str(), r.expected_width, r.expected_height);
  std::printf("psnr (RGB)          %s dB (--min-psnr %g)\n", psnr_text(r.psnr_db).c_str(),
              r.options.min_psnr_db);
  std::printf("differing pixels    %llu of %llu, fraction %.6g (--max-fraction %g), by more than %d levels\n",
              static_cast<unsigned long long>(r.differing_pixels),
              static_cast<unsigned long long>(r.total_pixels), r.differing_fraction,
              r.options.max_differing_fraction, r.options.channel_tolerance);
  std::printf("max difference      %d levels (any channel)\n", r.max_channel_difference);
  if (diff) std::printf("diff image          %s\n", diff->c_str());
  const auto failed = failed_bounds(r);
  if (failed.empty()) std::printf("PASS\n");
  for (const std::string& f : failed) std::printf("FAIL: %s\n", f.c_str());
}

// JSON has no infinity: identical RGB gives "psnr_db": null and "rgb_identical": true.
void print_json(const std::string& a, const std::string& b, const io::CompareResult& r,
                const std::optional<std::string>& diff) {
  nlohmann::json doc{{"a", a},
                     {"b", b},
                     {"width", r.expected_width},
                     {"height", r.expected_height},
                     {"psnr_db", std::isinf(r.psnr_db) ? nlohmann::json(nullptr) : nlohmann::json(r.psnr_db)},
                     {"rgb_identical", std::isinf(r.psnr_db)},
                     {"differing_pixels", r.differing_pixels},
                     {"total_pixels", r.total_pixels},
                     {"differing_fraction", r.differing_fraction},
                     {"max_channel_difference", r.max_channel_difference},
                     {"tolerance", r.options.channel_tolerance},
                     {"max_fraction", r.options.max_differing_fraction},
                     {"min_psnr_db", r.options.min_psnr_db},
                     {"passed", r.passed},
                     {"failed", failed_bounds(r)}};
  if (diff) doc["diff"] = *diff;
  std::printf("%s\n", doc.dump(2).c_str());
}

int run_compare_images(const ParsedArgs& args) {
  const auto bounds = bounds_from_args(args);
  if (!bounds) return kExitUsage;
  const auto diff = args.get("diff");
  if (diff && !names_png(*diff)) {
    std::fprintf(stderr, "lagoon compare-images: --diff %s must name a .png file\n", diff->c_str());
    return kExitUsage;
  }
  const std::string a_path = *args.get("a"), b_path = *args.get("b");
  const auto a = load(a_path);
  const auto b = load(b_path);
  if (!a || !b) return kExitFailure;
  // B is measured against A, so the diff picture is drawn over a grey copy of A.
  const io::CompareResult result = io::compare_images(*b, *a, *bounds);
  if (result.size_mismatch) {
    std::fprintf(stderr,
                 "lagoon compare-images: size mismatch: %s is %ux%u, %s is %ux%u; only images of the same "
                 "size can be compared (render both at the same --width and --height)\n",
                 a_path.c_str(), a->width, a->height, b_path.c_str(), b->width, b->height);
    return kExitFailure;
  }
  if (diff) {
    if (auto written = io::write_png(*diff, io::make_diff_image(*b, *a, bounds->channel_tolerance));
        !written) {
      std::fprintf(stderr, "lagoon compare-images: %s\n", written.error().message.c_str());
      return kExitFailure;
    }
  }
  if (args.has("json")) {
    print_json(a_path, b_path, result, diff);
  } else {
    print_text(a_path, b_path, result, diff);
  }
  return result.passed ? kExitOk : kExitFailure;
}

}  // namespace

const Command& compare_images_command() {
  static const Command command{
      .spec =
          {.name = "compare-images",
           .summary = "Compares two PNG images of the same size (e.g. two renders) and says whether they "
                      "agree: PSNR over RGB, how many pixels differ by more than a tolerance, and the "
                      "largest channel difference. Needs no Vulkan device.",
           .options = {{"a", "A.png", "the first image (the reference)", true},
                       {"b", "B.png", "the second image, measured against A", true},
                       {"tolerance", "N",
                        "a pixel differs when any channel (R, G, B or A) differs by more than N levels "
                        "of 255 (default " +
                            std::to_string(kDefaultTolerance) + ")"},
                       {"max-fraction", "F",
                        "pass only if at most this fraction (0..1) of pixels differ (default " +
                            shortest(kDefaultMaxFraction) + ")"},
                       {"min-psnr", "DB",
                        "pass only if the PSNR over RGB is at least DB (default " +
                            shortest(kDefaultMinPsnr) + "; 0 = off)"},
                       {"diff", "OUT.png",
                        "write a picture of the differences: A in dark grey, differing pixels in magenta, "
                        "brighter for larger differences"},
                       {"json", "",
                        "print the results as one JSON object (psnr_db is null when the RGB "
                        "channels are identical)"}},
           .positional = {"a", "b"},
           .details = "The defaults are the agreement Lagoon promises between two devices drawing the same "
                      "frame (docs/devices.md).\n"
                      "PSNR is 'inf' when the RGB channels are identical.\n"
                      "exit codes: 0 the images agree (PSNR >= --min-psnr and fraction <= --max-fraction),\n"
                      "  1 they do not (the failed bound is printed), or a file is missing, not a PNG or of\n"
                      "  a different size; 2 a bad command line.\n"
                      "example:\n  lagoon compare-images out/a.png out/b.png --diff out/diff.png\n"},
      .run = run_compare_images};
  return command;
}

}  // namespace lagoon::cli
