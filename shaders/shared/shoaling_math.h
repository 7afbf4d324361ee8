// Reading the floor's transformation table (shared/shoaling.h) at a point, written once for the GPU (float;
// common/shoaling.glsl) and the CPU (double; compute/ocean/shoaling.cpp). No include guard: the includer
// defines sh_real, sh_real2 and sh_real4.

// Where s (m along the profile's axis) falls: (index of the sample below, fraction to the next, s beyond the
// table's ends: 0 inside). `n` samples `spacing` apart from s = 0.
LAGOON_FN sh_real4 sh_locate(sh_real s, sh_real spacing, sh_real n) {
  sh_real t = clamp(s / spacing, sh_real(0), n - sh_real(1));
  sh_real i = min(floor(t), max(n - sh_real(2), sh_real(0)));
  return sh_real4(i, t - i, s - t * spacing, 0);
}

// A row's value at the located point: linear between the two samples (row 0, the floor's own values).
LAGOON_FN sh_real4 sh_value(sh_real4 below, sh_real4 above, sh_real4 at) {
  return below + (above - below) * at.y;
}

// A wave's row: beyond the table the floor is flat and the wave's phase offset goes on growing at the rate it
// ends with, (k_u - k_u0) per metre (k_u0: the wave's own wavenumber along the axis).
LAGOON_FN sh_real4 sh_wave_value(sh_real4 below, sh_real4 above, sh_real4 at, sh_real k_u0) {
  sh_real4 v = sh_value(below, above, at);
  v.x += (v.z - k_u0) * at.z;
  return v;
}
