// What every pass of a frame sees (engine/render/passes/): the command buffer, the frame's size and scene,
// and the slot's per-frame buffers. Passes only record into `cmd`; nothing that sees a FrameContext submits.
#pragma once
#include <vulkan/vulkan.h>

#include "scene/scene.h"
#include "vk/buffer.h"
#include "vk/gpu_timer.h"
#include "vk/pipeline.h"
#include "world/camera_medium.h"

namespace lagoon::render {

// The host-written buffers of one frame in flight (OceanRenderer::kSlots of them).
struct FrameSlot {
  vk::Buffer frame;            // gpu::FrameUniforms (shared/frame.h)
  vk::Buffer lights;           // gpu::PointLightGpu[kMaxLights]
  vk::Buffer sediment;         // gpu::SedimentHeader, then gpu::SedimentPuffGpu[LAGOON_MAX_SEDIMENT_PUFFS]
  vk::Buffer surface_indices;  // the clipmap cells drawn for this camera (render/surface_grid.h)
  uint32_t surface_index_count = 0;
  vk::GpuTimer timer;
};

struct FrameContext {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkExtent2D extent{};
  const scene::Scene& scene;
  FrameSlot& slot;
  world::CameraSide camera_side =
      world::CameraSide::Above;    // against the displaced surface (world/camera_medium.h)
  uint32_t light_count = 0;        // point lights in slot.lights
  bool caustics = false;           // the caustics pass makes a map this frame
  bool submerged_objects = false;  // something other than the procedural floor is under the water
  vk::BufferRef uniforms() const { return {slot.frame.handle()}; }
  vk::GpuTimer* timer() const { return &slot.timer; }
};

}  // namespace lagoon::render
