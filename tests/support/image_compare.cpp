#include "support/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <system_error>

namespace lagoon::test {
namespace {

bool has_valid_buffer(const io::Image8& image) {
  return image.rgba.size() == size_t{image.width} * image.height * 4;
}

int max_channel_difference(const uint8_t* a, const uint8_t* b) {
  int d = 0;
  for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int{a[c]} - int{b[c]}));
  return d;
}

std::string percent(double fraction) {
  std::ostringstream s;
  s << std::setprecision(4) << fraction * 100.0 << "%";
  return s.str();
}

// Writes one artifact and returns the line describing it for the failure message.
std::string write_artifact(const char* label, const std::filesystem::path& path, const io::Image8& image) {
  if (Result<void> r = io::write_png(path, image); !r)
    return std::string("\n  ") + label + ": " + r.error().message;
  return std::string("\n  ") + label + ": " + path.string();
}

void remove_quietly(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

}  // namespace

std::string CompareResult::summary() const {
  std::ostringstream s;
  s << (passed ? "PASS: " : "FAIL: ");
  if (size_mismatch) {
    if (actual_width == expected_width && actual_height == expected_height) {
      s << "rgba buffer size does not match width*height*4 (" << actual_width << "x" << actual_height << ")";
    } else {
      s << "size mismatch: actual " << actual_width << "x" << actual_height << ", expected " << expected_width
        << "x" << expected_height;
    }
    s << " (channel tolerance " << options.channel_tolerance << ")";
    return s.str();
  }
  s << differing_pixels << " of " << total_pixels << " pixels differ (" << percent(differing_fraction)
    << ", limit " << percent(options.max_differing_fraction) << ") by more than channel tolerance "
    << options.channel_tolerance << "; max channel difference " << max_channel_difference << "; PSNR ";
  if (std::isinf(psnr_db)) {
    s << "inf";
  } else {
    s << std::fixed << std::setprecision(2) << psnr_db;
  }
  s << " dB";
  if (options.min_psnr_db > 0) s << " (min " << options.min_psnr_db << " dB)";
  return s.str();
}

CompareResult compare_images(const io::Image8& actual, const io::Image8& expected,
                             const CompareOptions& options) {
  CompareResult r;
  r.options = options;
  r.actual_width = actual.width;
  r.actual_height = actual.height;
  r.expected_width = expected.width;
  r.expected_height = expected.height;
  if (actual.width != expected.width || actual.height != expected.height || !has_valid_buffer(actual) ||
      !has_valid_buffer(expected)) {
    r.size_mismatch = true;
    return r;
  }

  r.total_pixels = uint64_t{actual.width} * actual.height;
  uint64_t squared_error = 0;  // over RGB; fits easily: 3 * 255^2 per pixel
  for (size_t i = 0; i < actual.rgba.size(); i += 4) {
    const uint8_t* a = &actual.rgba[i];
    const uint8_t* e = &expected.rgba[i];
    const int d = max_channel_difference(a, e);
    r.max_channel_difference = std::max(r.max_channel_difference, d);
    if (d > options.channel_tolerance) ++r.differing_pixels;
    for (int c = 0; c < 3; ++c) {
      const int64_t diff = int{a[c]} - int{e[c]};
      squared_error += static_cast<uint64_t>(diff * diff);
    }
  }
  r.differing_fraction = r.total_pixels == 0
                             ? 0.0
                             : static_cast<double>(r.differing_pixels) / static_cast<double>(r.total_pixels);
  if (squared_error == 0) {
    r.psnr_db = std::numeric_limits<double>::infinity();
  } else {
    const double mse = static_cast<double>(squared_error) / (static_cast<double>(r.total_pixels) * 3.0);
    r.psnr_db = 10.0 * std::log10(255.0 * 255.0 / mse);
  }
  r.passed = r.differing_fraction <= options.max_differing_fraction &&
             (options.min_psnr_db <= 0.0 || r.psnr_db >= options.min_psnr_db);
  return r;
}

io::Image8 make_diff_image(const io::Image8& actual, const io::Image8& expected, int channel_tolerance) {
  io::Image8 out;
  if (!has_valid_buffer(expected)) return out;  // nothing sensible to draw on
  out.width = expected.width;
  out.height = expected.height;
  out.rgba.resize(expected.rgba.size());
  const bool actual_valid = has_valid_buffer(actual);
  for (uint32_t y = 0; y < out.height; ++y) {
    for (uint32_t x = 0; x < out.width; ++x) {
      const uint8_t* e = expected.pixel(x, y);
      uint8_t* o = out.pixel(x, y);
      const bool covered = actual_valid && x < actual.width && y < actual.height;
      const int d = covered ? max_channel_difference(actual.pixel(x, y), e) : 255;
      if (d > channel_tolerance) {
        // Start well above the grey background so even a difference of tolerance + 1 stands out.
        const auto level = static_cast<uint8_t>(96 + d * 159 / 255);
        o[0] = level;
        o[1] = 0;
        o[2] = level;
      } else {
        // Darkened so the magenta wins against any background, but the scene stays recognisable.
        const auto grey = static_cast<uint8_t>((e[0] * 77 + e[1] * 150 + e[2] * 29) / 256 / 3);
        o[0] = o[1] = o[2] = grey;
      }
      o[3] = 255;
    }
  }
  return out;
}

::testing::AssertionResult matches_golden(const io::Image8& actual, const std::filesystem::path& golden_path,
                                          const CompareOptions& options,
                                          const std::filesystem::path& artifact_dir) {
  const char* update = std::getenv("LAGOON_UPDATE_GOLDEN");
  if (update != nullptr && std::string_view(update) == "1") {
    if (Result<void> r = io::write_png(golden_path, actual); !r) {
      return ::testing::AssertionFailure() << "LAGOON_UPDATE_GOLDEN=1: " << r.error().message;
    }
    std::cout << "[ GOLDEN   ] updated " << golden_path.string() << std::endl;
    return ::testing::AssertionSuccess() << "updated golden " << golden_path.string();
  }

  const std::string stem = golden_path.stem().string();
  const std::filesystem::path actual_path = artifact_dir / (stem + ".actual.png");
  const std::filesystem::path diff_path = artifact_dir / (stem + ".diff.png");
  // Artifacts left by an earlier failing run would mislead whoever looks at the folder.
  remove_quietly(actual_path);
  remove_quietly(diff_path);

  std::error_code ec;
  if (!std::filesystem::exists(golden_path, ec)) {
    return ::testing::AssertionFailure() << "golden image " << golden_path.string()
                                         << " does not exist; run `make update-golden` to create it"
                                         << write_artifact("actual", actual_path, actual);
  }
  Result<io::Image8> golden = io::read_png(golden_path);
  if (!golden) {
    return ::testing::AssertionFailure()
           << golden.error().message << write_artifact("actual", actual_path, actual);
  }

  const CompareResult result = compare_images(actual, *golden, options);
  if (result.passed) return ::testing::AssertionSuccess() << result.summary();

  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  failure << golden_path.string() << ": " << result.summary() << "\n  golden: " << golden_path.string()
          << write_artifact("actual", actual_path, actual);
  if (!result.size_mismatch) {
    failure << write_artifact("diff", diff_path, make_diff_image(actual, *golden, options.channel_tolerance));
  }
  return failure << "\n  If the change is intended, run `make update-golden`.";
}

}  // namespace lagoon::test
