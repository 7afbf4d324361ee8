#include "dataset_render.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "exit_codes.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "io/dataset_manifest.h"
#include "io/npy.h"
#include "io/png.h"
#include "render/frame_metadata.h"
#include "render/ground_truth.h"

namespace lagoon::cli {
namespace {

namespace fs = std::filesystem;

// The manifest this shard continues: its entries whose files still match, or a new one. nullopt (after
// printing why) when the folder holds a manifest of another run.
std::optional<io::Manifest> resume_manifest(const fs::path& path, const DatasetRun& run) {
  io::Manifest fresh{.run = run.run,
                     .frames = run.sequence.frames,
                     .shard_index = run.sequence.shard.index,
                     .shard_count = run.sequence.shard.count};
  std::error_code ec;
  if (!fs::exists(path, ec)) return fresh;
  Result<io::Manifest> old = io::read_manifest(path);
  if (!old) {
    std::fprintf(stderr, "lagoon render: %s\n", old.error().message.c_str());
    return std::nullopt;
  }
  if (old->run != fresh.run || old->frames != fresh.frames) {
    std::fprintf(stderr,
                 "lagoon render: %s was written by another run (its scene, options or frame count differ); "
                 "render into another folder or delete the old set first\n",
                 path.c_str());
    return std::nullopt;
  }
  for (io::ManifestFrame& entry : old->entries)
    if (io::entry_mismatch(path.parent_path(), entry).empty()) fresh.entries.push_back(std::move(entry));
  return fresh;
}

void print_progress(size_t done, size_t total, size_t skipped) {
  const int bar = int(40 * done / std::max<size_t>(total, 1));
  std::fprintf(stderr, "\r[%s%s] %zu/%zu frames", std::string(bar, '#').c_str(),
               std::string(40 - bar, ' ').c_str(), done, total);
  if (skipped) std::fprintf(stderr, " (%zu already done)", skipped);
}

// The requested ground truth of the frame just drawn, as float32 .npy files named STEM.<aov>.npy.
Result<std::vector<std::string>> write_aovs(const DatasetRun& run, const scene::Scene& scene,
                                            render::OceanRenderer& renderer, const fs::path& stem) {
  std::vector<std::string> names;
  if (run.aovs.empty()) return names;
  const render::GroundTruth gt = render::frame_ground_truth(
      renderer, scene, std::any_of(run.aovs.begin(), run.aovs.end(), render::GroundTruth::needs_terms));
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
Result<std::vector<io::ManifestFile>> write_frame(const DatasetRun& run, const scene::Scene& scene,
                                                  render::OceanRenderer& renderer, long long frame,
                                                  const io::Image8& image) {
  const fs::path stem(frame_stem(run.out_png, frame, run.sequence));
  const fs::path folder = stem.parent_path();
  const std::string png = stem.filename().string() + ".png", meta = stem.filename().string() + ".json";
  if (Result<void> ok = io::write_png(folder / png, image); !ok) return ok.error();
  Result<std::vector<std::string>> aovs = write_aovs(run, scene, renderer, stem);
  if (!aovs) return aovs.error();
  const render::FrameFiles listed{.image = png, .aovs = run.aovs, .aov_files = *aovs};
  const std::string text = render::frame_metadata(scene, frame, listed).dump(2) + "\n";
  if (Result<void> ok = io::write_text_atomic(folder / meta, text); !ok) return ok.error();
  std::vector<io::ManifestFile> files;
  std::vector<std::string> names = {png, meta};
  names.insert(names.end(), aovs->begin(), aovs->end());
  for (const std::string& name : names) {
    Result<io::ManifestFile> file = io::describe_file(folder / name, name);
    if (!file) return file.error();
    files.push_back(std::move(*file));
  }
  return files;
}

}  // namespace

int render_dataset(const DatasetRun& run, scene::Scene& scene, vk::Context& ctx,
                   render::OceanRenderer& renderer) {
  renderer.set_history(render::OceanRenderer::History::Sequence);
  const fs::path manifest_file = manifest_path(run.out_png, run.sequence.shard);
  std::optional<io::Manifest> manifest = resume_manifest(manifest_file, run);
  if (!manifest) return kExitFailure;
  Result<io::ManifestWriter> writer = io::ManifestWriter::create(manifest_file, *manifest);
  if (!writer) {
    std::fprintf(stderr, "lagoon render: %s\n", writer.error().message.c_str());
    return kExitFailure;
  }
  std::set<long long> done;
  for (const io::ManifestFrame& entry : manifest->entries) done.insert(entry.frame);
  const std::vector<long long> frames = run.sequence.frames_of_shard();
  const size_t skipped =
      std::count_if(frames.begin(), frames.end(), [&](long long f) { return done.count(f); });
  const double t0 = scene.time_s;
  const scene::Camera lens = scene.camera;
  size_t finished = skipped;
  print_progress(finished, frames.size(), skipped);
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
    if (int status = validation_status(ctx); status != kExitOk) return status;
    Result<std::vector<io::ManifestFile>> files = write_frame(run, scene, renderer, f, image);
    Result<void> listed =
        files ? writer->append(
                    {.frame = f, .time_s = scene.time_s, .device = ctx.device_info().name, .files = *files})
              : Result<void>(files.error());
    if (!listed) {
      std::fprintf(stderr, "\nlagoon render: %s\n", listed.error().message.c_str());
      return kExitFailure;
    }
    print_progress(++finished, frames.size(), skipped);
  }
  std::fprintf(stderr, "\n");
  std::printf(
      "shard %lld/%lld: %zu frames of %lld (%zu rendered, %zu already done) at %.3g fps, %ux%u, on %s; "
      "manifest %s\n",
      run.sequence.shard.index, run.sequence.shard.count, frames.size(), run.sequence.frames,
      frames.size() - skipped, skipped, run.sequence.fps, scene.render.width, scene.render.height,
      ctx.device_info().name.c_str(), manifest_file.c_str());
  return kExitOk;
}

}  // namespace lagoon::cli
