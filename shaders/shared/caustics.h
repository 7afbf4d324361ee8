// Caustics (engine/render/passes/caustics_pass.cpp, shaders/render/caustics_*.comp): the sun's irradiance on
// horizontal planes at a few depths under a window of the sea around the camera, relative to the irradiance
// under a flat surface (1 = no focusing), by splatting the refracted sun rays of the displaced surface.
#ifndef LAGOON_SHARED_CAUSTICS_H
#define LAGOON_SHARED_CAUSTICS_H
#include "shared/interop.h"
#include "shared/surface.h"

#define LAGOON_CAUSTICS_SLICES 4     // depths per frame (FrameUniforms::caustic_depths)
#define LAGOON_CAUSTICS_CELLS 256    // destination cells per side of the window, at most (the map's size)
#define LAGOON_CAUSTICS_MARGIN 32    // source cells beyond each side: rays tilted by the waves land inside
#define LAGOON_CAUSTICS_ONE 65536.0  // fixed-point unit of the accumulation (one source cell's energy)
// Rays per source cell side (n x n rays of 1/n^2 a cell's energy). One ray per cell leaves each destination
// cell the sum of about one ray's bilinear weights once rays cross: a grain of std/mean ~0.67 beyond a few
// metres, which the blur by what the rays leave out (common/caustic_blur.glsl) smooths where it is wider
// than a cell (past ~5 m under a 7 m/s sea). 2 would draw the shallow planes without it, but its 16 atomics
// per ray cost a lavapipe frame of the reef-dive 30 % more (231 against 177 ms at 640 x 360, 2026-11-27).
#define LAGOON_CAUSTICS_RAYS 1

#define LAGOON_CAUSTICS_BIND_FRAME 0
// The cascades in the surface shaders' slots, so render/surface_fields.h serves this pass too.
#define LAGOON_CAUSTICS_BIND_DISPLACEMENT LAGOON_SURFACE_BIND_DISPLACEMENT  // sampler2DArray[MAX_CASCADES]
#define LAGOON_CAUSTICS_BIND_NORMAL_JACOBIAN \
  LAGOON_SURFACE_BIND_NORMAL_JACOBIAN  // sampler2DArray[MAX_CASCADES]
#define LAGOON_CAUSTICS_BIND_ACCUM 3   // uint[SLICES][CELLS][CELLS], fixed point
#define LAGOON_CAUSTICS_BIND_MAP 4     // r32f image2DArray, one layer per slice
#define LAGOON_CAUSTICS_BIND_ROWS 5    // float[SLICES][CELLS][CELLS]: the accumulation blurred along x
// Widest blur, cells each side (3 m): 3σ at 15 m under a 20 m/s sea with the sun 60° up (σ 0.95 m). A lower
// sun or a rougher sea is cut there (at 30° and 20 m/s σ is 2.4 m), a blur a little narrower than its σ.
#define LAGOON_CAUSTICS_MAX_BLUR 24
// Cells of a line each invocation of the blur's passes blurs (common/caustic_blur.glsl).
#define LAGOON_CAUSTICS_RUN 8
// ... and the wakes at LAGOON_SURFACE_BIND_WAKES (common/wake_fields.glsl)

LAGOON_GPU_BEGIN
struct CausticsPush {
  vec4 source;  // xy = world xz of source cell (0, 0)'s corner, zw = source cells along x and z
};
struct CausticsBlurPush {
  vec4 sigma_cells;  // each slice's Gaussian blur, standard deviation in cells (CausticsWindow::blur_cells)
  vec4 cells;        // x = this frame's cells per side (CausticsWindow::cells, at most LAGOON_CAUSTICS_CELLS)
};
LAGOON_GPU_END

#endif
