// Reading the floor's transformation table (shared/shoaling.h) at a point, written once for the GPU (float;
// common/shoaling.glsl) and the CPU (double; compute/ocean/shoaling.cpp). No include guard: the includer
// defines sh_real, sh_real2 and sh_real4.

// Where s (m along one of the grid's axes) falls: (index of the sample below, fraction to the next, s beyond
// the grid's ends: 0 inside). `n` samples `spacing` apart from s = 0.
LAGOON_FN sh_real4 sh_locate(sh_real s, sh_real spacing, sh_real n) {
  sh_real t = clamp(s / spacing, sh_real(0), n - sh_real(1));
  sh_real i = min(floor(t), max(n - sh_real(2), sh_real(0)));
  return sh_real4(i, t - i, s - t * spacing, 0);
}

// A value at the located point: bilinear between the four samples around it (a00 at the lower index on both
// axes, a10 the next along u, a01 along v), fu and fv the fractions.
LAGOON_FN sh_real4 sh_bilinear(sh_real4 a00, sh_real4 a10, sh_real4 a01, sh_real4 a11, sh_real fu,
                               sh_real fv) {
  sh_real4 a = a00 + (a10 - a00) * fu;
  sh_real4 b = a01 + (a11 - a01) * fu;
  return a + (b - a) * fv;
}

// A wave's value (phase offset, amplitude, k_u, k_v): beyond the grid the floor is flat and the wave's phase
// offset goes on growing at the rate it ends with, (k - k0)·(metres beyond) (k0: the wave's own wavevector).
LAGOON_FN sh_real4 sh_wave_value(sh_real4 v, sh_real beyond_u, sh_real beyond_v, sh_real k0_u, sh_real k0_v) {
  v.x += (v.z - k0_u) * beyond_u + (v.w - k0_v) * beyond_v;
  return v;
}

// The random sea's lattice over the floor (ocean/shoaling.h): cascade c's textures are read at the rest
// position moved along its representative wave by that wave's phase offset φ (w0 = (k0, k0/|k0|²)), so that
// the wave's phase there, k0·x' = k0·x + φ, is its phase over the floor: it shortens, slows and turns as a
// directly evaluated wave does, and the cascade's other waves with it. k0 = 0 (no waves): not moved.
LAGOON_FN sh_real2 sh_lattice_point(sh_real2 rest, sh_real phase, sh_real4 w0) {
  return rest + phase * sh_real2(w0.z, w0.w);
}

// A slope read at the moved point as the surface's slope at the rest position (the chain rule through the
// move): s + ∇φ (k0·s)/|k0|², with ∇φ = k - k0 (the local wavevector less its own).
LAGOON_FN sh_real2 sh_lattice_slope(sh_real2 slope, sh_real2 grad, sh_real4 w0) {
  return slope + grad * dot(sh_real2(w0.z, w0.w), slope);
}
