#include "export_surface.h"

#include <cmath>
#include <string>

namespace lagoon::cli {
namespace {

std::vector<size_t> surface_shape(const SurfaceWindow& w, size_t frames) {
  return {frames, size_t(w.rows), size_t(w.columns)};
}

Result<std::vector<double>> four_numbers(const std::string& text) {
  std::vector<double> values;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    auto v = parse_number(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (!v || !std::isfinite(*v)) break;
    values.push_back(*v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() != 4)
    return make_error("--surface " + text +
                      " must be four numbers X0,Z0,X1,Z1: the window's corners in metres (world x and z), "
                      "e.g. --surface -50,-50,50,50");
  return values;
}

}  // namespace

Result<std::optional<SurfaceWindow>> surface_window_option(const ParsedArgs& args) {
  const auto text = args.get("surface");
  if (!text) {
    if (args.has("surface-spacing")) return make_error("--surface-spacing needs --surface X0,Z0,X1,Z1");
    return std::optional<SurfaceWindow>{};
  }
  auto corners = four_numbers(*text);
  if (!corners) return corners.error();
  const auto& c = *corners;
  SurfaceWindow w;
  auto spacing = number_option(args, "surface-spacing", 1.0, 0.01, 1000);
  if (!spacing) return spacing.error();
  w.spacing_m = *spacing;
  const glm::dvec2 lo(std::min(c[0], c[2]), std::min(c[1], c[3])),
      hi(std::max(c[0], c[2]), std::max(c[1], c[3]));
  if (std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)}) >
      ocean::kWaveQueryMaxCoordinateM)
    return make_error("--surface " + *text +
                      " reaches beyond ±4.3e9 m, where positions are no longer resolved");
  const double columns = std::floor((hi.x - lo.x) / w.spacing_m + 1e-9) + 1;
  const double rows = std::floor((hi.y - lo.y) / w.spacing_m + 1e-9) + 1;
  if (columns < 2 || rows < 2)
    return make_error("--surface " + *text + " holds fewer than 2 samples a side at " +
                      std::to_string(w.spacing_m) + " m: widen the window or lower --surface-spacing");
  if (columns > kSurfaceMaxSide || rows > kSurfaceMaxSide)
    return make_error("--surface " + *text + " at " + std::to_string(w.spacing_m) + " m is " +
                      std::to_string((long long)columns) + " x " + std::to_string((long long)rows) +
                      " samples, more than " + std::to_string(kSurfaceMaxSide) +
                      " a side: raise --surface-spacing or narrow the window");
  w.lo = lo;
  w.columns = int(columns), w.rows = int(rows);
  return std::optional<SurfaceWindow>{w};
}

uint64_t surface_bytes(const SurfaceWindow& window, size_t frames) {
  return io::npy_file_bytes(surface_shape(window, frames)).value();  // at most 1e5 · 2048² floats
}

SurfaceExport::SurfaceExport(std::unique_ptr<ocean::WaveQuery> query, io::NpyStreamWriter heights,
                             SurfaceWindow window)
    : query_(std::move(query)), heights_(std::move(heights)), window_(window) {
  points_.reserve(size_t(window.rows) * window.columns);
  for (int j = 0; j < window.rows; ++j)
    for (int i = 0; i < window.columns; ++i)
      points_.push_back(window.lo + glm::dvec2(i, j) * window.spacing_m);
}

Result<SurfaceExport> SurfaceExport::create(const io::StagedOutput& staged, const scene::Scene& scene,
                                            std::vector<ocean::CascadeSpectrum> spectra,
                                            const SurfaceWindow& window, size_t frames) {
  auto heights =
      io::NpyStreamWriter::create(staged.file("surface_height.npy"), surface_shape(window, frames));
  if (!heights) return heights.error();
  // Heights only: the rest position's inversion needs the displacement, not the normals or velocities.
  auto query = std::make_unique<ocean::WaveQuery>(scene.ocean, std::move(spectra),
                                                  ocean::WaveQueryOptions{.heights_only = true});
  return SurfaceExport(std::move(query), std::move(*heights), window);
}

Result<void> SurfaceExport::append(double time_s) {
  const std::vector<ocean::WaveSample> samples = query_->sample(time_s, points_);
  slab_.resize(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) slab_[i] = float(samples[i].height);
  return heights_.append(slab_);
}

nlohmann::json SurfaceExport::meta() const {
  return {
      {"file", "surface_height.npy"},
      {"origin_m", {window_.lo.x, window_.lo.y}},
      {"spacing_m", window_.spacing_m},
      {"columns", window_.columns},
      {"rows", window_.rows},
      {"error_bound_m", query_->height_interpolation_bound_m()},
      {"layout",
       "float32 array [frame][z][x]: sample (i, j) is the height in metres above the mean water level of "
       "the displaced surface above world x = x0 + i*spacing, z = z0 + j*spacing ((x0, z0) = origin_m), "
       "at times_s[frame], as lagoon probe answers there: the cascades' sea scaled to the floor's "
       "depth-limited height and the swell trains shoaled and turned over the floor. Unlike the cascades' "
       "tiles (the deep sea's, the same everywhere) this is the sea over the scene's bathymetry. The wakes "
       "are not in it (wakes_height.npy)."}};
}

}  // namespace lagoon::cli
