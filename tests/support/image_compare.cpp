#include "support/image_compare.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>

namespace lagoon::test {
namespace {

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
