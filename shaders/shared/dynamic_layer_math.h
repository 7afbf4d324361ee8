// The dynamic wave layer's physics, written once for the GPU (float; shaders/ocean/dynamic_*.comp) and the
// CPU reference (double; compute/ocean/dynamic_layer.cpp). No include guard: the includer defines dl_real,
// dl_real2, dl_real4 and makes sqrt, tanh, exp, sin, cos, min, max, dot visible (GLSL has them).
//
// The layer is linear water waves on a periodic N x N grid. In the Fourier domain each mode k is an
// oscillator at the dispersion relation's ω(k) = sqrt(g k tanh(k d)) (Airy), pulled toward the surface's
// still-water depression under the pressure of the sources, E(k) = -p̂(k) / (ρ g):
//   h'' = -ω² (h - E),
// which each step advances exactly for E held constant over a sub-step (no stability limit on dt). Deep
// water's ω = sqrt(g k) is what gives a moving source its Kelvin wedge (docs/physics.md, Wakes).

// The DFT bin (i, j) of an n x n grid of `cell` metres as a wavevector (rad/m), negative frequencies above
// n/2.
LAGOON_FN dl_real2 dl_wavevector(int i, int j, int n, dl_real cell) {
  // n is a power of two: a shift, not a division (a scalar loop over the SIMD lanes on lavapipe).
  int fi = i < (n >> 1) ? i : i - n;
  int fj = j < (n >> 1) ? j : j - n;
  return dl_real2(fi, fj) * (dl_real(6.283185307179586) / (dl_real(n) * cell));
}

LAGOON_FN dl_real dl_omega(dl_real k, dl_real gravity, dl_real depth) {
  // tanh saturates long before 20; the bound keeps it finite for any depth.
  return depth > dl_real(0) ? sqrt(gravity * k * tanh(min(k * depth, dl_real(20)))) : sqrt(gravity * k);
}

// The exponent of a source's footprint at wavevector k (its Gaussian in the rotated frame, and exp(-k depth)
// for a source below the surface): below kDlNegligible the source adds nothing a float can hold.
#define kDlNegligible dl_real(-16)
// `along` is the heading as a unit vector in (x, z) (compass::toward of it, core/compass.h).
LAGOON_FN dl_real dl_source_exponent(dl_real2 k, dl_real2 along, dl_real2 sigma, dl_real depth) {
  dl_real2 across = dl_real2(along.y, -along.x);
  dl_real kl = dot(k, along) * sigma.x, kb = dot(k, across) * sigma.y;
  return dl_real(-0.5) * (kl * kl + kb * kb) - sqrt(dot(k, k)) * depth;
}

// The DFT (unnormalised, e^{-i k x}) of the depression under one source centred on `centre`, sampled on a
// grid of `cell` metres: the continuous transform of a Gaussian over the cell area, times exp(exponent)
// from dl_source_exponent. Complex as (re, im). The mean (k = 0) is left alone: the water a hull pushes
// aside raises the whole sea, not the layer's window.
// Its magnitude alone (for k != 0); the CPU multiplies it by phases it splits into x and z factors.
LAGOON_FN dl_real dl_source_magnitude(dl_real exponent, dl_real2 sigma, dl_real depression, dl_real cell) {
  return -depression * dl_real(6.283185307179586) * sigma.x * sigma.y / (cell * cell) * exp(exponent);
}
LAGOON_FN dl_real2 dl_source_hat(dl_real2 k, dl_real2 centre, dl_real exponent, dl_real2 sigma,
                                 dl_real depression, dl_real cell) {
  if (dot(k, k) <= dl_real(0)) return dl_real2(0, 0);
  dl_real magnitude = dl_source_magnitude(exponent, sigma, depression, cell);
  dl_real phase = -dot(k, centre);
  return magnitude * dl_real2(cos(phase), sin(phase));
}

// A source moving at `velocity` for dt shifts its DFT by this factor, e^{-i k·u dt}.
LAGOON_FN dl_real2 dl_source_shift(dl_real2 k, dl_real2 velocity, dl_real dt) {
  dl_real phase = -dot(k, velocity) * dt;
  return dl_real2(cos(phase), sin(phase));
}

LAGOON_FN dl_real2 dl_complex_mul(dl_real2 a, dl_real2 b) {
  return dl_real2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

// One mode over a step of dt: hv = (H.re, H.im, V.re, V.im) with V = dH/dt, toward the depression `e`,
// every amplitude damped by `decay` (the factor for dt); turn = (cos ωdt, sin ωdt, sin(ωdt)/ω), from
// dl_turn, the same for every step of a mode.
LAGOON_FN dl_real4 dl_turn(dl_real omega, dl_real dt) {
  dl_real s = sin(omega * dt);
  return dl_real4(cos(omega * dt), s, omega > dl_real(1e-9) ? s / omega : dt, omega);
}
LAGOON_FN dl_real4 dl_evolve(dl_real4 hv, dl_real2 e, dl_real4 turn, dl_real decay) {
  dl_real2 d = dl_real2(hv.x, hv.y) - e;
  dl_real2 v = dl_real2(hv.z, hv.w);
  dl_real2 h1 = e + (d * turn.x + v * turn.z) * decay;
  dl_real2 v1 = (v * turn.x - d * (turn.w * turn.y)) * decay;
  return dl_real4(h1.x, h1.y, v1.x, v1.y);
}

// The absorbing border: the factor for dt at a cell `from_edge` cells from the window's nearest edge
// (0 = on it). The rate rises as the square of the depth into a border `width` cells wide, so waves enter it
// without a step to reflect from.
LAGOON_FN dl_real dl_sponge(dl_real from_edge, dl_real width, dl_real rate_per_s, dl_real dt) {
  dl_real into = max(dl_real(0), dl_real(1) - from_edge / width);
  return exp(-rate_per_s * into * into * dt);
}

// Foam trails. A hull leaves foam behind its stern (propeller wash) and, at 0.3 of the rate, at its bow,
// along the segments those points sweep over a step, in a band of the beam's sigma across: `rate` · dt where
// a cell lies on the swept path. The foam there saturates at 1 (dl_foam_update), so crossing trails do not
// add up. Positions are compared on the periodic grid (`period` metres): the nearest image of the source
// counts.
LAGOON_FN dl_real dl_segment_distance2(dl_real2 p, dl_real2 a, dl_real2 b) {
  dl_real2 ab = b - a;
  dl_real len2 = dot(ab, ab);
  dl_real t = len2 > dl_real(0) ? clamp(dot(p - a, ab) / len2, dl_real(0), dl_real(1)) : dl_real(0);
  dl_real2 d = p - (a + ab * t);
  return dot(d, d);
}

LAGOON_FN dl_real2 dl_nearest_image(dl_real2 d, dl_real period) {
  return d - period * floor(d / period + dl_real(0.5));
}

LAGOON_FN dl_real dl_foam_injection(dl_real2 cell_xz, dl_real2 centre, dl_real2 velocity, dl_real2 along,
                                    dl_real2 sigma, dl_real rate, dl_real dt, dl_real period) {
  if (rate <= dl_real(0)) return dl_real(0);
  // Relative to the source's centre at the step's start, as the nearest periodic image.
  dl_real2 p = dl_nearest_image(cell_xz - centre, period);
  dl_real2 travel = velocity * dt;
  dl_real2 stern = -along * (dl_real(2) * sigma.x), bow = along * (dl_real(2) * sigma.x);
  dl_real width2 = dl_real(2) * sigma.y * sigma.y;
  dl_real shape = exp(-dl_segment_distance2(p, stern, stern + travel) / width2) +
                  dl_real(0.3) * exp(-dl_segment_distance2(p, bow, bow + travel) / width2);
  return rate * dt * shape;
}

// A cell's foam after the trails' diffusion over a step: explicit, from its own and its four neighbours' foam
// (their sum), `spread` = D dt / cell² (at most 0.24, below the scheme's limit of 1/4). The foam's total is
// kept: it only moves sideways, so a trail widens and thins as it ages.
LAGOON_FN dl_real dl_foam_spread(dl_real foam, dl_real neighbours, dl_real spread) {
  return foam + spread * (neighbours - dl_real(4) * foam);
}

// A cell's foam over a step: what it had, decayed by the step's factor, plus what the hulls left, at most 1.
LAGOON_FN dl_real dl_foam_update(dl_real foam, dl_real decay, dl_real injected) {
  return min(foam * decay + injected, dl_real(1));
}
