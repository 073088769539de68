#include "view/ui.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "util/error.h"
#include "vk/commands.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

void checkImguiVulkanResult(VkResult result) {
  if (result != VK_SUCCESS) failVulkanCall("ImGui Vulkan backend", result, __FILE__, __LINE__);
}

VkRenderPass createUiRenderPass(const Device& device, VkFormat format) {
  VkAttachmentDescription attachment{};
  attachment.format = format;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // draw over the blitted image
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  const VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  // The blit's writes come before the UI's loads and blending.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependency.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &dependency;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VK_CHECK(vkCreateRenderPass(device.handle, &info, nullptr, &renderPass));
  setDebugName(device, VK_OBJECT_TYPE_RENDER_PASS, reinterpret_cast<std::uint64_t>(renderPass), "ui render pass");
  return renderPass;
}

void destroyFramebuffers(const Device& device, Ui& ui) {
  for (VkFramebuffer framebuffer : ui.framebuffers) vkDestroyFramebuffer(device.handle, framebuffer, nullptr);
  ui.framebuffers.clear();
}

}  // namespace

Ui createUi(const Instance& instance, const Device& device, const Window& window, const Swapchain& swapchain) {
  Ui ui;
  ui.format = swapchain.format;
  // The font atlas is the backend's only sampled image.
  const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &poolSize;
  VK_CHECK(vkCreateDescriptorPool(device.handle, &poolInfo, nullptr, &ui.descriptorPool));
  setDebugName(device, ui.descriptorPool, "ui descriptor pool");
  ui.renderPass = createUiRenderPass(device, swapchain.format);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the user's working directory
  ImGui::StyleColorsDark();
  ImGui::GetStyle().Alpha = 0.94f;
  ImGui_ImplGlfw_InitForVulkan(window.handle, true);

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = instance.handle;
  info.PhysicalDevice = device.physical;
  info.Device = device.handle;
  info.QueueFamily = device.queueFamily;
  info.Queue = device.queue;
  info.DescriptorPool = ui.descriptorPool;
  info.Subpass = 0;
  info.MinImageCount = swapchain.minImageCount;
  info.ImageCount = static_cast<std::uint32_t>(swapchain.images.size());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImguiVulkanResult;
  if (!ImGui_ImplVulkan_Init(&info, ui.renderPass)) throw Error("the ImGui Vulkan backend failed to initialise");
  submitAndWait(device, [](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  recreateUiFramebuffers(device, ui, swapchain);
  return ui;
}

void destroyUi(const Device& device, Ui& ui) {
  if (ui.renderPass == VK_NULL_HANDLE) return;
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  destroyFramebuffers(device, ui);
  vkDestroyRenderPass(device.handle, ui.renderPass, nullptr);
  vkDestroyDescriptorPool(device.handle, ui.descriptorPool, nullptr);
  ui = {};
}

void recreateUiFramebuffers(const Device& device, Ui& ui, const Swapchain& swapchain) {
  if (swapchain.format != ui.format) throw Error("the swapchain changed its format; the UI cannot follow");
  destroyFramebuffers(device, ui);
  for (VkImageView view : swapchain.views) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = ui.renderPass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = swapchain.extent.width;
    info.height = swapchain.extent.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(device.handle, &info, nullptr, &framebuffer));
    setDebugName(device, VK_OBJECT_TYPE_FRAMEBUFFER, reinterpret_cast<std::uint64_t>(framebuffer), "ui framebuffer");
    ui.framebuffers.push_back(framebuffer);
  }
  ImGui_ImplVulkan_SetMinImageCount(swapchain.minImageCount);
}

void beginUiFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void recordUi(VkCommandBuffer cmd, const Ui& ui, const Swapchain& swapchain, std::uint32_t imageIndex) {
  ImGui::Render();
  // The render area is the union of the draw commands' clip rectangles (every fragment is scissored to one),
  // so the rest of the window needs no load or store; without any, there is no render pass at all.
  const ImDrawData* data = ImGui::GetDrawData();
  VkRect2D area{};
  if (data != nullptr) {
    ImVec2 lo(FLT_MAX, FLT_MAX), hi(-FLT_MAX, -FLT_MAX);
    for (int list = 0; list < data->CmdListsCount; ++list) {
      for (const ImDrawCmd& command : data->CmdLists[list]->CmdBuffer) {
        lo = ImVec2(std::min(lo.x, command.ClipRect.x), std::min(lo.y, command.ClipRect.y));
        hi = ImVec2(std::max(hi.x, command.ClipRect.z), std::max(hi.y, command.ClipRect.w));
      }
    }
    const auto clampTo = [](float value, std::uint32_t size) {
      return static_cast<std::int32_t>(std::clamp(value, 0.0f, float(size)));
    };
    area.offset = {clampTo(std::floor(lo.x), swapchain.extent.width),
                   clampTo(std::floor(lo.y), swapchain.extent.height)};
    const std::int32_t right = clampTo(std::ceil(hi.x), swapchain.extent.width);
    const std::int32_t bottom = clampTo(std::ceil(hi.y), swapchain.extent.height);
    area.extent = {static_cast<std::uint32_t>(std::max(right - area.offset.x, 0)),
                   static_cast<std::uint32_t>(std::max(bottom - area.offset.y, 0))};
  }
  if (area.extent.width == 0 || area.extent.height == 0) {
    // Nothing to draw: only the layout transition the render pass would have made.
    imageBarrier(cmd, swapchain.images[imageIndex],
                 {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR});
    return;
  }
  VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  info.renderPass = ui.renderPass;
  info.framebuffer = ui.framebuffers[imageIndex];
  info.renderArea = area;
  vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

bool uiWantsMouse() { return ImGui::GetIO().WantCaptureMouse; }
bool uiWantsKeyboard() { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace raylab
