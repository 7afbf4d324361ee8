// Golden-image comparison for render tests. Renders differ slightly between drivers, so the check is
// "few pixels differ by more than a small tolerance", not byte equality.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "io/png.h"

namespace lagoon::test {

struct CompareOptions {
  int channel_tolerance = 2;              // a pixel differs when any channel's |a-b| exceeds this (0..255)
  double max_differing_fraction = 0.001;  // test passes when differing pixels / all pixels <= this
  double min_psnr_db = 0.0;               // optional extra bound, 0 = off
};

struct CompareResult {
  bool passed = false;
  bool size_mismatch = false;
  uint64_t differing_pixels = 0;
  double differing_fraction = 0.0;
  int max_channel_difference = 0;  // over R, G, B and A
  double psnr_db = 0.0;            // over RGB, +infinity when identical
  // Context for summary().
  uint64_t total_pixels = 0;
  uint32_t actual_width = 0, actual_height = 0, expected_width = 0, expected_height = 0;
  CompareOptions options;

  std::string summary() const;  // one line with all the numbers and the tolerances
};

// Images whose rgba buffer does not hold width*height*4 bytes count as a size mismatch.
CompareResult compare_images(const io::Image8& actual, const io::Image8& expected,
                             const CompareOptions& options);

// Same size as `expected`: a darkened grey copy of it, with pixels that differ by more than the tolerance
// in magenta, brighter for larger differences. Pixels that `actual` does not cover are full magenta.
io::Image8 make_diff_image(const io::Image8& actual, const io::Image8& expected, int channel_tolerance);

// For gtest: compares `actual` with the golden PNG at golden_path. When the environment variable
// LAGOON_UPDATE_GOLDEN=1 is set, writes actual to golden_path and succeeds (prints that it did). On failure
// (or missing golden) writes <artifact_dir>/<stem>.actual.png and <stem>.diff.png (diff only when sizes
// match) and returns an AssertionFailure whose message has the summary and the artifact paths; a missing
// golden file says to run `make update-golden`.
::testing::AssertionResult matches_golden(const io::Image8& actual, const std::filesystem::path& golden_path,
                                          const CompareOptions& options,
                                          const std::filesystem::path& artifact_dir);

}  // namespace lagoon::test
