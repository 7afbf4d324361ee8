// The boundary coefficients of the four-flow model (seed eqs. 6–7): how a flat (mirror) water surface
// splits the sun's and the sky's light, and how it returns the water's upwelling light; and the bottom.
// Naming: t/r = transmitted/reflected, dd = directional stays directional, df = directional becomes diffuse,
// ff = diffuse stays diffuse; "w" = seen from the water side (the seed's "~" coefficients).
#pragma once

namespace lagoon::optics {

struct SurfaceCoefficients {
  // Air -> water (downward light).
  double t_dd = 0, r_dd = 0, t_df = 0, r_df = 0;  // direct sun; t_df = r_df = 0 for a flat surface
  double t_ff = 0, r_ff = 0;  // diffuse sky: averages over a uniform sky, cosine-weighted; r_ff + t_ff = 1
  // Water -> air (upward light).
  double rw_dd = 0, rw_df = 0;  // for G−(0), which travels along the refracted sun direction (see .cpp)
  double rw_ff = 0;             // uniform upwelling radiance, total internal reflection included
  double tw_ff = 0;             // 1 − rw_ff
};

// ior: index of refraction of water relative to air (> 0). sun_zenith_rad: the sun's zenith angle; at or
// below the horizon (>= π/2) no direct light enters: t_dd = 0, r_dd = 1.
SurfaceCoefficients surface_coefficients(double ior, double sun_zenith_rad);

// The bottom (the seed's R̂). Defaults: a black bottom.
struct BottomCoefficients {
  double r_dd = 0, r_df = 0, r_ff = 0;
};

// A Lambertian bottom of albedo A reflects both directional and diffuse light diffusely:
// r_dd = 0, r_df = r_ff = A.
BottomCoefficients lambertian_bottom(double albedo);

}  // namespace lagoon::optics
