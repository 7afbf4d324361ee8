// Suspended particles seen by a camera under the water (shaders/render/particles.*, shared/particles.h), and
// the sediment clouds' grains (render/sediment_grains.vert): drawn over the underwater frame, depth-tested
// against it, blended.
#pragma once
#include "render/frame_context.h"
#include "render/samplers.h"
#include "render/water_luts.h"
#include "shared/particles.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

// Where this frame's particles are: the lattice around the camera and what the shader needs of the scene.
gpu::ParticlesPush particles_push(const scene::Scene& scene);

class ParticlesPass {
 public:
  // `grains`: some vehicle stirs sediment and sediment.grains_per_g > 0.
  ParticlesPass(vk::Context& ctx, const WaterLuts& luts, const Samplers& samplers, VkFormat color_format,
                VkFormat depth_format, bool grains);

  // Over `color` and `depth` (attachments holding the frame from below); nothing when switched off.
  void record(const FrameContext& frame, vk::Target color, vk::Target depth) const;

 private:
  const WaterLuts& luts_;
  const Samplers& samplers_;
  vk::GraphicsPipeline pipeline_;
  vk::GraphicsPipeline grains_;  // empty without grains
};

}  // namespace lagoon::render
