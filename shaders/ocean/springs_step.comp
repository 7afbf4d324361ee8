#version 450
// One step of model springs (compute/ocean/springs.h): every node's eq. 5 from its four neighbours' eq. 4
// forces, the drops and gusts of this step, and the driven column. Ping-pong: the state in, the next out.
#extension GL_GOOGLE_include_directive : require
#include "shared/springs.h"
#define sp_real float
#define sp_real2 vec2
#include "shared/springs_math.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std430, binding = LAGOON_SPRINGS_BIND_STATE_IN) readonly buffer StateIn { vec2 state_in[]; };
layout(std430, binding = LAGOON_SPRINGS_BIND_STATE_OUT) writeonly buffer StateOut { vec2 state_out[]; };
layout(std430, binding = LAGOON_SPRINGS_BIND_EXCITATIONS) readonly buffer Excitations {
  SpringExcitation excitations[];
};
layout(push_constant) uniform Push { SpringsPush p; };

float height(int i, int j) {
  int n = int(p.n);
  return state_in[((j + n) % n) * n + (i + n) % n].x;
}

void main() {
  int n = int(p.n);
  ivec2 c = ivec2(gl_GlobalInvocationID.xy);
  if (c.x >= n || c.y >= n) return;
  vec2 here = state_in[c.y * n + c.x];
  float springs = sp_spring_force(height(c.x - 1, c.y) - here.x, p.stiffness, p.rest, p.spacing) +
                  sp_spring_force(height(c.x + 1, c.y) - here.x, p.stiffness, p.rest, p.spacing) +
                  sp_spring_force(height(c.x, c.y - 1) - here.x, p.stiffness, p.rest, p.spacing) +
                  sp_spring_force(height(c.x, c.y + 1) - here.x, p.stiffness, p.rest, p.spacing);
  float t = float(p.step) * p.dt, period = float(n) * p.spacing;
  vec2 node = vec2(c) * p.spacing;
  float pushed = 0.0;
  for (uint e = 0u; e < p.excitations; ++e) {
    SpringExcitation x = excitations[e];
    if (p.step < x.first_step || p.step >= x.end_step) continue;
    vec2 centre = x.centre + x.velocity * (t - x.start_s);
    pushed += x.accel * (sp_patch_weight(node, centre, x.sigma, period) - x.mean_weight);
  }
  vec2 next = sp_node_step(here, springs, pushed, p.mass, p.damping, p.dt);
  if (c.x == 0 && p.boundary_amplitude > 0.0) {
    float later = t + p.dt;
    next = vec2(p.boundary_amplitude * sin(p.boundary_omega * later),
                p.boundary_amplitude * p.boundary_omega * cos(p.boundary_omega * later));
  }
  state_out[c.y * n + c.x] = next;
}
