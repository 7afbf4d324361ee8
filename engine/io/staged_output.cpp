#include "io/staged_output.h"

#include <unistd.h>

namespace lagoon::io {

namespace fs = std::filesystem;

Result<StagedOutput> StagedOutput::create(const fs::path& out_dir) {
  std::error_code ec;
  if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec))
    return make_error(out_dir.string() + " exists and is not a folder");
  const fs::path parent = out_dir.has_parent_path() ? out_dir.parent_path() : fs::path(".");
  const fs::path staging = parent / (".lagoon-staging-" + std::to_string(::getpid()));
  fs::create_directories(staging, ec);
  if (ec) return make_error("cannot create " + staging.string() + ": " + ec.message());
  return StagedOutput(out_dir, staging);
}

StagedOutput::StagedOutput(StagedOutput&& other) noexcept
    : out_(std::move(other.out_)), staging_(std::exchange(other.staging_, fs::path())) {}

StagedOutput::~StagedOutput() {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
}

Result<void> StagedOutput::commit() {
  std::error_code ec;
  fs::create_directories(out_, ec);
  if (ec) return make_error("cannot create " + out_.string() + ": " + ec.message());
  for (const auto& entry : fs::directory_iterator(staging_)) {
    fs::rename(entry.path(), out_ / entry.path().filename(), ec);
    if (ec)
      return make_error("cannot move " + entry.path().filename().string() + " into " + out_.string() + ": " +
                        ec.message());
  }
  fs::remove_all(staging_, ec);
  staging_.clear();
  return {};
}

}  // namespace lagoon::io
