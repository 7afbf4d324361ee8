// The caustic map's blur (render/caustics_window.h): the spread of the refracted sun that a cell's ray does
// not follow, against Snell's law applied numerically (glm::refract, in double) to tilted facets and to the
// solar disc's edges, and the blur on each slice against the landing points' own numerical derivative.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "render/caustics_window.h"
#include "render/sky_light.h"
#include "shared/caustics.h"

namespace lagoon::test {
namespace {

constexpr double kIor = 1.333;

// The refracted sun's angle from the vertical, in the plane of incidence (x, y), for the sun at `elevation`
// (radians) over a facet whose slope along x is `slope`.
double refracted_angle(double elevation, double slope) {
  const glm::dvec3 towards_sun(std::cos(elevation), std::sin(elevation), 0.0);
  const glm::dvec3 normal = glm::normalize(glm::dvec3(-slope, 1.0, 0.0));
  const glm::dvec3 t = glm::refract(-towards_sun, normal, 1.0 / kIor);
  return std::atan2(-t.x, -t.y);
}

TEST(CausticSpread, IsSnellsLawForTiltedFacetsAndTheSolarDisc) {
  for (double elevation_deg : {30.0, 60.0, 85.0}) {
    SCOPED_TRACE(elevation_deg);
    const double e = elevation_deg * M_PI / 180.0, h = 1e-5;
    // The ray's turn per unit slope, and the disc's radius under the water, both by finite differences.
    const double turn = (refracted_angle(e, h) - refracted_angle(e, -h)) / (2 * h);
    const double alpha = render::kSunDiscRadiusRad;
    const double disc = std::abs(refracted_angle(e - alpha, 0.0) - refracted_angle(e + alpha, 0.0)) / 2;
    for (double mss : {0.0, 0.004, 0.03}) {
      const double per_axis = std::sqrt(mss / 2);  // isotropic slopes: mss/2 along each axis
      const double expected = std::hypot(std::abs(turn) * per_axis, disc / 2);  // uniform disc: R/2
      EXPECT_NEAR(render::refracted_sun_spread_rad(std::sin(e), kIor, mss) / expected, 1.0, 0.01) << mss;
    }
  }
}

TEST(CausticSpread, EachSliceBlursByTheLandingPointsSpreadAtItsDepth) {
  scene::Scene scene;
  scene.seafloor.type = scene::SeafloorType::Slope;  // something to light
  const double e = 50.0 * M_PI / 180.0, mss = 0.02;
  const glm::vec3 sun(float(std::cos(e)), float(std::sin(e)), 0.0f);
  const render::CausticsWindow w = render::caustics_window(scene, sun, float(kIor), float(mss));
  ASSERT_GT(w.cells, 0u);
  const double spread = render::refracted_sun_spread_rad(std::sin(e), kIor, mss);
  const double theta = refracted_angle(e, 0.0);
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) {
    // Where a ray turned by ±spread lands at the slice's depth z: z tan(θ ± spread).
    const double z = w.depths[k];
    const double metres = z * (std::tan(theta + spread) - std::tan(theta - spread)) / 2;
    EXPECT_NEAR(w.blur_cells[k] * w.cell_m / metres, 1.0, 0.01) << "slice " << k;
  }
  EXPECT_GT(w.blur_cells[LAGOON_CAUSTICS_SLICES - 1], 1.0f) << "a blur of less than a cell at 15 m";
  scene.render.effects.caustics_blur = false;
  const render::CausticsWindow sharp = render::caustics_window(scene, sun, float(kIor), float(mss));
  for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k) EXPECT_EQ(sharp.blur_cells[k], 0.0f);
}

}  // namespace
}  // namespace lagoon::test
