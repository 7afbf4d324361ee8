// The surface coefficients of a wavy sea, seed 000 eq. 10: the Fresnel coefficients averaged over the normals
// of the water's facets, each facet weighted by the light it intercepts per unit of horizontal area. Two ways
// that must agree (issue 16): over a patch's normals (the document's way), and analytically over the Gaussian
// slope distribution of the spectrum's slope covariance. At zero slope both are the flat surface's
// coefficients (surface.h) exactly. docs/optics.md, "A wavy surface".
//
// Which coefficients: r_dd (and t_dd = 1 − r_dd) for the sun, r_ff (t_ff) for a uniform sky, rw_ff (tw_ff)
// for uniform upwelling light (total internal reflection included), rw_dd = r_dd by reciprocity as for the
// flat surface. The flows stay directional or diffuse as on the flat surface (t_df = r_df = rw_df = 0): the
// four flows carry no direction spread, so tilted facets change how much light crosses, not which flow it
// joins.
#pragma once
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/surface.h"

namespace lagoon::optics {

// E[s sᵀ] of the slopes s = (∂h/∂x, ∂h/∂z).
struct SlopeCovariance {
  double xx = 0, zz = 0, xz = 0;
  double mean_square() const { return xx + zz; }
};

// Eq. 10 over a patch's slopes (one facet per slope). `sun` points toward the sun (unit).
SurfaceCoefficients patch_surface_coefficients(double ior, glm::dvec3 sun,
                                               std::span<const glm::dvec2> slopes);

// The same average over the Gaussian slope distribution with covariance `c`.
SurfaceCoefficients gaussian_surface_coefficients(double ior, glm::dvec3 sun, const SlopeCovariance& c);

// gaussian_surface_coefficients averaged over the sun's azimuth relative to the slopes (8 azimuths): what the
// LUTs use, so that they depend on the sun's elevation only, as before.
SurfaceCoefficients wavy_surface_coefficients(double ior, double sun_zenith_rad, const SlopeCovariance& c);

}  // namespace lagoon::optics
