// A camera sequence with its ground truth (`lagoon render --frames/--shard/--path/--aov`, docs/datasets.md):
// every frame from the first brought about in order, the foam and wakes carried from one to the next
// (OceanRenderer::History::Sequence), and this shard's frames drawn, written with their metadata JSON, listed
// in the shard's manifest once complete, and skipped on a second run when their files still match.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/result.h"
#include "dataset/sequence.h"
#include "render/ocean_renderer.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace lagoon::dataset {

struct SequenceRun {
  std::string out_png;
  FrameSequence sequence;
  std::optional<scene::CameraPath> path;
  std::vector<std::string> aovs;  // ground truth to write beside each frame (kAovs), in this order
  nlohmann::json run;             // what the manifest records as the run (scene, checksums, options)
  // Called before the first frame and after each frame written: (finished, this shard's frames, of them
  // finished by an earlier run).
  std::function<void(size_t done, size_t total, size_t skipped)> progress;
};

struct SequenceSummary {
  size_t frames = 0;   // this shard's
  size_t skipped = 0;  // of them, finished by an earlier run and kept
  std::string manifest;
};

// Renders run's shard of the sequence from `scene` (its time_s is the first frame's; its camera the lens a
// path moves). An error names what failed: a manifest of another run in the folder, a file that could not be
// written, or a frame drawn while the Vulkan validation layer reported errors (nothing of it is written).
Result<SequenceSummary> render_sequence(const SequenceRun& run, scene::Scene& scene, vk::Context& ctx,
                                        render::OceanRenderer& renderer);

}  // namespace lagoon::dataset
