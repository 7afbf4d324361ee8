// One axis of the caustic map's Gaussian blur (render/caustics_window.h: the rays' spread a cell's splat does
// not follow), for both of its passes (caustics/blur_rows.comp along x, caustics/resolve.comp along z).
// A workgroup is LAGOON_CAUSTICS_LINE cells of one line of one slice: it reads its cells and the blur's reach
// on either side once into shared memory, and each cell's taps read them there, not 2r + 1 storage-buffer
// loads a cell (on lavapipe each such load is a loop over the SIMD lanes).
// Needs, declared by the includer: `caustic_in(slice, x, z)`, the unblurred value at a cell.
#ifndef LAGOON_COMMON_CAUSTIC_BLUR_GLSL
#define LAGOON_COMMON_CAUSTIC_BLUR_GLSL

#define LAGOON_CAUSTICS_LINE 64
layout(local_size_x = LAGOON_CAUSTICS_LINE) in;
shared float line_cells[LAGOON_CAUSTICS_LINE + 2 * LAGOON_CAUSTICS_MAX_BLUR];

// This invocation's cell: along the line `gl_GlobalInvocationID.x`, the line `gl_GlobalInvocationID.y`, the
// slice `gl_GlobalInvocationID.z`; `along_x` says which way the line runs.
ivec3 caustic_cell(bool along_x) {
  ivec3 g = ivec3(gl_GlobalInvocationID);
  return along_x ? g : ivec3(g.y, g.x, g.z);
}

// The cell blurred along its line with standard deviation `sigma` cells (the same for the whole workgroup:
// one slice) over 3σ each side; the edge cells stand for what lies beyond the window (clamped), so a flat sea
// stays 1 there. sigma below 0.05 cell (weights beyond the centre under 1e-87) is no blur. Every invocation
// of the workgroup calls it (a barrier).
float caustic_blur(bool along_x, float sigma) {
  ivec3 c = caustic_cell(along_x);
  if (sigma < 0.05) return caustic_in(c.z, c.x, c.y);
  const int last = LAGOON_CAUSTICS_CELLS - 1, reach = LAGOON_CAUSTICS_MAX_BLUR;
  int i = int(gl_LocalInvocationID.x), first = int(gl_WorkGroupID.x) * LAGOON_CAUSTICS_LINE - reach;
  for (int j = i; j < LAGOON_CAUSTICS_LINE + 2 * reach; j += LAGOON_CAUSTICS_LINE) {
    int at = clamp(first + j, 0, last);
    line_cells[j] = along_x ? caustic_in(c.z, at, c.y) : caustic_in(c.z, c.x, at);
  }
  barrier();
  int radius = min(int(ceil(3.0 * sigma)), reach);
  // The weights e^{k i²} by recurrence, two multiplications a tap instead of an exp:
  // e^{k i²} = e^{k (i-1)²} e^{k (2i - 1)}, and e^{k (2i + 1)} = e^{k (2i - 1)} e^{2k}.
  float k = -0.5 / (sigma * sigma), step = exp(k), ratio = exp(2.0 * k), w = 1.0;
  int centre = i + reach;
  float sum = line_cells[centre], total = 1.0;
  for (int t = 1; t <= radius; ++t) {
    w *= step;
    step *= ratio;
    sum += w * (line_cells[centre + t] + line_cells[centre - t]);
    total += 2.0 * w;
  }
  return sum / total;
}

#endif
