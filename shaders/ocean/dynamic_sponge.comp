#version 450
// The dynamic wave layer's step in space (compute/ocean/dynamic_layer.h): the absorbing border damps the state
// after the inverse transform, the hulls' foam trails decay and grow, and the renderer's fields are written
// from the damped heights: (h, dh/dx, dh/dz, foam) per cell, central differences across neighbouring cells
// (damped on the fly, so no cell waits for another's result). Storage is toroidal: world cell a lives at
// index a mod n.
#extension GL_GOOGLE_include_directive : require
#include "shared/dynamic_layer.h"
#define dl_real float
#define dl_real2 vec2
#define dl_real4 vec4
#include "shared/dynamic_layer_math.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
// Off for the steps of a catch-up but its last: only the last step's fields are ever drawn, and the slopes'
// four neighbour loads are most of this pass on lavapipe.
layout(constant_id = LAGOON_DYNAMIC_SPEC_FIELDS) const bool DL_FIELDS = true;

layout(std430, binding = LAGOON_DYNAMIC_BIND_RAW) readonly buffer Raw { vec2 raw[]; };
layout(std430, binding = LAGOON_DYNAMIC_BIND_STATE) writeonly buffer State { vec2 state[]; };
layout(rgba32f, binding = LAGOON_DYNAMIC_BIND_FIELDS) writeonly uniform image2D fields;
// A uniform block, not a storage buffer: every invocation reads the same sources, and lavapipe loads a
// uniform block at a uniform offset once for the SIMD vector instead of once per lane.
layout(std140, binding = LAGOON_DYNAMIC_BIND_SOURCES) uniform Sources { DynamicSource sources[LAGOON_DYNAMIC_MAX_SOURCES]; };
layout(std430, binding = LAGOON_DYNAMIC_BIND_FOAM_IN) readonly buffer FoamIn { float foam_in[]; };
layout(std430, binding = LAGOON_DYNAMIC_BIND_FOAM) writeonly buffer Foam { float foam[]; };
layout(push_constant) uniform Push { DynamicPush p; };

// n is a power of two: wrapping is a mask (two's complement keeps it right for negative values), where a
// modulo would be a scalar loop over the SIMD lanes on lavapipe.
int from_edge(int index, int origin, int n) {
  int a = (index - origin) & (n - 1);
  return min(a, n - 1 - a);
}

// The world cell that storage index `index` holds.
int window_cell(int index, int origin, int n) {
  return origin + ((index - origin) & (n - 1));
}

float sponge_at(int i, int j) {
  int n = int(p.n);
  float edge = float(min(from_edge(i, p.origin.x, n), from_edge(j, p.origin.y, n)));
  return dl_sponge(edge, p.sponge_cells, p.sponge_per_s, p.dt);
}

// The damped height at storage index (i, j), wrapped: one float load, where the state is two.
float damped_height(int i, int j) {
  int n = int(p.n);
  i &= n - 1;
  j &= n - 1;
  return raw[j * n + i].x * sponge_at(i, j);
}

// The last step's foam at storage index (i, j), wrapped.
float previous_foam(int i, int j) {
  int n = int(p.n);
  return foam_in[(j & (n - 1)) * n + (i & (n - 1))];
}

void main() {
  int n = int(p.n);
  ivec2 c = ivec2(gl_GlobalInvocationID.xy);
  if (c.x >= n || c.y >= n) return;
  float keep = sponge_at(c.x, c.y);
  vec2 here = raw[c.y * n + c.x] * keep;
  state[c.y * n + c.x] = here;
  vec2 xz = vec2(window_cell(c.x, p.origin.x, n), window_cell(c.y, p.origin.y, n)) * p.cell;
  float injected = 0.0;
  for (uint s = 0u; s < p.foam_sources; ++s) {
    DynamicSource src = sources[s];
    injected += dl_foam_injection(xz, src.centre, src.velocity, src.along, src.sigma, src.foam_per_s, p.dt,
                                  float(p.n) * p.cell);
  }
  float neighbours = previous_foam(c.x - 1, c.y) + previous_foam(c.x + 1, c.y) + previous_foam(c.x, c.y - 1) +
                     previous_foam(c.x, c.y + 1);
  float spread = dl_foam_spread(foam_in[c.y * n + c.x], neighbours, p.foam_spread);
  float trail = dl_foam_update(spread, p.foam_decay, injected) * keep;
  foam[c.y * n + c.x] = trail;
  if (!DL_FIELDS) return;
  float dx = (damped_height(c.x + 1, c.y) - damped_height(c.x - 1, c.y)) / (2.0 * p.cell);
  float dz = (damped_height(c.x, c.y + 1) - damped_height(c.x, c.y - 1)) / (2.0 * p.cell);
  imageStore(fields, c, vec4(here.x, dx, dz, trail));
}
