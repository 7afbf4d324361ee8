// Which frames a `lagoon render` run draws and what their files are called: --frames N at --fps F from the
// scene's time_s, and --shard i/n (frames i, i+n, ...: one shard per cluster task; docs/datasets.md).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.h"

namespace lagoon::dataset {

struct Shard {
  long long index = 0, count = 1;
};

// "i/n" with 0 <= i < n <= 100000; the error says what was wrong and what to write.
Result<Shard> parse_shard(const std::string& text);

struct FrameSequence {
  long long frames = 1;
  double fps = 30.0;
  Shard shard;

  // This shard's frames in increasing order.
  std::vector<long long> frames_of_shard() const;
  // Seconds from the first frame.
  double offset_s(long long frame) const { return double(frame) / fps; }
};

// The common stem of a frame's files: OUT without ".png" for a single unsharded frame, OUT_0000, OUT_0001,
// ... otherwise (at least four digits; as many as N - 1 needs).
std::string frame_stem(const std::string& out_png, long long frame, const FrameSequence& sequence);

// The shard's manifest beside the frames: OUT.shard-I-of-N.jsonl (OUT without ".png").
std::filesystem::path manifest_path(const std::string& out_png, const Shard& shard);

}  // namespace lagoon::dataset
