#version 450
// y = a*x + y over n floats: the compute round trip's kernel (CPU reference in the test).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer X { float x[]; };
layout(std430, binding = 1) buffer Y { float y[]; };
layout(push_constant) uniform Push { float a; uint n; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < push.n) y[i] = push.a * x[i] + y[i];
}
