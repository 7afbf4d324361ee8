// The foundation's placeholder scene: an analytic sky and a camera-centred grid displaced by Gerstner
// waves, lit by the sun, rendered offscreen and read back. The surface renderer (issue 5) replaces it.
#pragma once
#include <vector>

#include "io/png.h"
#include "scene/scene.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class PlaceholderRenderer {
 public:
  static constexpr VkFormat kColorFormat =
      VK_FORMAT_R8G8B8A8_UNORM;  // display-referred: gamma applied in shader
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
  static constexpr uint32_t kGridVertsPerSide = 160;
  // Beyond ~1.5 km the placeholder's 5-38 m waves are smaller than a grid cell; the sky fog hides the edge.
  static constexpr float kGridHalfExtentM = 1500.0f;

  explicit PlaceholderRenderer(vk::Context& ctx);

  // Renders `scene` at scene.render.width x height and time scene.time_s. Per-pass GPU times go to `timings`.
  io::Image8 render(const scene::Scene& scene, std::vector<vk::PassTime>* timings = nullptr);

 private:
  vk::Context& ctx_;
  vk::GraphicsPipeline sky_;
  vk::GraphicsPipeline grid_;
  vk::Buffer frame_;
  vk::GpuTimer timer_;
};

}  // namespace lagoon::render
