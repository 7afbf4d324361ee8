// Several output files that must appear together or not at all: they are written into a staging folder
// beside the output folder and moved in by commit(); the destructor removes whatever was not committed.
#pragma once
#include <filesystem>
#include <string>

#include "core/result.h"

namespace lagoon::io {

class StagedOutput {
 public:
  static Result<StagedOutput> create(const std::filesystem::path& out_dir);
  StagedOutput(StagedOutput&& other) noexcept;
  StagedOutput& operator=(StagedOutput&&) = delete;
  ~StagedOutput();

  // Where to write a file that will become out_dir/name.
  std::filesystem::path file(const std::string& name) const { return staging_ / name; }
  Result<void> commit();

 private:
  StagedOutput(std::filesystem::path out, std::filesystem::path staging)
      : out_(std::move(out)), staging_(std::move(staging)) {}
  std::filesystem::path out_, staging_;
};

}  // namespace lagoon::io
