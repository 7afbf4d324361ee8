// lagoon-demo's window, frame loop and panel: the same OceanRenderer as the CLI draws into a swapchain
// (copied, then the UI on top), with frames in flight (vk::FrameRing and the renderer's slots).
#pragma once
#include "demo_options.h"

namespace lagoon::demo {

// Runs until the window closes (or after --frames with --exit). Returns the process exit code.
int run_demo(DemoOptions options);

}  // namespace lagoon::demo
