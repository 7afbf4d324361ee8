#include "dataset/render_sequence.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "dataset/frame_metadata.h"
#include "dataset/ground_truth.h"
#include "dataset/manifest.h"
#include "io/atomic_file.h"
#include "io/npy.h"
#include "io/png.h"

namespace lagoon::dataset {
namespace {

namespace fs = std::filesystem;

// The manifest this shard continues: its entries whose files still match, or a new one; an error when the
// folder holds a manifest of another run.
Result<Manifest> resume_manifest(const fs::path& path, const SequenceRun& run) {
  Manifest fresh{.run = run.run,
                 .frames = run.sequence.frames,
                 .shard_index = run.sequence.shard.index,
                 .shard_count = run.sequence.shard.count};
  std::error_code ec;
  if (!fs::exists(path, ec)) return fresh;
  Result<Manifest> old = read_manifest(path);
  if (!old) return old.error();
  if (old->run != fresh.run || old->frames != fresh.frames)
    return Error{
        path.string() +
        " was written by another run (its scene, options or frame count differ); render into another "
        "folder or delete the old set first"};
  for (ManifestFrame& entry : old->entries)
    if (entry_mismatch(path.parent_path(), entry).empty()) fresh.entries.push_back(std::move(entry));
  return fresh;
}

// The requested ground truth of the frame just drawn, as float32 .npy files named STEM.<aov>.npy.
Result<std::vector<std::string>> write_aovs(const SequenceRun& run, const scene::Scene& scene,
                                            render::OceanRenderer& renderer, const fs::path& stem) {
  std::vector<std::string> names;
  if (run.aovs.empty()) return names;
  const GroundTruth gt = frame_ground_truth(
      renderer, scene, std::any_of(run.aovs.begin(), run.aovs.end(), GroundTruth::needs_terms));
  const size_t h = gt.height, w = gt.width;
  for (const std::string& kind : run.aovs) {
    const std::vector<float>& values = gt.plane(kind);
    const std::vector<size_t> shape =
        values.size() == 3 * h * w ? std::vector<size_t>{h, w, 3} : std::vector<size_t>{h, w};
    const std::string name = stem.filename().string() + "." + kind + ".npy";
    if (Result<void> ok = io::write_npy(stem.parent_path() / name, values, shape); !ok) return ok.error();
    names.push_back(name);
  }
  return names;
}

// Writes the frame's files and returns their manifest entries (names relative to the output folder).
Result<std::vector<ManifestFile>> write_frame(const SequenceRun& run, const scene::Scene& scene,
                                              render::OceanRenderer& renderer, long long frame,
                                              const io::Image8& image) {
  const fs::path stem(frame_stem(run.out_png, frame, run.sequence));
  const fs::path folder = stem.parent_path();
  const std::string png = stem.filename().string() + ".png", meta = stem.filename().string() + ".json";
  if (Result<void> ok = io::write_png(folder / png, image); !ok) return ok.error();
  Result<std::vector<std::string>> aovs = write_aovs(run, scene, renderer, stem);
  if (!aovs) return aovs.error();
  const FrameFiles listed{.image = png, .aovs = run.aovs, .aov_files = *aovs};
  const std::string text = frame_metadata(scene, frame, listed).dump(2) + "\n";
  if (Result<void> ok = io::write_text_atomic(folder / meta, text); !ok) return ok.error();
  std::vector<ManifestFile> files;
  std::vector<std::string> names = {png, meta};
  names.insert(names.end(), aovs->begin(), aovs->end());
  for (const std::string& name : names) {
    Result<ManifestFile> file = describe_file(folder / name, name);
    if (!file) return file.error();
    files.push_back(std::move(*file));
  }
  return files;
}

}  // namespace

Result<SequenceSummary> render_sequence(const SequenceRun& run, scene::Scene& scene, vk::Context& ctx,
                                        render::OceanRenderer& renderer) {
  renderer.set_history(render::OceanRenderer::History::Sequence);
  const fs::path manifest_file = manifest_path(run.out_png, run.sequence.shard);
  Result<Manifest> manifest = resume_manifest(manifest_file, run);
  if (!manifest) return manifest.error();
  Result<ManifestWriter> writer = ManifestWriter::create(manifest_file, *manifest);
  if (!writer) return writer.error();
  std::set<long long> done;
  for (const ManifestFrame& entry : manifest->entries) done.insert(entry.frame);
  const std::vector<long long> frames = run.sequence.frames_of_shard();
  const size_t skipped =
      std::count_if(frames.begin(), frames.end(), [&](long long f) { return done.count(f); });
  const double t0 = scene.time_s;
  const scene::Camera lens = scene.camera;
  size_t finished = skipped;
  if (run.progress) run.progress(finished, frames.size(), skipped);
  // Every frame from the first is brought about in order, so the foam and the wakes each carries on are the
  // same in every shard and after a restart; only this shard's unfinished ones are drawn.
  const std::set<long long> mine(frames.begin(), frames.end());
  const long long last = frames.empty() ? -1 : frames.back();
  for (long long f = 0; f <= last; ++f) {
    scene.time_s = float(t0 + run.sequence.offset_s(f));
    if (run.path) scene.camera = run.path->at(run.sequence.offset_s(f), lens);
    if (!mine.count(f) || done.count(f)) {
      renderer.advance(scene);
      continue;
    }
    const io::Image8 image = renderer.render(scene);
    // A frame rendered with validation errors is not written: it cannot be trusted.
    if (const uint32_t failures = ctx.validation().failures(); failures > 0)
      return Error{"frame " + std::to_string(f) + " was drawn while the Vulkan validation layer reported " +
                   std::to_string(failures) + " error(s); nothing of it was written"};
    Result<std::vector<ManifestFile>> files = write_frame(run, scene, renderer, f, image);
    if (!files) return files.error();
    Result<void> listed = writer->append(
        {.frame = f, .time_s = scene.time_s, .device = ctx.device_info().name, .files = *files});
    if (!listed) return listed.error();
    if (run.progress) run.progress(++finished, frames.size(), skipped);
  }
  return SequenceSummary{.frames = frames.size(), .skipped = skipped, .manifest = manifest_file.string()};
}

}  // namespace lagoon::dataset
