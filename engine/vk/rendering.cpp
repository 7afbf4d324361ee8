#include "vk/rendering.h"

#include <vector>

namespace lagoon::vk {

void begin_rendering(VkCommandBuffer cmd, VkExtent2D extent, std::initializer_list<ColorTarget> colors,
                     std::optional<DepthTarget> depth) {
  std::vector<VkRenderingAttachmentInfo> color_infos;
  for (const ColorTarget& c : colors) {
    VkRenderingAttachmentInfo info{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = c.view,
        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        .loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    if (c.clear) info.clearValue.color = {{(*c.clear)[0], (*c.clear)[1], (*c.clear)[2], (*c.clear)[3]}};
    color_infos.push_back(info);
  }
  VkRenderingAttachmentInfo depth_info{};
  if (depth) {
    depth_info = {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                  .imageView = depth->view,
                  .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                  .loadOp = depth->clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                  .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    depth_info.clearValue.depthStencil = {depth->clear.value_or(1.0f), 0};
  }
  const VkRenderingInfo info{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                             .renderArea = {{0, 0}, extent},
                             .layerCount = 1,
                             .colorAttachmentCount = static_cast<uint32_t>(color_infos.size()),
                             .pColorAttachments = color_infos.data(),
                             .pDepthAttachment = depth ? &depth_info : nullptr};
  vkCmdBeginRendering(cmd, &info);
  // Negative-height viewport: y up in clip space, as in OpenGL and GLM's projection matrices.
  const VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f,
                            1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void end_rendering(VkCommandBuffer cmd) {
  vkCmdEndRendering(cmd);
}

}  // namespace lagoon::vk
