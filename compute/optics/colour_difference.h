// CIELAB and the CIEDE2000 colour difference, to measure how far an approximated colour is from the exact
// one in steps a viewer can see (ΔE00 ≈ 1 is a just-noticeable difference).
#pragma once
#include <glm/vec3.hpp>

namespace lagoon::optics {

// CIE 1976 L*a*b* of `xyz` against the reference white `white_xyz` (CIE 15:2004 §8.2.1).
glm::dvec3 xyz_to_lab(glm::dvec3 xyz, glm::dvec3 white_xyz);
// Lab of a linear sRGB colour, the white being RGB (1, 1, 1) (D65).
glm::dvec3 linear_srgb_to_lab(glm::dvec3 linear_rgb);

// CIEDE2000 with k_L = k_C = k_H = 1 (CIE 142-2001), as Sharma, Wu & Dalal (2005) implement it.
double delta_e_2000(glm::dvec3 lab1, glm::dvec3 lab2);

}  // namespace lagoon::optics
