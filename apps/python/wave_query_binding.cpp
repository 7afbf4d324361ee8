// lagoon.WaveQuery: the water's height, normal and velocity at points, the sea (ocean/wave_query.h) plus the
// vehicles' wakes (world/water_probe.h): what `lagoon probe` prints, as numpy arrays.
#include <pybind11/numpy.h>

#include <cmath>
#include <glm/vec2.hpp>
#include <limits>
#include <memory>
#include <vector>

#include "bindings.h"
#include "ocean/initial_spectrum.h"
#include "scene/scene.h"
#include "world/water_probe.h"

namespace lagoon::python {
namespace {

class WaveQuery {
 public:
  WaveQuery(const scene::Scene& scene, double max_wavenumber) : scene_(scene) {
    if (!(max_wavenumber > 0)) throw py::value_error("max_wavenumber must be a positive number of rad/m");
    if (std::isinf(max_wavenumber)) {
      query_ = std::make_unique<ocean::WaveQuery>(scene_.ocean);  // as `lagoon probe` builds it
      return;
    }
    ocean::WaveQueryOptions options;
    options.max_wavenumber = max_wavenumber;
    query_ =
        std::make_unique<ocean::WaveQuery>(scene_.ocean, ocean::make_cascade_spectra(scene_.ocean), options);
  }

  // `points`: N x 2 (x, z) in metres. A dict of arrays: height (N), normal (N x 3), velocity (N x 3),
  // wake_height (N), error_bound (N), converged (N, bool).
  py::dict sample(double time_s,
                  const py::array_t<double, py::array::c_style | py::array::forcecast>& points) {
    if (points.ndim() != 2 || points.shape(1) != 2)
      throw py::value_error("points must be an N x 2 array of (x, z) in metres");
    if (!std::isfinite(time_s) || std::abs(time_s) > ocean::kWaveQueryMaxTimeS)
      throw py::value_error(
          "time must be finite and within ±4294967296 s (beyond it a double's phases are noise)");
    const size_t n = size_t(points.shape(0));
    std::vector<glm::dvec2> at(n);
    const double* p = points.data();
    for (size_t i = 0; i < n; ++i) {
      at[i] = {p[2 * i], p[2 * i + 1]};
      if (!std::isfinite(at[i].x) || !std::isfinite(at[i].y) ||
          std::max(std::abs(at[i].x), std::abs(at[i].y)) > ocean::kWaveQueryMaxCoordinateM)
        throw py::value_error("point " + std::to_string(i) + " is not finite or beyond ±4294967296 m");
    }
    Result<world::WaterAtPoints> water = world::WaterAtPoints{};
    {
      py::gil_scoped_release unlocked;
      water = world::water_at_points(scene_, *query_, time_s, at);
    }
    if (!water) {
      raise_scene_error(water.error().message);
    }
    py::array_t<double> height{py::ssize_t(n)}, wake{py::ssize_t(n)}, bound{py::ssize_t(n)};
    py::array_t<double> normal({py::ssize_t(n), py::ssize_t(3)}), velocity({py::ssize_t(n), py::ssize_t(3)});
    py::array_t<bool> converged{py::ssize_t(n)};
    double *h = height.mutable_data(), *w = wake.mutable_data(), *b = bound.mutable_data();
    double *nrm = normal.mutable_data(), *vel = velocity.mutable_data();
    bool* c = converged.mutable_data();
    for (size_t i = 0; i < n; ++i) {
      const ocean::WaveSample& s = water->samples[i];
      h[i] = s.height;
      w[i] = water->wake_heights[i];
      b[i] = s.error_bound_m;
      c[i] = s.converged;
      for (int k = 0; k < 3; ++k) {
        nrm[3 * i + k] = s.normal[k];
        vel[3 * i + k] = s.velocity[k];
      }
    }
    py::dict out;
    out["height"] = height;
    out["normal"] = normal;
    out["velocity"] = velocity;
    out["wake_height"] = wake;
    out["error_bound"] = bound;
    out["converged"] = converged;
    return out;
  }

 private:
  scene::Scene scene_;
  std::unique_ptr<ocean::WaveQuery> query_;
};

}  // namespace

void bind_wave_query(py::module_& m) {
  py::class_<WaveQuery>(
      m, "WaveQuery",
      "The water's height, normal and velocity at any (x, z) and time, on the CPU (no device), "
      "as `lagoon probe` computes it: the sea's waves plus the vehicles' wakes.")
      .def(py::init<const scene::Scene&, double>(), py::arg("scene"),
           py::arg("max_wavenumber") = std::numeric_limits<double>::infinity(),
           "`max_wavenumber` (rad/m): leave out waves with |k| at or above it (a hull averages them out).")
      .def("sample", &WaveQuery::sample, py::arg("time"), py::arg("points"),
           "At `time` (s), `points` an N x 2 array of (x, z): a dict of numpy arrays height (N, m above the "
           "mean level), normal (N x 3), velocity (N x 3, m/s), wake_height (N, the wakes' part of height), "
           "error_bound (N, m) and converged (N).");
}

}  // namespace lagoon::python
