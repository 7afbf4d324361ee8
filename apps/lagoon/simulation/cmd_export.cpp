// lagoon export: the GPU ocean's fields for a run of frames, as .npy arrays plus meta.json; with vehicles,
// the wakes' dynamic layer and foam trails too; with floating objects or vehicles, their poses per frame.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "export_surface.h"
#include "gpu_session.h"
#include "interrupt_guard.h"
#include "io/atomic_file.h"
#include "io/disk_space.h"
#include "io/npy_stream.h"
#include "io/staged_output.h"
#include "ocean/gpu/dynamic_layer_gpu.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/initial_spectrum.h"
#include "scene_args.h"
#include "vk/transfer.h"
#include "world/floating_objects.h"
#include "world/moving_pose.h"
#include "world/vehicle_wakes.h"

namespace lagoon::cli {
namespace {

namespace fs = std::filesystem;

// One frame of one cascade, split into the four arrays' layouts.
struct CascadeArrays {
  std::vector<float> displacement, normal, jacobian, foam;
};

// The wakes' part of meta.json: where the layer's window lies and what its arrays hold.
nlohmann::json wakes_json(const world::VehicleWakes& wakes, glm::ivec2 window) {
  const ocean::DynamicLayerParams& p = wakes.params();
  return {
      {"resolution", p.n},
      {"cell_size_m", p.cell_m},
      {"window_origin_m", {window.x * p.cell_m, window.y * p.cell_m}},
      {"step_s", wakes.step_s()},
      {"files", {{"height", "wakes_height.npy"}, {"foam", "wakes_foam.npy"}}},
      {"layout",
       "float32 arrays [frame][z][x]: sample (i, j) is the layer at world x = x0 + i*cell, z = z0 + j*cell "
       "((x0, z0) = window_origin_m), at the last layer step not after the frame's time. height = the wakes' "
       "height in metres, added to the cascades' (at the surface point's rest position); foam = the foam "
       "trails' coverage in [0, 1]. The window's absorbing border (wakes.border_m) holds no waves."}};
}

nlohmann::json meta_json(const scene::Scene& scene, const ocean::GpuOcean& gpu,
                         const std::vector<double>& times) {
  const ocean::OceanParams& p = scene.ocean;
  nlohmann::json cascades = nlohmann::json::array();
  for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
    const ocean::CascadeSpectrum& s = gpu.spectra()[c];
    const std::string prefix = "cascade" + std::to_string(c);
    cascades.push_back({{"index", c},
                        {"patch_size_m", s.patch_size_m},
                        {"resolution", s.resolution},
                        {"k_min_rad_per_m", s.band.k_min},
                        {"k_max_rad_per_m", s.band.k_max},
                        {"foam_onset", gpu.foam_rule().cascades[c].onset},
                        {"foam_width", gpu.foam_rule().cascades[c].width},
                        {"files",
                         {{"displacement", prefix + "_displacement.npy"},
                          {"normal", prefix + "_normal.npy"},
                          {"jacobian", prefix + "_jacobian.npy"},
                          {"foam", prefix + "_foam.npy"}}}});
  }
  return {
      {"format_version", 1},
      {"generator", "lagoon export"},
      {"times_s", times},
      {"gravity_mps2", ocean::kGravity},
      {"depth_m", p.depth_m},
      {"seed", p.seed},
      {"choppiness", p.choppiness},
      {"loop_period_s", p.loop_period_s},
      {"spectrum",
       {{"type", ocean::to_string(p.spectrum.type)},
        {"wind_speed_mps", p.spectrum.wind_speed_mps},
        {"wind_direction_deg", p.spectrum.wind_direction_deg},
        {"fetch_km", p.spectrum.fetch_km},
        {"gamma", p.spectrum.gamma},
        {"spreading", ocean::to_string(p.spectrum.spreading)},
        {"swell", p.spectrum.swell},
        {"small_wave_cutoff_m", p.spectrum.small_wave_cutoff_m}}},
      {"foam",
       {{"coverage", p.foam.coverage == ocean::FoamCoverage::Monahan ? "monahan" : "threshold"},
        {"threshold", p.foam.threshold},
        {"whole_sea_onset", gpu.foam_rule().whole.onset},
        {"whole_sea_width", gpu.foam_rule().whole.width},
        {"decay_per_s", p.foam.decay_per_s}}},
      {"cascades", cascades},
      {"layout",
       "float32 arrays [frame][z][x](component). Sample (i, j) (column i, row j) rests at x = i*L/N, z = "
       "j*L/N. "
       "displacement = (dx, height, dz) in metres, dx and dz already scaled by the choppiness; the surface "
       "point "
       "is (x + dx, height, z + dz). normal = unit normal from the slopes. jacobian = Jacobian of the "
       "horizontal "
       "map (1 = undisturbed, <= 0 folded). foam in [0, 1]. A scene's surface is the sum over cascades."}};
}

// The four arrays of one cascade, each streamed to its own .npy file a frame at a time.
struct CascadeStreams {
  io::NpyStreamWriter displacement, normal, jacobian, foam;
};

std::vector<size_t> vector_shape(size_t frames, size_t n) {
  return {frames, n, n, 3};
}
std::vector<size_t> scalar_shape(size_t frames, size_t n) {
  return {frames, n, n};
}
std::string cascade_prefix(uint32_t c) {
  return "cascade" + std::to_string(c);
}

// What the export will put on disk: the arrays exactly, meta.json generously (it lists every frame's time).
uint64_t export_bytes(const scene::Scene& scene, const world::VehicleWakes& wakes, size_t frames) {
  const ocean::OceanParams& params = scene.ocean;
  // meta.json: its fixed part, a time per frame, and a pose of each floating object and vehicle per frame
  // (about 800 characters as dump(2) writes one, names aside).
  uint64_t bytes = 16384 + 32 * uint64_t(frames);
  for (const world::MovingTarget& target : world::moving_targets(scene))
    bytes += uint64_t(frames) * (1024 + (target.vehicle ? scene.vehicles[target.index].name.size()
                                                        : scene.objects[target.index].name.size()));
  if (!wakes.empty()) bytes += 2 * io::npy_file_bytes(scalar_shape(frames, wakes.params().n)).value();
  for (const ocean::CascadeParams& c : params.cascades)
    for (const auto& shape : {vector_shape(frames, c.resolution), vector_shape(frames, c.resolution),
                              scalar_shape(frames, c.resolution), scalar_shape(frames, c.resolution)})
      bytes += io::npy_file_bytes(shape).value();  // shapes of at most 1e5 · 1024² · 3 floats never overflow
  return bytes;
}

Result<CascadeStreams> open_streams(const io::StagedOutput& staged, uint32_t c, size_t frames, size_t n) {
  const std::string prefix = cascade_prefix(c);
  auto displacement =
      io::NpyStreamWriter::create(staged.file(prefix + "_displacement.npy"), vector_shape(frames, n));
  if (!displacement) return displacement.error();
  auto normal = io::NpyStreamWriter::create(staged.file(prefix + "_normal.npy"), vector_shape(frames, n));
  if (!normal) return normal.error();
  auto jacobian = io::NpyStreamWriter::create(staged.file(prefix + "_jacobian.npy"), scalar_shape(frames, n));
  if (!jacobian) return jacobian.error();
  auto foam = io::NpyStreamWriter::create(staged.file(prefix + "_foam.npy"), scalar_shape(frames, n));
  if (!foam) return foam.error();
  return CascadeStreams{std::move(*displacement), std::move(*normal), std::move(*jacobian), std::move(*foam)};
}

// Splits one readback's interleaved texels into the four arrays' slabs and appends them. `scratch` is reused
// from frame to frame, so memory holds one frame of one cascade whatever the number of frames.
Result<void> append_frame(CascadeStreams& streams, const ocean::CascadeReadback& r, CascadeArrays& scratch) {
  const size_t texels = r.displacement.size() / 4;
  scratch.displacement.resize(3 * texels);
  scratch.normal.resize(3 * texels);
  scratch.jacobian.resize(texels);
  scratch.foam.resize(texels);
  for (size_t t = 0; t < texels; ++t) {
    for (size_t k = 0; k < 3; ++k) {
      scratch.displacement[3 * t + k] = r.displacement[4 * t + k];
      scratch.normal[3 * t + k] = r.normal_jacobian[4 * t + k];
    }
    scratch.foam[t] = r.displacement[4 * t + 3];
    scratch.jacobian[t] = r.normal_jacobian[4 * t + 3];
  }
  for (auto [stream, data] : {std::pair{&streams.displacement, &scratch.displacement},
                              {&streams.normal, &scratch.normal},
                              {&streams.jacobian, &scratch.jacobian},
                              {&streams.foam, &scratch.foam}})
    if (auto a = stream->append(*data); !a) return a;
  return {};
}

Result<void> commit_streams(std::vector<CascadeStreams>& streams) {
  for (CascadeStreams& s : streams)
    for (io::NpyStreamWriter* w : {&s.displacement, &s.normal, &s.jacobian, &s.foam})
      if (auto r = w->commit(); !r) return r;
  return {};
}

// The wakes' layer stepped with the frames, and its two arrays.
struct WakeExport {
  std::unique_ptr<ocean::DynamicLayerGpu> layer;
  io::NpyStreamWriter height, foam;
  long long steps_done = 0;
  std::vector<float> scratch;
};

Result<WakeExport> open_wake_export(vk::Context& ctx, const io::StagedOutput& staged,
                                    const world::VehicleWakes& wakes, const scene::Scene& scene,
                                    size_t frames) {
  const std::vector<size_t> shape = scalar_shape(frames, wakes.params().n);
  auto height = io::NpyStreamWriter::create(staged.file("wakes_height.npy"), shape);
  if (!height) return height.error();
  auto foam = io::NpyStreamWriter::create(staged.file("wakes_foam.npy"), shape);
  if (!foam) return foam.error();
  WakeExport w{std::make_unique<ocean::DynamicLayerGpu>(ctx, wakes.params()),
               std::move(*height),
               std::move(*foam),
               wakes.first_step_for(scene.time_s),
               {}};
  w.layer->set_window(wakes.window_for(scene.camera));
  return w;
}

// Steps the layer to time t (in submissions of at most kStepsInFlight steps) and appends its window, in world
// order, to both arrays.
Result<void> append_wakes(vk::Context& ctx, const world::VehicleWakes& wakes, WakeExport& w, double t) {
  const long long target = wakes.step_at(t);
  do {
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      const long long end =
          std::min(target, w.steps_done + (long long)ocean::DynamicLayerGpu::kStepsInFlight);
      for (; w.steps_done < end; ++w.steps_done)
        w.layer->record_step(cmd, wakes.step_s(), wakes.sources(double(w.steps_done) * wakes.step_s()));
      vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
    });
  } while (w.steps_done < target);
  const int n = int(wakes.params().n);
  const glm::ivec2 o = w.layer->window();
  auto window_order = [&](const std::vector<std::byte>& raw, int stride) {
    const float* values = reinterpret_cast<const float*>(raw.data());
    w.scratch.resize(size_t(n) * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = ((o.x + i) % n + n) % n, b = ((o.y + j) % n + n) % n;
        w.scratch[size_t(j) * n + i] = values[stride * (size_t(b) * n + a)];
      }
    return w.scratch;
  };
  if (auto r = w.height.append(window_order(vk::readback_buffer(ctx, w.layer->state()), 2)); !r) return r;
  return w.foam.append(window_order(vk::readback_buffer(ctx, w.layer->foam()), 1));
}

// Refuses an export larger than the free space at --out before any work, with both figures.
Result<void> check_space(const fs::path& out, uint64_t bytes) {
  std::fprintf(stderr, "lagoon export: will write %s to %s\n", io::format_bytes(bytes).c_str(), out.c_str());
  auto available = io::available_bytes(out);
  if (!available) return available.error();
  if (bytes > *available) {
    return make_error("the output needs " + io::format_bytes(bytes) + " but only " +
                      io::format_bytes(*available) + " is free at " + out.string() +
                      "; choose fewer --frames, fewer or smaller cascades, or another --out");
  }
  return {};
}

int export_failure(const std::string& message) {
  std::fprintf(stderr, "lagoon export: %s\n", message.c_str());
  return kExitFailure;
}

struct ExportOptions {
  long long frames = 1;
  double dt = 1.0 / 30.0;              // seconds between frames
  std::vector<std::string> overrides;  // --t0 T as --set time_s=T, validated like the scene file
  std::optional<SurfaceWindow> surface;
};

// --frames, --dt and --t0; nullopt (after printing why) when one is out of range.
std::optional<ExportOptions> export_options(const ParsedArgs& args) {
  ExportOptions o;
  const auto frames_arg = integer_option(args, "frames", 1, 1, 100000);
  if (!frames_arg) {
    std::fprintf(stderr, "lagoon export: %s\n", frames_arg.error().message.c_str());
    return std::nullopt;
  }
  o.frames = *frames_arg;
  if (auto v = args.get("dt")) {
    auto d = parse_number(*v);
    if (!d || *d <= 0 || *d > 3600) {
      std::fprintf(stderr, "lagoon export: --dt %s must be a number of seconds in (0, 3600]\n", v->c_str());
      return std::nullopt;
    }
    o.dt = *d;
  }
  if (auto v = args.get("t0")) {
    if (!parse_number(*v)) {
      std::fprintf(stderr, "lagoon export: --t0 %s is not a number of seconds\n", v->c_str());
      return std::nullopt;
    }
    o.overrides.push_back("time_s=" + *v);
  }
  auto surface = surface_window_option(args);
  if (!surface) {
    std::fprintf(stderr, "lagoon export: %s\n", surface.error().message.c_str());
    return std::nullopt;
  }
  o.surface = *surface;
  return o;
}

Result<std::vector<CascadeStreams>> open_all_streams(const io::StagedOutput& staged,
                                                     const ocean::GpuOcean& gpu, size_t frames) {
  std::vector<CascadeStreams> streams;
  for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
    auto s = open_streams(staged, c, frames, gpu.spectra()[c].resolution);
    if (!s) return s.error();
    streams.push_back(std::move(*s));
  }
  return streams;
}

// meta.json, then every array, then the folder itself: the output appears complete or not at all.
Result<void> commit_export(io::StagedOutput& staged, std::vector<CascadeStreams>& streams, WakeExport* wakes,
                           SurfaceExport* surface, const std::string& meta) {
  if (auto r = io::write_text_atomic(staged.file("meta.json"), meta); !r) return r;
  if (auto r = commit_streams(streams); !r) return r;
  if (surface)
    if (auto r = surface->commit(); !r) return r;
  if (wakes)
    for (io::NpyStreamWriter* w : {&wakes->height, &wakes->foam})
      if (auto r = w->commit(); !r) return r;
  return staged.commit();
}

// Steps the GPU ocean frame after frame, streaming every cascade's fields into a staged --out.
int export_fields(vk::Context& ctx, const scene::Scene& scene, const world::VehicleWakes& wakes,
                  const fs::path& out, const ExportOptions& o) {
  // Frames go straight into a staging folder beside the output; it is moved into place only when complete,
  // and removed on any failure or interruption (io::StagedOutput's destructor), so nothing half-written
  // remains.
  InterruptGuard interrupt;
  auto staged = io::StagedOutput::create(out);
  if (!staged) return export_failure(staged.error().message);
  auto gpu_ocean = ocean::GpuOcean::create(ctx, scene.ocean);
  if (!gpu_ocean) return export_failure(gpu_ocean.error().message);
  ocean::GpuOcean& gpu = **gpu_ocean;
  auto streams = open_all_streams(*staged, gpu, size_t(o.frames));
  if (!streams) return export_failure(streams.error().message);
  std::optional<WakeExport> wake;
  if (!wakes.empty()) {
    auto w = open_wake_export(ctx, *staged, wakes, scene, size_t(o.frames));
    if (!w) return export_failure(w.error().message);
    wake.emplace(std::move(*w));
  }
  std::optional<SurfaceExport> surface;
  if (o.surface) {
    auto e = SurfaceExport::create(*staged, scene, gpu.spectra(), *o.surface, size_t(o.frames));
    if (!e) return export_failure(e.error().message);
    surface.emplace(std::move(*e));
  }
  // What floats and the vehicles, simulated on the CPU from bodies_start_s (as in a render of each frame).
  const std::vector<world::MovingTarget> targets = world::moving_targets(scene);
  std::unique_ptr<world::FloatingObjects> moving;
  if (!targets.empty()) {
    auto m = world::FloatingObjects::create(scene, scene.ocean, gpu.spectra());
    if (!m) return export_failure(m.error().message);
    moving = std::move(*m);
  }
  nlohmann::json poses = nlohmann::json::array();
  CascadeArrays scratch;
  std::vector<double> times;
  for (long long f = 0; f < o.frames; ++f) {
    if (interrupt.signal()) {
      std::fprintf(stderr,
                   "\nlagoon export: interrupted by signal %d after %lld of %lld frames; nothing written\n",
                   interrupt.signal(), f, o.frames);
      return interrupt.exit_code();
    }
    const double t = scene.time_s + double(f) * o.dt;
    times.push_back(t);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) { gpu.record_step(cmd, t, f == 0 ? 0.0 : o.dt); });
    for (uint32_t c = 0; c < gpu.cascade_count(); ++c)
      if (auto r = append_frame((*streams)[c], gpu.read_cascade(c), scratch); !r)
        return export_failure(r.error().message);
    if (wake)
      if (auto r = append_wakes(ctx, wakes, *wake, t); !r) return export_failure(r.error().message);
    if (surface)
      if (auto r = surface->append(t); !r) return export_failure(r.error().message);
    if (moving) {
      moving->advance(t);
      nlohmann::json frame = nlohmann::json::array();
      for (const world::MovingTarget& target : targets)
        frame.push_back(world::moving_pose(scene, *moving, target, t));
      poses.push_back(std::move(frame));
    }
    if (o.frames > 1) std::fprintf(stderr, "\rlagoon export: frame %lld/%lld", f + 1, o.frames);
  }
  if (o.frames > 1) std::fprintf(stderr, "\n");
  if (int status = validation_status(ctx); status != kExitOk) return status;

  nlohmann::json meta = meta_json(scene, gpu, times);
  if (wake) meta["wakes"] = wakes_json(wakes, wake->layer->window());
  if (surface) meta["surface"] = surface->meta();
  if (moving)
    meta["poses"] = {
        {"layout",
         "poses[frame][k]: the k-th floating object (objects[] with floating.enabled) or vehicle, "
         "objects first, in scene order, at times_s[frame], as lagoon probe --object prints it: "
         "origin = where the model's origin is (world, m, y up), orientation_wxyz = the model's "
         "rotation as a unit quaternion, velocities of the centre of mass (m/s, rad/s)"},
        {"frames", std::move(poses)}};
  if (auto r = commit_export(*staged, *streams, wake ? &*wake : nullptr, surface ? &*surface : nullptr,
                             meta.dump(2) + "\n");
      !r)
    return export_failure(r.error().message);
  std::printf("wrote %s: %lld frame(s), %u cascade(s), on %s\n", out.c_str(), o.frames, gpu.cascade_count(),
              ctx.device_info().name.c_str());
  return kExitOk;
}

int run_export(const ParsedArgs& args) {
  const fs::path out = *args.get("out");
  const auto options = export_options(args);
  if (!options) return kExitUsage;
  auto scene = load_scene_from_args(args, "export", options->overrides);
  if (!scene) return kExitFailure;
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))  // checked before the GPU work, not after
    return export_failure("--out " + out.string() + " exists and is not a folder");
  auto wakes = world::VehicleWakes::create(*scene);
  if (!wakes) return export_failure(wakes.error().message);
  const uint64_t bytes = export_bytes(*scene, *wakes, size_t(options->frames)) +
                         (options->surface ? surface_bytes(*options->surface, size_t(options->frames)) : 0);
  if (auto space = check_space(out, bytes); !space) return export_failure(space.error().message);
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  return export_fields(*ctx, *scene, *wakes, out, *options);
}

}  // namespace

const Command& export_command() {
  static const Command command{
      .spec =
          {.name = "export",
           .summary =
               "Runs the FFT ocean of a scene for a number of frames on the GPU and writes every "
               "cascade's displacement, normal, Jacobian and foam as float32 .npy arrays, with "
               "meta.json describing times, parameters, layout and each cascade's wavenumber band. With "
               "vehicles (and wakes.enabled), also the wakes' dynamic layer: wakes_height.npy and "
               "wakes_foam.npy over its window (meta.json's \"wakes\"); with floating objects or vehicles, "
               "their pose and velocities at every frame (meta.json's \"poses\").",
           .options =
               {scene_option(),
                {"out", "DIR", "output folder (created; existing files of the same names are replaced)",
                 true},
                {"frames", "N",
                 "number of frames (default 1, at most 100000); each is written as it is "
                 "computed, so memory does not grow with N"},
                {"dt", "S", "seconds between frames (default 1/30); foam evolves with it"},
                {"t0", "T", "time of the first frame (default: the scene's time_s)"},
                {"surface", "X0,Z0,X1,Z1",
                 "also the sea's surface over this window of the world (metres): "
                 "surface_height.npy [frame][z][x], the heights lagoon probe answers there, with the "
                 "floor's shoaling and the swell's turning (the cascades' tiles are the deep sea's; "
                 "meta.json's \"surface\")"},
                {"surface-spacing", "M",
                 "metres between the --surface samples (default 1, 0.01 to 1000; at most 2048 a side)"},
                set_option()},
           .details =
               "The output's size is printed first; an export larger than the free space at --out is refused "
               "before any work. Frames are staged beside --out and moved in only when all are written: "
               "an error, SIGINT or SIGTERM leaves no partial output (exit 128 + the signal's number).\n"
               "example:\n  lagoon export --scene scenes/default.json --out out/fields --frames 30 "
               "--dt 0.1\n  lagoon export --scene scenes/beach.json --out out/beach --surface -40,-60,40,20 "
               "--surface-spacing 0.5\n  python3 -c \"import numpy; print(numpy.load('out/fields/"
               "cascade0_displacement.npy').shape)\"\n"},
      .run = run_export};
  return command;
}

}  // namespace lagoon::cli
