#include "optics/surface.h"

#include <cmath>

#include "optics/fresnel.h"

namespace lagoon::optics {

SurfaceCoefficients surface_coefficients(double ior, double sun_zenith_rad) {
  constexpr double kAir = 1.0;
  SurfaceCoefficients c;
  // Below the horizon the cosine is clamped to 0 (grazing), where Fresnel gives R = 1: no direct light
  // enters, and eq. 6 (t_dd + r_dd + t_df + r_df = 1) still holds.
  const double mu_sun = std::fmax(std::cos(sun_zenith_rad), 0.0);
  // A mirror surface keeps a direct beam direct: only dd terms, fixed by Fresnel at the sun's angle.
  c.r_dd = fresnel_reflectance(kAir, ior, mu_sun);
  c.t_dd = 1.0 - c.r_dd;
  c.t_df = c.r_df = 0.0;
  c.r_ff = fresnel_hemispherical(kAir, ior);
  c.t_ff = 1.0 - c.r_ff;
  // G− is the directional light the bottom returns specularly (R̂_dd), so it travels up along the mirror
  // image of the refracted sun ray and meets the surface at the refracted angle. A flat surface sends the
  // reflected part back down as a directional beam along the refracted sun direction, i.e. into G+ (eq. 7,
  // first line), and makes no diffuse light of it: rw_df = 0. rw_dd is Fresnel from below at the refracted
  // angle, which by reciprocity is r_dd; evaluating it from below would be ill-conditioned for a low sun,
  // whose refracted ray is near the critical angle where R has a square-root singularity.
  c.rw_dd = c.r_dd;
  c.rw_df = 0.0;
  c.rw_ff = fresnel_hemispherical(ior, kAir);
  c.tw_ff = 1.0 - c.rw_ff;
  return c;
}

BottomCoefficients lambertian_bottom(double albedo) {
  return {.r_dd = 0.0, .r_df = albedo, .r_ff = albedo};
}

}  // namespace lagoon::optics
