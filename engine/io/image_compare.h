// Comparing two 8-bit RGBA images: PSNR, the share of pixels that differ beyond a tolerance, and a picture
// of where they differ. Renders differ slightly between drivers, so "the same image" means "few pixels
// differ by more than a small tolerance", not byte equality. One implementation serves the golden-image
// tests and `lagoon compare-images`, so both judge an image the same way.
#pragma once
#include <cstdint>
#include <string>

#include "io/png.h"

namespace lagoon::io {

struct CompareOptions {
  int channel_tolerance = 2;              // a pixel differs when any channel's |a-b| exceeds this (0..255)
  double max_differing_fraction = 0.001;  // passes when differing pixels / all pixels <= this
  double min_psnr_db = 0.0;               // optional extra bound, 0 = off
};

// What Lagoon promises between two devices drawing the same frame (docs/devices.md): at most 1 % of pixels
// more than 8/255 apart and PSNR >= 35 dB. The golden tests on a device other than lavapipe,
// tools/cross-device-check.sh and `lagoon compare-images` (its defaults) all read it from here.
inline constexpr CompareOptions kDeviceAgreement{
    .channel_tolerance = 8, .max_differing_fraction = 0.01, .min_psnr_db = 35.0};

struct CompareResult {
  bool passed = false;  // within_fraction() && within_psnr() and the sizes match
  bool size_mismatch = false;
  uint64_t differing_pixels = 0;
  double differing_fraction = 0.0;
  int max_channel_difference = 0;  // over R, G, B and A
  double psnr_db = 0.0;            // over RGB, +infinity when identical
  // Context for summary().
  uint64_t total_pixels = 0;
  uint32_t actual_width = 0, actual_height = 0, expected_width = 0, expected_height = 0;
  CompareOptions options;

  // Each bound on its own, so a caller can say which one failed. Both false on a size mismatch.
  bool within_fraction() const;
  bool within_psnr() const;
  std::string summary() const;  // one line with all the numbers and the tolerances
};

// Images whose rgba buffer does not hold width*height*4 bytes count as a size mismatch.
CompareResult compare_images(const Image8& actual, const Image8& expected, const CompareOptions& options);

// Same size as `expected`: a darkened grey copy of it, with pixels that differ by more than the tolerance
// in magenta, brighter for larger differences. Pixels that `actual` does not cover are full magenta.
Image8 make_diff_image(const Image8& actual, const Image8& expected, int channel_tolerance);

}  // namespace lagoon::io
