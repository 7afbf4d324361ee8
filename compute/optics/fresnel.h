// Fresnel reflectance of a flat interface between two dielectrics (unpolarised light), and its average over
// a hemisphere of uniform radiance: the building blocks of the surface coefficients (surface.h).
#pragma once

namespace lagoon::optics {

// Reflectance for light going from index n_from into n_to, hitting the interface at an angle whose cosine
// (to the normal, either side: the sign is ignored) is cos_incidence. 1 beyond the critical angle.
double fresnel_reflectance(double n_from, double n_to, double cos_incidence);

// Cosine of the transmitted angle (Snell's law); 0 under total internal reflection.
double refracted_cos(double n_from, double n_to, double cos_incidence);

// Cosine-weighted hemisphere average of fresnel_reflectance, ∫0^1 R(μ) 2μ dμ: the fraction of the flux of
// a uniform (isotropic) radiance field that the interface reflects, total internal reflection included.
double fresnel_hemispherical(double n_from, double n_to);

}  // namespace lagoon::optics
