// One axis of the caustic map's Gaussian blur (render/caustics_window.h: the rays' spread a cell's splat does
// not follow), for both of its passes (caustics/blur_rows.comp along x, caustics/resolve.comp along z).
// Each tap is a storage-buffer load. A line read once into shared memory would need a barrier, which made
// lavapipe's cold compile of the two passes 0.25 s longer (its compute barriers are coroutines).
// Needs, declared by the includer: `caustic_in(slice, x, z)`, the unblurred value at a cell.
#ifndef LAGOON_COMMON_CAUSTIC_BLUR_GLSL
#define LAGOON_COMMON_CAUSTIC_BLUR_GLSL

// The map's cells blurred along `axis` ((1, 0) or (0, 1)) with standard deviation `sigma` cells; the edge
// cells stand for what lies beyond the window (clamped), so a flat sea stays 1 there. sigma below 0.05 cell
// (weights beyond the centre under 1e-87) is no blur: the cell's own value.
float caustic_blur(int slice, ivec2 cell, ivec2 axis, float sigma) {
  if (sigma < 0.05) return caustic_in(slice, cell.x, cell.y);
  const ivec2 last = ivec2(LAGOON_CAUSTICS_CELLS - 1);
  int radius = min(int(ceil(3.0 * sigma)), LAGOON_CAUSTICS_MAX_BLUR);
  // The weights e^{k i²} by recurrence, two multiplications a tap instead of an exp (costly on lavapipe):
  // e^{k i²} = e^{k (i-1)²} e^{k (2i - 1)}, and e^{k (2i + 1)} = e^{k (2i - 1)} e^{2k}.
  float k = -0.5 / (sigma * sigma), step = exp(k), ratio = exp(2.0 * k), w = 1.0;
  float sum = caustic_in(slice, cell.x, cell.y), total = 1.0;
  for (int i = 1; i <= radius; ++i) {
    w *= step;
    step *= ratio;
    ivec2 a = clamp(cell + axis * i, ivec2(0), last), b = clamp(cell - axis * i, ivec2(0), last);
    sum += w * (caustic_in(slice, a.x, a.y) + caustic_in(slice, b.x, b.y));
    total += 2.0 * w;
  }
  return sum / total;
}

#endif
