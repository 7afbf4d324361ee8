// One axis of the caustic map's Gaussian blur (render/caustics_window.h: the rays' spread a cell's splat does
// not follow), for both of its passes (caustics/blur_rows.comp along x, caustics/resolve.comp along z).
// An invocation blurs a run of LAGOON_CAUSTICS_RUN cells of one line: it loads the run and the blur's reach
// on either side once into a private window, and every tap reads that. Runs made a 160 x 90 frame on
// lavapipe 9 ms faster than an invocation per cell, with or without the blur; the taps themselves still
// add about 10 ms there (a private array indexed per lane is a loop over the SIMD lanes too). A line shared
// by a workgroup would need a barrier, which lavapipe compiles as a coroutine: a longer cold compile and
// slower passes. A recursive (IIR) Gaussian would make the taps' cost independent of σ.
// Needs, declared by the includer: `caustic_in(slice, x, z)`, the unblurred value at a cell.
#ifndef LAGOON_COMMON_CAUSTIC_BLUR_GLSL
#define LAGOON_COMMON_CAUSTIC_BLUR_GLSL

// The run of cells from `start` along `axis` ((1, 0) or (0, 1)) of the frame's n x n cells, blurred along it
// with standard deviation `sigma` cells over ⌈3σ⌉ each side; the edge cells stand for what lies beyond the
// window (clamped), so a flat sea stays 1 there. sigma below 0.05 cell (weights beyond the centre under 1e-87) is no blur.
void caustic_blur_run(int n, int slice, ivec2 start, ivec2 axis, float sigma,
                      out float run[LAGOON_CAUSTICS_RUN]) {
  ivec2 last = ivec2(n - 1);
  int radius = sigma < 0.05 ? 0 : min(int(ceil(3.0 * sigma)), LAGOON_CAUSTICS_MAX_BLUR);
  float window[LAGOON_CAUSTICS_RUN + 2 * LAGOON_CAUSTICS_MAX_BLUR];
  for (int j = 0; j < LAGOON_CAUSTICS_RUN + 2 * radius; ++j) {
    ivec2 c = clamp(start + axis * (j - radius), ivec2(0), last);
    window[j] = caustic_in(slice, c.x, c.y);
  }
  // The weights e^{k i²} by recurrence, two multiplications a tap instead of an exp (costly on lavapipe):
  // e^{k i²} = e^{k (i-1)²} e^{k (2i - 1)}, and e^{k (2i + 1)} = e^{k (2i - 1)} e^{2k}.
  float k = -0.5 / max(sigma * sigma, 1e-6), first_step = exp(k), ratio = exp(2.0 * k);
  for (int j = 0; j < LAGOON_CAUSTICS_RUN; ++j) {
    int centre = j + radius;
    float step = first_step, w = 1.0, sum = window[centre], total = 1.0;
    for (int i = 1; i <= radius; ++i) {
      w *= step;
      step *= ratio;
      sum += w * (window[centre + i] + window[centre - i]);
      total += 2.0 * w;
    }
    run[j] = sum / total;
  }
}

#endif
