// lagoon export: the GPU ocean's fields for a run of frames, as .npy arrays plus meta.json.
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "io/npy.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/initial_spectrum.h"
#include "scene_args.h"
#include "staged_output.h"

namespace lagoon::cli {
namespace {

namespace fs = std::filesystem;

struct CascadeArrays {
  std::vector<float> displacement, normal, jacobian, foam;
};

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
      {"foam", {{"threshold", p.foam.threshold}, {"decay_per_s", p.foam.decay_per_s}}},
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

int run_export(const ParsedArgs& args) {
  const fs::path out = *args.get("out");
  double dt = 1.0 / 30.0;
  const auto frames_arg = integer_option(args, "frames", 1, 1, 100000);
  if (!frames_arg) {
    std::fprintf(stderr, "lagoon export: %s\n", frames_arg.error().message.c_str());
    return kExitUsage;
  }
  const long long frames = *frames_arg;
  if (auto v = args.get("dt")) {
    auto d = parse_number(*v);
    if (!d || *d <= 0 || *d > 3600) {
      std::fprintf(stderr, "lagoon export: --dt %s must be a number of seconds in (0, 3600]\n", v->c_str());
      return kExitUsage;
    }
    dt = *d;
  }
  std::vector<std::string> overrides;
  if (auto v = args.get("t0")) {
    if (!parse_number(*v)) {
      std::fprintf(stderr, "lagoon export: --t0 %s is not a number of seconds\n", v->c_str());
      return kExitUsage;
    }
    overrides.push_back("time_s=" + *v);
  }
  auto scene = load_scene_from_args(args, "export", overrides);
  if (!scene) return kExitFailure;
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {  // checked before the GPU work, not after
    std::fprintf(stderr, "lagoon export: --out %s exists and is not a folder\n", out.c_str());
    return kExitFailure;
  }
  auto ctx = open_context();
  if (!ctx) return kExitFailure;

  ocean::GpuOcean gpu(*ctx, scene->ocean);
  std::vector<CascadeArrays> arrays(gpu.cascade_count());
  std::vector<double> times;
  for (long long f = 0; f < frames; ++f) {
    const double t = scene->time_s + double(f) * dt;
    times.push_back(t);
    ctx->submit_and_wait([&](VkCommandBuffer cmd) { gpu.record_step(cmd, t, f == 0 ? 0.0 : dt); });
    for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
      const ocean::CascadeReadback r = gpu.read_cascade(c);
      CascadeArrays& a = arrays[c];
      for (size_t i = 0; i < r.displacement.size(); i += 4) {
        a.displacement.insert(a.displacement.end(), &r.displacement[i], &r.displacement[i] + 3);
        a.foam.push_back(r.displacement[i + 3]);
        a.normal.insert(a.normal.end(), &r.normal_jacobian[i], &r.normal_jacobian[i] + 3);
        a.jacobian.push_back(r.normal_jacobian[i + 3]);
      }
    }
    if (frames > 1) std::fprintf(stderr, "\rlagoon export: frame %lld/%lld", f + 1, frames);
  }
  if (frames > 1) std::fprintf(stderr, "\n");
  if (int status = validation_status(*ctx); status != kExitOk) return status;

  // Everything goes to a staging folder next to the output first: a failure leaves nothing.
  auto staged = StagedOutput::create(out);
  if (!staged) {
    std::fprintf(stderr, "lagoon export: %s\n", staged.error().message.c_str());
    return kExitFailure;
  }
  auto fail = [&](const std::string& message) {
    std::fprintf(stderr, "lagoon export: %s\n", message.c_str());
    return kExitFailure;
  };
  const std::string meta = meta_json(*scene, gpu, times).dump(2) + "\n";
  if (auto r = io::write_file_atomic(staged->file("meta.json"),
                                     std::as_bytes(std::span(meta.data(), meta.size())));
      !r)
    return fail(r.error().message);
  for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
    const size_t n = gpu.spectra()[c].resolution, t = size_t(frames);
    const std::string prefix = "cascade" + std::to_string(c);
    const std::vector<size_t> vec_shape{t, n, n, 3}, scalar_shape{t, n, n};
    for (auto [name, data, shape] : {std::tuple{"_displacement.npy", &arrays[c].displacement, &vec_shape},
                                     {"_normal.npy", &arrays[c].normal, &vec_shape},
                                     {"_jacobian.npy", &arrays[c].jacobian, &scalar_shape},
                                     {"_foam.npy", &arrays[c].foam, &scalar_shape}})
      if (auto r = io::write_npy(staged->file(prefix + name), *data, *shape); !r)
        return fail(r.error().message);
  }
  if (auto r = staged->commit(); !r) return fail(r.error().message);
  std::printf("wrote %s: %lld frame(s), %u cascade(s), on %s\n", out.c_str(), frames, gpu.cascade_count(),
              ctx->device_info().name.c_str());
  return kExitOk;
}

}  // namespace

const Command& export_command() {
  static const Command command{
      .spec = {.name = "export",
               .summary =
                   "Runs the FFT ocean of a scene for a number of frames on the GPU and writes every "
                   "cascade's displacement, normal, Jacobian and foam as float32 .npy arrays, with "
                   "meta.json describing times, parameters, layout and each cascade's wavenumber band.",
               .options = {scene_option(),
                           {"out", "DIR",
                            "output folder (created; existing files of the same names are replaced)", true},
                           {"frames", "N", "number of frames (default 1)"},
                           {"dt", "S", "seconds between frames (default 1/30); foam evolves with it"},
                           {"t0", "T", "time of the first frame (default: the scene's time_s)"},
                           set_option()},
               .details =
                   "example:\n  lagoon export --scene scenes/default.json --out out/fields --frames 30 "
                   "--dt 0.1\n  python3 -c \"import numpy; print(numpy.load('out/fields/"
                   "cascade0_displacement.npy').shape)\"\n"},
      .run = run_export};
  return command;
}

}  // namespace lagoon::cli
