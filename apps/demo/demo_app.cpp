// run_demo(): the Demo's start-up, its loop and the summary it prints at the end.
#include "demo_app.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "demo.h"
#include "exit_codes.h"
#include "gpu_session.h"
#include "interrupt_guard.h"
#include "vk/check.h"

namespace lagoon::demo {

Demo::~Demo() {
  // Not wait_idle(): it throws on a lost device, and a destructor must not.
  if (ctx_) vkDeviceWaitIdle(ctx_->device());
}

int Demo::run() {
  // Ctrl-C or SIGTERM closes the demo as its window's close button does: the loop ends (at once when the
  // signal came during start-up), the GPU drains, and the validation result still decides the exit code.
  cli::InterruptGuard interrupt;
  if (const int status = start(); status != cli::kExitOk) return status;
  while (!window_->should_close() && !interrupt.signal()) {
    window_->poll_events();
    if (!frame()) break;  // the last of --frames, with --exit
  }
  ctx_->wait_idle();
  cold_failures_ += render::ColdCompile::finish(cold_, *ctx_);
  print_summary();
  if (int v = cli::validation_status(*ctx_); v != cli::kExitOk) return v;
  if (cold_failures_ > 0) {
    std::fprintf(stderr,
                 "lagoon-demo: the Vulkan validation layer reported %u error(s) on the cold start's second "
                 "device (render/cold_compile.h); see the messages above\n",
                 cold_failures_);
    return cli::kExitValidation;
  }
  return exit_status_;
}

// The window, a device that can present to it, the renderer, the swapchain and the UI; an exit code.
int Demo::start() {
  auto window = Window::create(options_.width, options_.height, "Lagoon");
  if (!window) {
    std::fprintf(stderr, "lagoon-demo: %s\n", window.error().message.c_str());
    return cli::kExitFailure;
  }
  window_ = std::move(*window);
  // For the tests of the error path: the device is reported lost right after that frame is submitted.
  if (const char* fail = std::getenv("LAGOON_DEMO_FAIL_AFTER_FRAME")) fail_after_frame_ = std::atoll(fail);
  vk::ContextOptions context_options = vk::ContextOptions::from_environment();
  context_options.instance_extensions = Window::required_instance_extensions();
  context_options.create_surface = [&](VkInstance instance) { return window_->create_surface(instance); };
  context_options.frames_in_flight = render::OceanRenderer::kSlots;
  auto ctx = vk::Context::create(context_options);
  if (!ctx) {
    std::fprintf(stderr, "lagoon-demo: %s\n", ctx.error().message.c_str());
    return cli::kExitFailure;
  }
  ctx_ = std::move(*ctx);
  cold_ = render::ColdCompile::start_if_cold(*ctx_, context_options, scene_);
  vsync_ = options_.vsync;
  resolution_.set_target_fps(options_.target_fps);
  show_ui_ = !options_.hide_ui;
  time_s_ = scene_.time_s;
  camera_.emplace(scene_.camera);
  if (auto r = rebuild_renderer(); !r) {
    std::fprintf(stderr, "lagoon-demo: %s: %s\n", scene_.source.c_str(), r.error().message.c_str());
    return cli::kExitFailure;
  }
  swapchain_ = std::make_unique<Swapchain>(*ctx_, window_->framebuffer_extent(), vsync_);
  ui_ = std::make_unique<ImGuiLayer>(*ctx_, *window_, *swapchain_);
  ring_ = std::make_unique<vk::FrameRing>(*ctx_, render::OceanRenderer::kSlots);
  create_acquire_semaphores();
  t0_ = time_s_;
  last_frame_ = Clock::now();
  return cli::kExitOk;
}

// One per frame slot: the image acquired for a slot's frame is waited on by that slot's submit.
void Demo::create_acquire_semaphores() {
  for (uint32_t i = 0; i < render::OceanRenderer::kSlots; ++i) {
    const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(ctx_->device(), &info, nullptr, &s));
    acquired_.emplace_back(ctx_->device(), s);
  }
}

void Demo::print_summary() const {
  // The median skips the first frames (pipeline compilation, warm-up), as `lagoon bench` does; a run closed
  // before there were more (a loaded machine, an early SIGTERM) still says what it drew.
  std::string median;
  if (frame_ms_.size() > 2) {
    std::vector<float> times(frame_ms_.begin() + 2, frame_ms_.end());
    std::sort(times.begin(), times.end());
    char text[64];
    std::snprintf(text, sizeof text, "; median frame time %.1f ms", times[times.size() / 2]);
    median = text;
  }
  std::printf("lagoon-demo: %lld frames at %ux%u on %s%s\n", frame_, swapchain_->extent().width,
              swapchain_->extent().height, ctx_->device_info().name.c_str(), median.c_str());
  if (!options_.frames && resolution_.target_fps() > 0) {
    const VkExtent2D drawn = resolution_.render_extent(swapchain_->extent());
    std::printf("lagoon-demo: live frames drawn at %.0f %% of the window (%ux%u) for %g frames a second\n",
                100.0 * resolution_.scale(), drawn.width, drawn.height, resolution_.target_fps());
  }
  print_helm();
}

int run_demo(DemoOptions options) {
  Demo demo(std::move(options));
  return demo.run();
}

}  // namespace lagoon::demo
