// The frame renderer: the FFT ocean (compute/ocean/gpu) drawn over an analytic sky whose light comes from
// the optics model, water colour from the optics LUTs, then tone mapping (seed 000's eq. 18) and gamma.
// Passes: ocean step, sky, surface (HDR, RGBA16F), post (RGBA8). Reflections of objects, the refraction
// pass and the sea floor arrive with the rest of issue 5; today the surface reflects the sky and shows the
// deep-water colour.
#pragma once
#include <memory>
#include <vector>

#include "io/png.h"
#include "ocean/gpu/gpu_ocean.h"
#include "render/sky_light.h"
#include "scene/scene.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/handle.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class OceanRenderer {
 public:
  static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // display-referred after post
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
  static constexpr uint32_t kGridVertsPerSide = 192;
  // Before a still frame the ocean runs this long (in kWarmupStep steps) so foam has built up.
  static constexpr double kWarmupS = 3.0;
  static constexpr double kWarmupStep = 0.1;

  // Throws lagoon::vk::VulkanError / std::logic_error only on engine bugs; scene values are validated.
  OceanRenderer(vk::Context& ctx, const scene::Scene& scene);
  ~OceanRenderer();

  // Renders `scene` (same ocean and water as at construction) at scene.render size and time scene.time_s.
  io::Image8 render(const scene::Scene& scene, std::vector<vk::PassTime>* timings = nullptr);

 private:
  void record_frame(VkCommandBuffer cmd, const scene::Scene& scene, const vk::Image& hdr,
                    const vk::Image& depth, const vk::Image& color);

  vk::Context& ctx_;
  std::unique_ptr<ocean::GpuOcean> ocean_;
  double ocean_time_ = -1;
  glm::vec3 deep_colour_{0};
  vk::GraphicsPipeline sky_, surface_, post_;
  vk::Buffer frame_;
  vk::Unique<VkSampler> repeat_sampler_, clamp_sampler_;
  vk::GpuTimer timer_;
};

}  // namespace lagoon::render
