// Waves that feel the floor (issue 37; ocean/shoaling.h, docs/ocean.md "Waves over the floor"): the
// transformation's table as the surface shaders read it (common/shoaling.glsl): a storage buffer of vec4, one
// per sample of the floor's grid (columns along its axis, rows across it) and a layer per quantity:
// layer 0 = (depth m, the random sea's height scale, the waves' steepness scale, breaking ratio), layer 1 + i
// = direct wave i's (phase offset rad, amplitude m, its wavevector along and across the axis rad/m). Read
// and interpolated by shared/shoaling_math.h, the same arithmetic as the CPU's.
#ifndef LAGOON_SHARED_SHOALING_H
#define LAGOON_SHARED_SHOALING_H

#define LAGOON_SURFACE_BIND_SHOALING 19
// Specialisation constant of the shaders that sum the water's motion: the transformation compiled in for a
// profile (1) or a grid (2), or not (0: no floor shallow enough to matter: the deep sea's code, bit for bit).
#define LAGOON_SURFACE_SPEC_SHOALING 10
#define LAGOON_SHOALING_MAX_SAMPLES 4096

#endif
