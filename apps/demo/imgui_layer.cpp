#include "imgui_layer.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <cstdio>
#include <stdexcept>

#include "vk/check.h"

namespace lagoon::demo {
namespace {

void check_imgui_vk(VkResult result) {
  if (result != VK_SUCCESS)
    throw std::runtime_error("ImGui Vulkan backend: VkResult " + std::to_string(result));
}

}  // namespace

ImGuiLayer::ImGuiLayer(vk::Context& ctx, const Window& window, const Swapchain& swapchain) : ctx_(ctx) {
  create_descriptor_pool();
  create_render_pass(swapchain.format());
  create_framebuffers(swapchain);
  init_backends(window, swapchain);
}

void ImGuiLayer::create_descriptor_pool() {
  // The backend allocates one descriptor set (the font atlas).
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8}};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT,
                                             .maxSets = 8,
                                             .poolSizeCount = 1,
                                             .pPoolSizes = sizes};
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(ctx_.device(), &pool_info, nullptr, &pool));
  pool_ = vk::Unique<VkDescriptorPool>(ctx_.device(), pool);
}

// Loads the swapchain image the frame was copied into, draws over it and leaves it ready to present.
void ImGuiLayer::create_render_pass(VkFormat format) {
  const VkAttachmentDescription attachment{.format = format,
                                           .samples = VK_SAMPLE_COUNT_1_BIT,
                                           .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                           .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                           .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                           .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                           .initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                           .finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
  const VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkSubpassDescription subpass{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
                                     .colorAttachmentCount = 1,
                                     .pColorAttachments = &colour};
  // In: after the copy of the rendered frame. Out: before a screenshot copy (presentation needs none).
  const VkSubpassDependency dependencies[] = {
      {.srcSubpass = VK_SUBPASS_EXTERNAL,
       .dstSubpass = 0,
       .srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
       .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
       .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
       .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT},
      {.srcSubpass = 0,
       .dstSubpass = VK_SUBPASS_EXTERNAL,
       .srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
       .dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
       .srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
       .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT}};
  const VkRenderPassCreateInfo rp_info{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                                       .attachmentCount = 1,
                                       .pAttachments = &attachment,
                                       .subpassCount = 1,
                                       .pSubpasses = &subpass,
                                       .dependencyCount = 2,
                                       .pDependencies = dependencies};
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VK_CHECK(vkCreateRenderPass(ctx_.device(), &rp_info, nullptr, &render_pass));
  render_pass_ = vk::Unique<VkRenderPass>(ctx_.device(), render_pass);
}

// The ImGui context and its GLFW and Vulkan backends, with the font atlas uploaded.
void ImGuiLayer::init_backends(const Window& window, const Swapchain& swapchain) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the working folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = ctx_.instance();
  info.PhysicalDevice = ctx_.physical_device();
  info.Device = ctx_.device();
  info.QueueFamily = ctx_.queue_family();
  info.Queue = ctx_.queue();
  info.PipelineCache = ctx_.pipeline_cache();
  info.DescriptorPool = pool_;
  info.Subpass = 0;
  info.MinImageCount = swapchain.min_image_count();
  info.ImageCount = swapchain.image_count();
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = check_imgui_vk;
  ImGui_ImplVulkan_Init(&info, render_pass_);
  ctx_.submit_and_wait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiLayer::~ImGuiLayer() {
  vkDeviceWaitIdle(ctx_.device());  // not wait_idle(): it throws on a lost device, and a destructor must not
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::create_framebuffers(const Swapchain& swapchain) {
  framebuffers_.clear();
  extent_ = swapchain.extent();
  for (uint32_t i = 0; i < swapchain.image_count(); ++i) {
    const VkImageView view = swapchain.view(i);
    const VkFramebufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                       .renderPass = render_pass_,
                                       .attachmentCount = 1,
                                       .pAttachments = &view,
                                       .width = extent_.width,
                                       .height = extent_.height,
                                       .layers = 1};
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(ctx_.device(), &info, nullptr, &framebuffer));
    framebuffers_.emplace_back(ctx_.device(), framebuffer);
  }
}

void ImGuiLayer::on_swapchain(const Swapchain& swapchain) {
  create_framebuffers(swapchain);
  ImGui_ImplVulkan_SetMinImageCount(swapchain.min_image_count());
}

void ImGuiLayer::new_frame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::record(VkCommandBuffer cmd, uint32_t image, ImDrawData* draw_data) {
  const VkRenderPassBeginInfo begin{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                    .renderPass = render_pass_,
                                    .framebuffer = framebuffers_[image],
                                    .renderArea = {{0, 0}, extent_}};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  if (draw_data && draw_data->CmdListsCount > 0) ImGui_ImplVulkan_RenderDrawData(draw_data, cmd);
  vkCmdEndRenderPass(cmd);
}

}  // namespace lagoon::demo
