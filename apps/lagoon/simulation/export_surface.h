// `lagoon export --surface`: the sea's surface over a window of the world, sampled where the waves are, as
// WaveQuery answers it (ocean/wave_query.h): the cascades' random sea scaled by the floor's depth-limited
// height, the swell trains shoaled and turned over the floor (ocean/shoaling.h). The cascades' tiles are the
// deep sea's, the same everywhere; this is the sea a scene draws and its bodies feel over its bathymetry
// (issue 37: one surface for everyone).
#pragma once
#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "args.h"
#include "core/result.h"
#include "io/npy_stream.h"
#include "io/staged_output.h"
#include "ocean/wave_query.h"
#include "scene/scene.h"

namespace lagoon::cli {

// The grid: columns i along x, rows j along z, sample (i, j) at lo + (i, j) * spacing.
struct SurfaceWindow {
  glm::dvec2 lo{0.0};
  double spacing_m = 1.0;
  int columns = 0, rows = 0;
};

inline constexpr int kSurfaceMaxSide = 2048;  // samples along x or z

// --surface X0,Z0,X1,Z1 and --surface-spacing M: nullopt without --surface; an error naming the option and
// the fix when the window is empty, not finite, too far out or more than kSurfaceMaxSide samples a side.
Result<std::optional<SurfaceWindow>> surface_window_option(const ParsedArgs& args);

// surface_height.npy's size for `frames` frames.
uint64_t surface_bytes(const SurfaceWindow& window, size_t frames);

// The window's heights, a frame at a time, streamed into the staged output's surface_height.npy.
class SurfaceExport {
 public:
  static Result<SurfaceExport> create(const io::StagedOutput& staged, const scene::Scene& scene,
                                      std::vector<ocean::CascadeSpectrum> spectra,
                                      const SurfaceWindow& window, size_t frames);
  Result<void> append(double time_s);
  Result<void> commit() { return heights_.commit(); }
  // meta.json's "surface".
  nlohmann::json meta() const;

 private:
  SurfaceExport(std::unique_ptr<ocean::WaveQuery> query, io::NpyStreamWriter heights, SurfaceWindow window);

  std::unique_ptr<ocean::WaveQuery> query_;
  io::NpyStreamWriter heights_;
  SurfaceWindow window_;
  std::vector<glm::dvec2> points_;
  std::vector<float> slab_;
};

}  // namespace lagoon::cli
