#version 450
// Reflection test: workgroup size from specialization constants. x and z are specializable (SpecId 3 and
// 5, defaults 16 and 1), y is fixed at 4.
layout(local_size_x = 16, local_size_y = 4, local_size_x_id = 3, local_size_z_id = 5) in;

layout(set = 0, binding = 0) buffer Data {
  uint values[];
} data;

void main() {
  data.values[gl_GlobalInvocationID.x] = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
}
