// Model springs (issue 15, docs/models.md): push constants, excitations and binding slots of its passes
// (shaders/ocean/springs_*.comp, compute/ocean/gpu/springs_gpu.*). The step both sides evaluate is in
// shared/springs_math.h.
#ifndef LAGOON_SHARED_SPRINGS_H
#define LAGOON_SHARED_SPRINGS_H
#include "shared/interop.h"

#define LAGOON_SPRINGS_MAX_EXCITATIONS 64
// The step (springs_step.comp): state (x, v) per node in, the next state out, the excitations.
#define LAGOON_SPRINGS_BIND_STATE_IN 0
#define LAGOON_SPRINGS_BIND_STATE_OUT 1
#define LAGOON_SPRINGS_BIND_EXCITATIONS 2
// The fields (springs_assemble.comp): the state in, the ocean's three images out (one array layer).
#define LAGOON_SPRINGS_BIND_DISPLACEMENT 3
#define LAGOON_SPRINGS_BIND_NORMAL_JACOBIAN 4
#define LAGOON_SPRINGS_BIND_JACOBIAN_TERMS 5

LAGOON_GPU_BEGIN
// A drop or a gust: an extra acceleration (m/s², upward; drops and gusts push down) on a Gaussian patch of
// `sigma` m whose centre starts at `centre` at `start_s` and moves at `velocity`, during steps [first_step,
// end_step). `mean_weight` is the patch's weight averaged over the grid, taken off every node's: the grid's
// uniform mode has no spring to restore it, so a push with a net volume would sink the whole sea for good.
struct SpringExcitation {
  vec2 centre;
  vec2 velocity;
  float sigma;
  float accel;
  float start_s;
  uint first_step;
  uint end_step;
  float mean_weight;
  uint pad1;
  uint pad2;
};

struct SpringsPush {
  uint n;                    // nodes per side (periodic)
  uint step;                 // the step being taken: from time step·dt to (step + 1)·dt
  uint excitations;          // how many of the buffer's excitations to apply
  uint layer;                // assembly: the array layer of the first cascade
  float spacing;             // m between nodes
  float dt;                  // s
  float mass;                // kg per node
  float stiffness;           // N/m per spring
  float damping;             // kg/s
  float rest;                // m: eq. 4's rest length L (0 = linear springs)
  float boundary_amplitude;  // m: the column x = 0 held at amplitude sin(omega t); 0 = free
  float boundary_omega;      // rad/s
  float behind_s;            // assembly: the state is at time t_m; the picture is at t_m - behind_s
  float foam_threshold;  // assembly: as the FFT ocean's foam (J is 1 on a grid that only moves vertically)
  float foam_decay;      // assembly: the factor the foam keeps over this frame
  uint reset_foam;
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(SpringExcitation, 48);
LAGOON_CHECK_SIZE(SpringsPush, 64);
#endif
#endif
