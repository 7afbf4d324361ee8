// `lagoon render` for sequences and datasets (--frames, --shard, --path): every frame from the first brought
// about in order, the foam and wakes carried from one to the next (OceanRenderer::History::Sequence), and
// this shard's drawn, written with its metadata JSON, listed in the shard's manifest once complete, and
// skipped on a second run when its files still match (docs/datasets.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frame_sequence.h"
#include "render/ground_truth.h"
#include "render/ocean_renderer.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace lagoon::cli {

struct DatasetRun {
  std::string out_png;
  FrameSequence sequence;
  std::optional<scene::CameraPath> path;
  std::vector<std::string> aovs;  // ground truth to write beside each frame (render::kAovs), in this order
  nlohmann::json run;             // what the manifest records as the run (scene, checksums, options)
};

// The process exit code; prints progress on stderr and a summary on stdout.
int render_dataset(const DatasetRun& run, scene::Scene& scene, vk::Context& ctx,
                   render::OceanRenderer& renderer);

}  // namespace lagoon::cli
