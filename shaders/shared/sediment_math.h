// The optics of a sediment cloud, written once for the GPU (float; shaders/common/sediment.glsl) and the
// CPU (double; compute/physics/sediment.cpp). No include guard: the includer defines sed_real, sed_real2,
// sed_real3, includes shared/sediment.h and makes exp, sqrt, abs, min, max, dot visible (GLSL has them).
//
// A cloud is an isotropic Gaussian of mass m (g) and standard deviation σ whose particles attenuate light by
// c* (m²/g) per gram: its attenuation coefficient at p is m c* N(p; centre, σ) with N the normal density.
// Along a ray o + t d (|d| = 1), 0 <= t <= L, the optical depth is closed-form: the Gaussian restricted to
// the line is a 1-D normal in t around the closest approach t*, scaled by the 2-D normal of the miss distance
// r,
//   τ = m c* / (2π σ²) · exp(-r² / 2σ²) · [Φ((L - t*)/σ) - Φ(-t*/σ)],
// and the attenuation-weighted mean t (where along the ray the cloud's light comes from) is
//   t̄ = t* + σ (φ(-t*/σ) - φ((L - t*)/σ)) / [Φ((L - t*)/σ) - Φ(-t*/σ)].

// The standard normal's distribution function Φ(x) = ½(1 + erf(x/√2)), erf by Abramowitz & Stegun 7.1.26
// (|error| <= 1.5e-7; GLSL has none), given e = exp(-x²/2), which is also the density's (sed_pdf): a cloud
// needs both at both ends of the segment, and its exponentials are most of a pixel's cost of the cloud.
LAGOON_FN sed_real sed_cdf(sed_real x, sed_real e) {
  sed_real s = x < sed_real(0) ? sed_real(-1) : sed_real(1);
  sed_real t = sed_real(1) / (sed_real(1) + sed_real(0.3275911) * sed_real(0.7071067811865476) * abs(x));
  sed_real poly =
      t * (sed_real(0.254829592) +
           t * (sed_real(-0.284496736) +
                t * (sed_real(1.421413741) + t * (sed_real(-1.453152027) + t * sed_real(1.061405429)))));
  return sed_real(0.5) + sed_real(0.5) * s * (sed_real(1) - poly * e);
}
// The standard normal's density, given e = exp(-x²/2).
LAGOON_FN sed_real sed_pdf(sed_real e) {
  return sed_real(0.3989422804014327) * e;
}

// A cloud's optical depth along the ray and the ray's distance weighted by it (τ, τ t̄); (0, 0) for a ray
// segment that passes further than √20 σ ≈ 4.5 σ away (below e^-10 of the peak everywhere on it: what it
// leaves out is at most e^-10/2 of the cloud's optical depth through its centre). The segment, not its line:
// a pixel's ray that ends at the floor short of a cloud it points at, or starts past it, sees none of it,
// and sed_segment_meets_box can then cull every cloud at once. `strength` = m c* (m²).
LAGOON_FN sed_real2 sed_ray(sed_real3 origin, sed_real3 dir, sed_real len, sed_real3 centre, sed_real sigma,
                            sed_real strength) {
  sed_real3 to = centre - origin;
  sed_real t_star = dot(to, dir);
  sed_real miss2 = max(dot(to, to) - t_star * t_star, sed_real(0));
  sed_real s2 = sigma * sigma;
  sed_real3 nearest = to - dir * max(sed_real(0), min(t_star, len));  // from the segment's nearest point
  if (dot(nearest, nearest) > sed_real(LAGOON_SEDIMENT_REACH2_SIGMA2) * s2) return sed_real2(0);
  sed_real a = -t_star / sigma, b = (len - t_star) / sigma;
  sed_real ea = exp(sed_real(-0.5) * a * a), eb = exp(sed_real(-0.5) * b * b);
  sed_real share = max(sed_cdf(b, eb) - sed_cdf(a, ea), sed_real(0));
  sed_real peak = strength / (sed_real(6.283185307179586) * s2) * exp(sed_real(-0.5) * miss2 / s2);
  sed_real tau = peak * share;
  sed_real moment = tau * t_star + peak * sigma * (sed_pdf(ea) - sed_pdf(eb));
  return sed_real2(tau, moment);
}

// The part [span.x, span.y] of a segment's t that lies between one axis' planes lo and hi (o, d: the
// origin's and the direction's components on that axis); empty (x > y) when none does.
LAGOON_FN sed_real2 sed_slab(sed_real o, sed_real d, sed_real lo, sed_real hi, sed_real2 span) {
  if (abs(d) < sed_real(1e-12)) return (o < lo || o > hi) ? sed_real2(1, 0) : span;  // parallel to them
  sed_real a = (lo - o) / d, b = (hi - o) / d;
  return sed_real2(max(span.x, min(a, b)), min(span.y, max(a, b)));
}

// Whether origin + t dir, 0 <= t <= len, meets the box [lo, hi] (SedimentHeader's clouds' reach).
LAGOON_FN bool sed_segment_meets_box(sed_real3 origin, sed_real3 dir, sed_real len, sed_real3 lo,
                                     sed_real3 hi) {
  sed_real2 span = sed_real2(0, len);
  span = sed_slab(origin.x, dir.x, lo.x, hi.x, span);
  span = sed_slab(origin.y, dir.y, lo.y, hi.y, span);
  span = sed_slab(origin.z, dir.z, lo.z, hi.z, span);
  return span.x <= span.y;
}
