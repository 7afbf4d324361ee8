// The spring grid's physics (seed 001 §1.1.3, eqs. 4-5), written once for the GPU (float;
// shaders/ocean/springs_step.comp) and the CPU reference (double; compute/ocean/springs.cpp). No include
// guard: the includer defines sp_real and sp_real2 and makes sqrt, exp, sin, cos, dot visible.
//
// Nodes on a periodic square grid move vertically only (the document allows it), each tied to its four
// neighbours by a spring. Eq. 4's force of the spring to neighbour j, vertical component:
//   f = c (y_j - y_i) (1 - L / l),  l = sqrt(h² + (y_j - y_i)²)  (h: the node spacing),
// which for L = 0 is Hooke's linear c (y_j - y_i): the discrete wave equation, ring speed sqrt(c/m) cells/s.

// Eq. 4's vertical force on a node from one spring, the neighbour `dy` above it.
LAGOON_FN sp_real sp_spring_force(sp_real dy, sp_real stiffness, sp_real rest, sp_real spacing) {
  if (rest <= sp_real(0)) return stiffness * dy;
  return stiffness * dy * (sp_real(1) - rest / sqrt(spacing * spacing + dy * dy));
}

// Eq. 5 with the springs' force restoring (the document writes -f_i, which would push every node away from
// its neighbours): a = (f + f_ext - γ v) / m, v' = v + a Δt, x' = x + v' Δt (semi-implicit Euler, as
// printed). `xv` is (height, vertical velocity); `pushed` is f_ext / m, upward positive.
LAGOON_FN sp_real2 sp_node_step(sp_real2 xv, sp_real springs, sp_real pushed, sp_real mass, sp_real damping,
                                sp_real dt) {
  sp_real a = (springs - damping * xv.y) / mass + pushed;
  sp_real v = xv.y + a * dt;
  return sp_real2(xv.x + v * dt, v);
}

// The Gaussian weight of an excitation centred on `centre` at the node `p` on a periodic patch of `period` m
// (the nearest image of the centre counts).
LAGOON_FN sp_real sp_patch_weight(sp_real2 p, sp_real2 centre, sp_real sigma, sp_real period) {
  sp_real2 d = p - centre;
  d = d - period * floor(d / period + sp_real(0.5));
  return exp(sp_real(-0.5) * dot(d, d) / (sigma * sigma));
}
