#include "dataset/sequence.h"

#include <cstdio>

#include "core/whole_number.h"

namespace lagoon::dataset {

Result<Shard> parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  const auto index = slash == std::string::npos ? std::nullopt : parse_whole_number(text.substr(0, slash));
  const auto count = slash == std::string::npos ? std::nullopt : parse_whole_number(text.substr(slash + 1));
  if (!index || !count)
    return Error{"--shard " + text +
                 " must be I/N: this task's index I from 0 and the number of shards N, "
                 "e.g. --shard 0/4"};
  if (*count < 1 || *count > 100000 || *index < 0 || *index >= *count)
    return Error{"--shard " + text +
                 ": the index must be from 0 to N - 1 and N from 1 to 100000 (a Slurm "
                 "array's --array=0-3 or a Kubernetes Indexed Job's JOB_COMPLETION_INDEX counts from 0)"};
  return Shard{*index, *count};
}

std::vector<long long> FrameSequence::frames_of_shard() const {
  std::vector<long long> list;
  for (long long f = shard.index; f < frames; f += shard.count) list.push_back(f);
  return list;
}

std::string frame_stem(const std::string& out_png, long long frame, const FrameSequence& sequence) {
  const std::string stem = out_png.substr(0, out_png.size() - 4);
  if (sequence.frames == 1 && sequence.shard.count == 1) return stem;
  char suffix[24];  // "_" + up to 19 digits + NUL
  std::snprintf(suffix, sizeof(suffix), "_%04lld", frame);
  return stem + suffix;
}

std::filesystem::path manifest_path(const std::string& out_png, const Shard& shard) {
  return out_png.substr(0, out_png.size() - 4) + ".shard-" + std::to_string(shard.index) + "-of-" +
         std::to_string(shard.count) + ".jsonl";
}

}  // namespace lagoon::dataset
