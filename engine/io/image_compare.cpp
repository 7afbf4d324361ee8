#include "io/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>

namespace lagoon::io {
namespace {

bool has_valid_buffer(const Image8& image) {
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

double psnr_from_squared_error(uint64_t squared_error, uint64_t channel_samples) {
  if (squared_error == 0) return std::numeric_limits<double>::infinity();
  const double mse = static_cast<double>(squared_error) / static_cast<double>(channel_samples);
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace

bool CompareResult::within_fraction() const {
  return !size_mismatch && differing_fraction <= options.max_differing_fraction;
}

bool CompareResult::within_psnr() const {
  return !size_mismatch && (options.min_psnr_db <= 0.0 || psnr_db >= options.min_psnr_db);
}

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

CompareResult compare_images(const Image8& actual, const Image8& expected, const CompareOptions& options) {
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
  uint64_t squared_error = 0;  // over RGB; at most 3 * 255^2 per pixel, so 64 bits cannot overflow
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
  r.psnr_db = psnr_from_squared_error(squared_error, r.total_pixels * 3);
  r.passed = r.within_fraction() && r.within_psnr();
  return r;
}

Image8 make_diff_image(const Image8& actual, const Image8& expected, int channel_tolerance) {
  Image8 out;
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

}  // namespace lagoon::io
