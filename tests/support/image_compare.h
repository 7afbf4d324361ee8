// Golden-image checks for render tests: compare with the golden PNG, or write it in update mode.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>

#include "io/image_compare.h"
#include "io/png.h"

namespace lagoon::test {

// The comparison itself lives in the engine (io/image_compare.h), shared with `lagoon compare-images`;
// these names keep the tests' spelling.
using io::compare_images;
using io::CompareOptions;
using io::CompareResult;
using io::make_diff_image;

// The largest difference of any channel at any pixel (same-size images).
inline int max_channel_difference(const io::Image8& a, const io::Image8& b) {
  return compare_images(a, b, {}).max_channel_difference;
}

// For gtest: compares `actual` with the golden PNG at golden_path. When the environment variable
// LAGOON_UPDATE_GOLDEN=1 is set, writes actual to golden_path and succeeds (prints that it did). On failure
// (or missing golden) writes <artifact_dir>/<stem>.actual.png and <stem>.diff.png (diff only when sizes
// match) and returns an AssertionFailure whose message has the summary and the artifact paths; a missing
// golden file says to run `make update-golden`.
::testing::AssertionResult matches_golden(const io::Image8& actual, const std::filesystem::path& golden_path,
                                          const CompareOptions& options,
                                          const std::filesystem::path& artifact_dir);

}  // namespace lagoon::test
