// Parts 2 and 3 of the embedding example: a host engine that owns its Vulkan instance, device, queue,
// command buffers and render targets, loads a Lagoon scene and lets Lagoon record the ocean step and the
// water into its own command buffers and images. Headless; the last frame is read back and written as PNG.
//
//   embed_render SCENE.json OUT.png [WIDTH HEIGHT]
//
// Environment: LAGOON_DEVICE picks the device whose name contains it (case-insensitive; default: the first
// Vulkan 1.3 device); LAGOON_VALIDATION=1 turns on the validation layer with synchronization validation,
// and any error it reports makes the exit status 3. docs/embedding.md describes the contract.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "io/png.h"
#include "render/ocean_renderer.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "vk/context.h"

namespace {

using lagoon::render::OceanRenderer;

// Frames the host keeps in flight; Lagoon's renderer has kSlots sets of per-frame buffers.
constexpr uint32_t kFramesInFlight = OceanRenderer::kSlots;
constexpr uint32_t kFrames = 3;  // more than kFramesInFlight, so a slot is reused after its fence wait

// The host's own handling of "cannot happen" Vulkan failures.
void check(VkResult result, const char* call) {
  if (result == VK_SUCCESS) return;
  std::fprintf(stderr, "embed_render: %s failed (VkResult %d)\n", call, static_cast<int>(result));
  std::exit(1);
}

std::string env(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// The host's validation callback: errors and validation warnings count as failures, as in Lagoon's tests.
VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT type,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                     void* user) {
  const bool failure = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ||
                       ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) &&
                        (type & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT));
  if (failure) ++*static_cast<int*>(user);
  std::fprintf(stderr, "embed_render: validation %s: %s\n", failure ? "error" : "note", data->pMessage);
  return VK_FALSE;
}

// The host's instance, device and queue, destroyed in reverse order of creation.
struct HostGpu {
  bool validation = false;
  int* validation_failures = nullptr;  // counted by the messenger; outlives this object
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  uint32_t queue_family = 0;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  // The extensions and feature chain vkCreateDevice got; Context::adopt() checks them.
  std::vector<const char*> device_extensions;
  std::unique_ptr<lagoon::vk::RequiredFeatures> features;
  float queue_priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  VkDeviceCreateInfo device_info{};

  explicit HostGpu(int* failures) : validation_failures(failures) {}
  HostGpu(const HostGpu&) = delete;
  HostGpu& operator=(const HostGpu&) = delete;
  ~HostGpu() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
      destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
  }

  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    std::fprintf(stderr, "embed_render: no memory type with flags 0x%x\n", flags);
    std::exit(1);
  }
};

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

// Instance (with the validation layer and a messenger when asked), device and queue: what any engine has
// already made before it embeds Lagoon. Returns false with a message when the machine cannot do it.
bool create_host_gpu(HostGpu& gpu) {
  gpu.validation = !env("LAGOON_VALIDATION").empty() && env("LAGOON_VALIDATION") != "0";
  std::vector<const char*> layers, extensions;
  if (gpu.validation) {
    if (!has_layer("VK_LAYER_KHRONOS_validation")) {
      std::fprintf(stderr,
                   "embed_render: LAGOON_VALIDATION is set but VK_LAYER_KHRONOS_validation is missing\n");
      return false;
    }
    layers.push_back("VK_LAYER_KHRONOS_validation");
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "lagoon-embed-example",
                              .apiVersion = lagoon::vk::kRequiredApiVersion};
  const VkDebugUtilsMessengerCreateInfoEXT messenger_info{
      .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
      .messageSeverity =
          VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
      .messageType =
          VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
      .pfnUserCallback = &on_validation_message,
      .pUserData = gpu.validation_failures};
  // Synchronization validation checks the hand-over between the host's commands and Lagoon's.
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  const VkValidationFeaturesEXT validation_features{.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
                                                    .pNext = &messenger_info,
                                                    .enabledValidationFeatureCount = 1,
                                                    .pEnabledValidationFeatures = enables};
  const VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                           .pNext = gpu.validation ? &validation_features : nullptr,
                                           .pApplicationInfo = &app,
                                           .enabledLayerCount = static_cast<uint32_t>(layers.size()),
                                           .ppEnabledLayerNames = layers.data(),
                                           .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                                           .ppEnabledExtensionNames = extensions.data()};
  if (VkResult r = vkCreateInstance(&instance_info, nullptr, &gpu.instance); r != VK_SUCCESS) {
    std::fprintf(stderr,
                 "embed_render: no Vulkan 1.3 instance (VkResult %d); is a Vulkan driver installed?\n",
                 static_cast<int>(r));
    return false;
  }
  if (gpu.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
    check(create(gpu.instance, &messenger_info, nullptr, &gpu.messenger), "vkCreateDebugUtilsMessengerEXT");
  }

  // The device: LAGOON_DEVICE's substring of the name, else the first that has Vulkan 1.3.
  uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  const std::string wanted = lowercase(env("LAGOON_DEVICE"));
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(d, &props);
    if (props.apiVersion < lagoon::vk::kRequiredApiVersion) continue;
    if (!wanted.empty() && lowercase(props.deviceName).find(wanted) == std::string::npos) continue;
    gpu.physical_device = d;
    gpu.properties = props;
    break;
  }
  if (!gpu.physical_device) {
    std::fprintf(stderr, "embed_render: no Vulkan 1.3 device%s%s\n", wanted.empty() ? "" : " named like ",
                 wanted.c_str());
    return false;
  }
  vkGetPhysicalDeviceMemoryProperties(gpu.physical_device, &gpu.memory);

  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical_device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical_device, &family_count, families.data());
  const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  gpu.queue_family = family_count;
  for (uint32_t i = 0; i < family_count && gpu.queue_family == family_count; ++i)
    if ((families[i].queueFlags & need) == need) gpu.queue_family = i;
  if (gpu.queue_family == family_count) {
    std::fprintf(stderr, "embed_render: %s has no graphics+compute queue\n", gpu.properties.deviceName);
    return false;
  }

  // What Lagoon needs, as Lagoon reports it; an engine would add its own extensions and features here.
  gpu.device_extensions = lagoon::vk::required_device_extensions();
  gpu.features = std::make_unique<lagoon::vk::RequiredFeatures>(gpu.physical_device);
  gpu.queue_info = {.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                    .queueFamilyIndex = gpu.queue_family,
                    .queueCount = 1,
                    .pQueuePriorities = &gpu.queue_priority};
  gpu.device_info = {.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                     .pNext = gpu.features->chain(),
                     .queueCreateInfoCount = 1,
                     .pQueueCreateInfos = &gpu.queue_info,
                     .enabledExtensionCount = static_cast<uint32_t>(gpu.device_extensions.size()),
                     .ppEnabledExtensionNames = gpu.device_extensions.data()};
  if (VkResult r = vkCreateDevice(gpu.physical_device, &gpu.device_info, nullptr, &gpu.device);
      r != VK_SUCCESS) {
    std::fprintf(stderr, "embed_render: vkCreateDevice on %s failed (VkResult %d)\n",
                 gpu.properties.deviceName, static_cast<int>(r));
    return false;
  }
  vkGetDeviceQueue(gpu.device, gpu.queue_family, 0, &gpu.queue);
  return true;
}

// An image the host owns, with its memory and view.
struct HostImage {
  VkDevice device = VK_NULL_HANDLE;
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;

  HostImage(const HostGpu& gpu, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
            VkImageAspectFlags aspect)
      : device(gpu.device) {
    const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                                 .imageType = VK_IMAGE_TYPE_2D,
                                 .format = format,
                                 .extent = {extent.width, extent.height, 1},
                                 .mipLevels = 1,
                                 .arrayLayers = 1,
                                 .samples = VK_SAMPLE_COUNT_1_BIT,
                                 .tiling = VK_IMAGE_TILING_OPTIMAL,
                                 .usage = usage,
                                 .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    check(vkCreateImage(device, &info, nullptr, &image), "vkCreateImage");
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, image, &req);
    const VkMemoryAllocateInfo alloc{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = req.size,
        .memoryTypeIndex = gpu.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
    check(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
    check(vkBindImageMemory(device, image, memory, 0), "vkBindImageMemory");
    const VkImageViewCreateInfo view_info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                          .image = image,
                                          .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                          .format = format,
                                          .subresourceRange = {aspect, 0, 1, 0, 1}};
    check(vkCreateImageView(device, &view_info, nullptr, &view), "vkCreateImageView");
  }
  HostImage(const HostImage&) = delete;
  HostImage& operator=(const HostImage&) = delete;
  ~HostImage() {
    vkDestroyImageView(device, view, nullptr);
    vkDestroyImage(device, image, nullptr);
    vkFreeMemory(device, memory, nullptr);
  }
};

// A host-visible buffer the colour image is copied into.
struct HostReadback {
  VkDevice device = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;

  HostReadback(const HostGpu& gpu, VkDeviceSize size) : device(gpu.device) {
    const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                  .size = size,
                                  .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT};
    check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, buffer, &req);
    const VkMemoryAllocateInfo alloc{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = req.size,
        .memoryTypeIndex = gpu.memory_type(
            req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)};
    check(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
    check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  }
  HostReadback(const HostReadback&) = delete;
  HostReadback& operator=(const HostReadback&) = delete;
  ~HostReadback() {
    vkDestroyBuffer(device, buffer, nullptr);
    vkFreeMemory(device, memory, nullptr);
  }
};

// The host's command pool, one command buffer and fence per frame in flight.
struct HostFrames {
  VkDevice device = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd[kFramesInFlight]{};
  VkFence done[kFramesInFlight]{};

  explicit HostFrames(const HostGpu& gpu) : device(gpu.device) {
    const VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                            .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                            .queueFamilyIndex = gpu.queue_family};
    check(vkCreateCommandPool(device, &pool_info, nullptr, &pool), "vkCreateCommandPool");
    const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                            .commandPool = pool,
                                            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                            .commandBufferCount = kFramesInFlight};
    check(vkAllocateCommandBuffers(device, &alloc, cmd), "vkAllocateCommandBuffers");
    const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
                                       .flags = VK_FENCE_CREATE_SIGNALED_BIT};
    for (VkFence& f : done) check(vkCreateFence(device, &fence_info, nullptr, &f), "vkCreateFence");
  }
  HostFrames(const HostFrames&) = delete;
  HostFrames& operator=(const HostFrames&) = delete;
  ~HostFrames() {
    for (VkFence f : done) vkDestroyFence(device, f, nullptr);
    vkDestroyCommandPool(device, pool, nullptr);
  }
};

// The host's own work after Lagoon's: copy the colour image (left in COLOR_ATTACHMENT_OPTIMAL after colour
// writes) into the readback buffer and make it visible to the CPU.
void record_readback(VkCommandBuffer cmd, const HostImage& color, VkExtent2D extent,
                     const HostReadback& readback) {
  const VkImageMemoryBarrier2 to_copy{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                                      .srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                      .srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                      .dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                      .dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT,
                                      .oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                      .newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                      .image = color.image,
                                      .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
  const VkDependencyInfo before{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                .imageMemoryBarrierCount = 1,
                                .pImageMemoryBarriers = &to_copy};
  vkCmdPipelineBarrier2(cmd, &before);
  const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .imageExtent = {extent.width, extent.height, 1}};
  vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
  const VkBufferMemoryBarrier2 to_host{.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
                                       .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                       .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                       .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                                       .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT,
                                       .buffer = readback.buffer,
                                       .size = VK_WHOLE_SIZE};
  const VkDependencyInfo after{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                               .bufferMemoryBarrierCount = 1,
                               .pBufferMemoryBarriers = &to_host};
  vkCmdPipelineBarrier2(cmd, &after);
}

int run(int argc, char** argv, HostGpu& gpu) {
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: embed_render SCENE.json OUT.png [WIDTH HEIGHT]\n");
    return 2;
  }
  const std::string width = argc == 5 ? argv[3] : "320", height = argc == 5 ? argv[4] : "180";

  // Part 2: a scene file, with the size overridden the way `lagoon render --set` does.
  const std::vector<std::string> overrides{"render.width=" + width, "render.height=" + height};
  auto loaded = lagoon::scene::load_scene(argv[1], overrides);
  if (!loaded) {
    std::fprintf(stderr, "embed_render: %s\n", loaded.error().message.c_str());
    return 1;
  }
  lagoon::scene::Scene scene = *loaded;
  const VkExtent2D extent{scene.render.width, scene.render.height};
  std::printf("scene %s: %zu object(s), %zu cascade(s), %ux%u\n", argv[1], scene.objects.size(),
              scene.ocean.cascades.size(), extent.width, extent.height);

  // Part 3: the host's device, wrapped (not owned) by Lagoon.
  if (!create_host_gpu(gpu)) return 1;
  std::printf("device: %s\n", gpu.properties.deviceName);
  lagoon::vk::AdoptOptions adopt_options = lagoon::vk::AdoptOptions::from_environment();
  adopt_options.frames_in_flight = kFramesInFlight;
  auto adopted = lagoon::vk::Context::adopt({.instance = gpu.instance,
                                             .instance_api_version = lagoon::vk::kRequiredApiVersion,
                                             .debug_utils = gpu.validation,
                                             .physical_device = gpu.physical_device,
                                             .device = gpu.device,
                                             .device_create_info = &gpu.device_info,
                                             .queue = gpu.queue,
                                             .queue_family = gpu.queue_family},
                                            adopt_options);
  if (!adopted) {
    std::fprintf(stderr, "embed_render: %s\n", adopted.error().message.c_str());
    return 1;
  }
  // Lagoon's context and renderer, like the host's images below, are destroyed when run() returns, before
  // the device (main's HostGpu). The context waits for the device to be idle first.
  std::unique_ptr<lagoon::vk::Context> ctx = std::move(adopted.value());

  // The host's render targets, in the formats the renderer draws (OceanRenderer::kColorFormat =
  // R8G8B8A8_UNORM, kDepthFormat = D32_SFLOAT).
  const HostImage color(gpu, OceanRenderer::kColorFormat, extent,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                        VK_IMAGE_ASPECT_COLOR_BIT);
  const HostImage depth(gpu, OceanRenderer::kDepthFormat, extent, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                        VK_IMAGE_ASPECT_DEPTH_BIT);
  const HostReadback readback(gpu, VkDeviceSize{extent.width} * extent.height * 4);
  const HostFrames frames(gpu);

  auto created = OceanRenderer::create(*ctx, scene);
  if (!created) {
    std::fprintf(stderr, "embed_render: %s\n", created.error().message.c_str());
    return 1;
  }
  std::unique_ptr<OceanRenderer> renderer = std::move(created.value());

  const lagoon::render::HostTargets targets{.color = color.image,
                                            .color_view = color.view,
                                            .depth = depth.image,
                                            .depth_view = depth.view,
                                            .extent = extent};
  const float start_s = scene.time_s;
  for (uint32_t frame = 0; frame < kFrames; ++frame) {
    const uint32_t slot = frame % kFramesInFlight;
    VkFence fence = frames.done[slot];
    VkCommandBuffer cmd = frames.cmd[slot];
    // The slot's previous frame has finished: its command buffer can be reused, and what Lagoon retired
    // while recording it can go.
    check(vkWaitForFences(gpu.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(gpu.device, 1, &fence), "vkResetFences");
    ctx->deferred().begin_frame(slot);

    // 30 frames per second, the last one at the scene's time (the frame `lagoon render` draws).
    scene.time_s = start_s - float(kFrames - 1 - frame) / 30.0f;
    renderer->prepare(scene);  // may submit to the queue and wait (foam warm-up on the first frame)
    check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                         .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    renderer->record(cmd, scene, targets, slot);  // the ocean step, then every pass, into the host's images
    if (frame + 1 == kFrames) record_readback(cmd, color, extent, readback);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    const VkCommandBufferSubmitInfo cmd_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                             .commandBuffer = cmd};
    const VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                               .commandBufferInfoCount = 1,
                               .pCommandBufferInfos = &cmd_info};
    check(vkQueueSubmit2(gpu.queue, 1, &submit, fence), "vkQueueSubmit2");
  }
  check(vkWaitForFences(gpu.device, kFramesInFlight, frames.done, VK_TRUE, UINT64_MAX), "vkWaitForFences");

  lagoon::io::Image8 image{.width = extent.width, .height = extent.height};
  image.rgba.resize(size_t{extent.width} * extent.height * 4);
  std::memcpy(image.rgba.data(), readback.mapped, image.rgba.size());
  if (auto written = lagoon::io::write_png(argv[2], image); !written) {
    std::fprintf(stderr, "embed_render: %s\n", written.error().message.c_str());
    return 1;
  }

  // A frame that drew nothing (no water, wrong layouts, lost writes) comes back as one colour.
  size_t differing = 0;
  for (size_t i = 4; i < image.rgba.size(); i += 4)
    if (std::memcmp(&image.rgba[i], image.rgba.data(), 4) != 0) ++differing;
  std::printf("wrote %s: %zu of %zu pixels differ from the first\n", argv[2], differing,
              image.rgba.size() / 4 - 1);
  if (differing == 0) {
    std::fprintf(stderr, "embed_render: the frame is uniform: nothing was drawn\n");
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int validation_failures = 0;
  int status = 0;
  {
    // Outlives everything run() makes on it, Lagoon's objects included; destroyed before the count is read,
    // so objects left alive at vkDestroyDevice count as failures too.
    HostGpu gpu(&validation_failures);
    status = run(argc, argv, gpu);
  }
  if (status == 0 && validation_failures > 0) {
    std::fprintf(stderr, "embed_render: the validation layer reported %d error(s)\n", validation_failures);
    return 3;
  }
  return status;
}
