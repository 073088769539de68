// The comparison instrument: the split view's right side (start, stop, follow the scene), the difference view's
// statistics, the mouse over the image (divider, picking, hovering), the lobe plot, and their script events.
#include "view/viewer_state.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "brdf_params/material_params.h"
#include "scene/camera_frame.h"
#include "scene/camera_pivot.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "vk/commands.h"

namespace raylab {

namespace {

// The largest channel of |A - B|, or of it over the larger of A and B (zero where both are black).
float pixelDifference(const glm::vec4& a, const glm::vec4& b, bool relative) {
  const glm::vec3 d = glm::abs(glm::vec3(a) - glm::vec3(b));
  const float shown = std::max({d.r, d.g, d.b});
  if (!relative) return shown;
  const float level = std::max({a.r, a.g, a.b, b.r, b.g, b.b});
  return level > 0.0f ? shown / level : 0.0f;
}

std::string materialName(const Scene& scene, std::uint32_t material) {
  const Material& m = scene.materials.at(material);
  return (m.name.empty() ? "material " + std::to_string(material) : m.name) + " (" +
         std::string(modelInfo(m.record.model).name) + ")";
}

// The first surface through the centre of `pixel` of the traced image: the CPU cast of camera_pivot.h.
std::optional<SceneHit> castThrough(const Viewer& v, glm::uvec2 pixel) {
  gpu::FrameParams params{};
  params.width = v.scheduler.traceExtent.x;
  params.height = v.scheduler.traceExtent.y;
  applyCamera(params, v.camera, params.width, params.height);
  return firstHit(v.scene, params.cameraOrigin, primaryDirection(params, pixel));
}

glm::uvec2 tracedExtent(const Viewer& v) {
  return glm::max(v.scheduler.traceExtent, glm::uvec2(1));
}

}  // namespace

void startComparing(Viewer& v, const CompareSpec& spec) {
  waitForFrames(v);
  RenderSettings settings = v.options.render;
  settings.width = v.scheduler.fullExtent.x;
  settings.height = v.scheduler.fullExtent.y;
  settings.backend = v.renderer.trace.backend;
  startComparison(v.device, v.gpuScene, v.scene, settings, v.integrator, spec, v.comparison);
  v.comparedRecord = spec.record;
  bindCompared(v.device, v.display, v.comparison.renderer.accumulation.handle);
  v.difference = {};
  v.kernelState = KernelState::kFirstDispatch;
  v.pending.accumulation = true;
  v.pending.display = true;
  v.status.message = rightLabel(v.scene, v.comparison);
}

void stopComparing(Viewer& v) {
  if (!v.comparison.active) return;
  waitForFrames(v);
  stopComparison(v.device, v.comparison);
  bindCompared(v.device, v.display, v.renderer.accumulation.handle);
  v.difference = {};
  v.pending.display = true;
}

void refreshComparison(Viewer& v) {
  if (!v.comparison.active) return;
  waitForFrames(v);
  const KernelFeatures before = v.comparison.renderer.kernel;
  updateComparison(v.device, v.scene, v.integrator, v.comparison);
  if (!(before == v.comparison.renderer.kernel)) v.kernelState = KernelState::kFirstDispatch;
  v.pending.accumulation = true;
}

DisplaySettings displaySettings(const Viewer& v) {
  DisplaySettings display{v.settings.exposure, v.settings.toneMap};
  if (v.comparison.active) {
    constexpr DisplayMode kModes[] = {DisplayMode::kSplit, DisplayMode::kDifference, DisplayMode::kRelativeDifference};
    display.mode = kModes[static_cast<int>(v.compareView.show)];
    display.divider = v.compareView.divider;
    display.differenceScale = v.compareView.differenceScale;
  }
  return display;
}

bool handlePointer(Viewer& v) {
  glm::dvec2 cursor;
  glfwGetCursorPos(v.window.handle, &cursor.x, &cursor.y);
  const VkRect2D area = imageArea(v);
  PointerInput input;
  input.cursor = glm::vec2(cursor);
  input.left = glfwGetMouseButton(v.window.handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  input.uiWantsMouse = uiWantsMouse();
  input.imageOrigin = glm::vec2(float(area.offset.x), float(area.offset.y));
  input.imageSize = glm::max(glm::vec2(float(area.extent.width), float(area.extent.height)), glm::vec2(1.0f));
  if (v.comparison.active && v.compareView.show == CompareShow::kSplit) input.divider = v.compareView.divider;
  const PointerEvents events = updatePointer(v.pointer, input);
  v.cursor = input.cursor;
  if (events.divider) {
    v.compareView.divider = *events.divider;
  }
  if (events.click) pickAt(v, *events.click);
  const double now = v.clock.seconds();
  if (!events.hover) {
    v.hovered.clear();
  } else if (*events.hover != v.hoveredAt && now - v.lastHover >= kHoverSeconds &&
             v.gpuScene.triangleCount <= kHoverTriangles && v.scheduler.traceExtent.x > 0) {
    const std::optional<SceneHit> hit = castThrough(v, pixelAt(*events.hover, tracedExtent(v)));
    v.hovered = hit ? materialName(v.scene, hit->material) : "";
    v.hoveredAt = *events.hover;
    v.lastHover = now;
  }
  return events.cameraBlocked;
}

void pickAt(Viewer& v, glm::vec2 fraction) {
  if (v.scheduler.traceExtent.x == 0) return;
  const glm::uvec2 pixel = pixelAt(fraction, tracedExtent(v));
  PickedPixel picked;
  picked.pixel = pixel;
  const std::optional<SceneHit> hit = castThrough(v, pixel);
  if (hit) {
    v.selection.material = hit->material;
    picked.material = materialName(v.scene, hit->material);
  } else {
    picked.material = "(background)";
  }
  waitForFrames(v);
  picked.left = readPixel(v.device, v.renderer, pixel);
  if (v.comparison.active) picked.right = readPixel(v.device, v.comparison.renderer, pixel);
  v.picked = picked;
  if (!v.options.quiet && v.automation) {
    std::printf("raylab view: picked (%u, %u): %s, %.6g %.6g %.6g (%u spp)\n", pixel.x, pixel.y,
                picked.material.c_str(), double(picked.left.radiance.r), double(picked.left.radiance.g),
                double(picked.left.radiance.b), picked.left.samples);
  }
}

bool differenceStatsDue(const Viewer& v) {
  if (!v.panelShown || !v.comparison.active || v.scheduler.sampleIndex == 0 || v.scheduler.preview) return false;
  const bool reading = std::any_of(v.slots.begin(), v.slots.end(),
                                   [](const FrameSlot& slot) { return slot.inFlight && slot.differenceRead; });
  if (reading) return false;
  if (!v.difference.valid) return true;
  if (v.difference.spp == v.scheduler.sampleIndex) return false;
  // Scripts measure at every sample count they can (their output is deterministic); a person reads them at most
  // once a second.
  return v.automation || v.clock.seconds() - v.lastDifference >= kDifferenceSeconds;
}

void recordDifferenceReadback(VkCommandBuffer cmd, Viewer& v, FrameSlot& slot) {
  const glm::uvec2 extent(v.renderer.params.width, v.renderer.params.height);
  const VkDeviceSize side = VkDeviceSize(extent.x) * extent.y * sizeof(glm::vec4);
  if (slot.difference.size < 2 * side) {
    destroyBuffer(v.device, slot.difference);
    slot.difference = createBuffer(v.device, 2 * side, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kHost,
                                   "difference read-back");
  }
  computeBarrier(cmd);  // the trace passes' sums, before the copies read them
  const VkBufferCopy left{0, 0, side};
  const VkBufferCopy right{0, side, side};
  vkCmdCopyBuffer(cmd, v.renderer.accumulation.handle, slot.difference.handle, 1, &left);
  vkCmdCopyBuffer(cmd, v.comparison.renderer.accumulation.handle, slot.difference.handle, 1, &right);
  computeBarrier(cmd);  // the copies' writes, visible to the host
  slot.differenceRead = true;
  slot.differenceExtent = extent;
}

void readDifferenceStats(Viewer& v, FrameSlot& slot) {
  slot.differenceRead = false;
  if (!v.comparison.active) return;  // stopped while the frame was in flight
  const auto* sums = static_cast<const glm::vec4*>(slot.difference.mapped);
  const std::size_t pixels = std::size_t(slot.differenceExtent.x) * slot.differenceExtent.y;
  const auto mean = [](const glm::vec4& sum) { return sum.w > 0.0f ? sum / sum.w : glm::vec4(0.0f); };
  const bool relative = v.compareView.show == CompareShow::kRelativeDifference;
  double total = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const double d = pixelDifference(mean(sums[i]), mean(sums[pixels + i]), relative);
    total += d;
    largest = std::max(largest, d);
  }
  v.difference = {true, total / double(std::max<std::size_t>(1, pixels)), largest, slot.spp};
  v.lastDifference = v.clock.seconds();
  if (!v.options.quiet && v.automation) {
    std::printf("raylab view: difference %s mean %.9g max %.9g (%u spp)\n", relative ? "relative" : "absolute",
                v.difference.mean, v.difference.max, v.difference.spp);
  }
}

void drawComparisonSections(Viewer& v) {
  std::optional<std::uint32_t> compared;
  if (v.comparison.active) compared = v.comparison.spec.material;
  const CompareShow shownBefore = v.compareView.show;
  const CompareEdits edits =
      drawCompareSection(v.scene, v.selection.material, compared, v.comparedRecord, v.compareView, v.difference);
  if (shownBefore != v.compareView.show) v.difference = {};  // absolute and relative statistics differ
  if (edits.start) {
    CompareSpec spec;
    spec.material = static_cast<std::uint32_t>(v.selection.material);
    spec.record = v.scene.materials.at(spec.material).record;
    startComparing(v, spec);
  } else if (edits.stop) {
    stopComparing(v);
  } else if (edits.rightChanged) {
    v.comparison.spec.record = v.comparedRecord;
    refreshComparison(v);
  }
  drawPickSection(v.picked);
  if (ImGui::CollapsingHeader("Lobe", ImGuiTreeNodeFlags_DefaultOpen) && v.selection.material < v.scene.materials.size()) {
    const gpu::MaterialRecord& selected = v.scene.materials[v.selection.material].record;
    const bool rightToo = v.comparison.active && v.comparison.spec.material == v.selection.material;
    updateLobePlot(v.device, v.lobe, selected, rightToo ? &v.comparison.spec.record : nullptr);
    ImGui::PushID("lobe");
    drawLobePlot(v.lobe);
    ImGui::PopID();
  }
  if (v.slicePlot && ImGui::CollapsingHeader("Measured target", ImGuiTreeNodeFlags_DefaultOpen) &&
      v.selection.material < v.scene.materials.size()) {
    const bool rightToo = v.comparison.active && v.comparison.spec.material == v.selection.material;
    ImGui::PushID("target");
    drawSlicePlot(*v.slicePlot, v.scene.materials[v.selection.material].record,
                  rightToo ? &v.comparison.spec.record : nullptr);
    ImGui::PopID();
  }
}

void drawOverlay(Viewer& v) {
  const VkRect2D area = imageArea(v);
  OverlayText text;
  if (v.comparison.active) {
    text.left = leftLabel(v.scene, v.comparison);
    text.right = rightLabel(v.scene, v.comparison);
  }
  text.hover = v.hovered;
  drawCompareOverlay(glm::vec2(float(area.offset.x), float(area.offset.y)),
                     glm::vec2(float(area.extent.width), float(area.extent.height)), v.compareView, text, v.cursor);
}

void saveComparison(Viewer& v, const std::string& exrPath) {
  if (!v.comparison.active) return;
  const std::filesystem::path path(exrPath);
  const std::string stem = (path.parent_path() / path.stem()).string();
  const Image a = readImage(v.device, v.renderer);
  const Image b = readImage(v.device, v.comparison.renderer);
  Image difference(a.width, a.height);
  for (std::size_t i = 0; i < a.rgba.size(); ++i) difference.rgba[i] = (i % 4 == 3) ? 1.0f : std::abs(a.rgba[i] - b.rgba[i]);
  writeExr(stem + "_compare.exr", b);
  writeExr(stem + "_difference.exr", difference);
  if (!v.options.quiet) std::printf("wrote %s_compare.exr\nwrote %s_difference.exr\n", stem.c_str(), stem.c_str());
}

void saveLobe(Viewer& v, const std::string& path) {
  if (v.selection.material >= v.scene.materials.size()) throw Error("save lobe: the scene has no materials");
  const gpu::MaterialRecord& selected = v.scene.materials[v.selection.material].record;
  const bool rightToo = v.comparison.active && v.comparison.spec.material == v.selection.material;
  updateLobePlot(v.device, v.lobe, selected, rightToo ? &v.comparison.spec.record : nullptr);
  writeFileAtomically(path, lobeCsv(v.lobe));
  if (!v.options.quiet) std::printf("wrote %s\n", path.c_str());
}

void applyCompareEvent(Viewer& v, const ScriptEvent& event) {
  switch (event.action) {
    case ScriptAction::kCompare:
      if (event.name == "off") stopComparing(v);
      else startComparing(v, parseCompareSpec(event.name, v.scene, event.where));
      break;
    case ScriptAction::kSetDivider:
    case ScriptAction::kSetDifference:
      if (!v.comparison.active) throw Error(event.where + ": nothing is compared yet (a 'compare' event comes first)");
      if (event.action == ScriptAction::kSetDivider) {
        v.compareView.divider = event.value.x;
      } else {
        v.compareView.show = event.param == "relative" ? CompareShow::kRelativeDifference
                             : event.param == "absolute" ? CompareShow::kDifference
                                                         : CompareShow::kSplit;
        if (event.valueCount == 1) v.compareView.differenceScale = event.value.x;
        v.difference = {};
      }
      break;
    case ScriptAction::kPick: {
      const glm::uvec2 full = v.scheduler.fullExtent;
      if (event.value.x >= float(full.x) || event.value.y >= float(full.y)) {
        throw Error(event.where + ": pixel (" + std::to_string(int(event.value.x)) + ", " +
                    std::to_string(int(event.value.y)) + ") is outside the " + std::to_string(full.x) + "x" +
                    std::to_string(full.y) + " image");
      }
      pickAt(v, (glm::vec2(event.value) + 0.5f) / glm::vec2(full));
      break;
    }
    case ScriptAction::kSaveLobe:
      saveLobe(v, event.name);
      break;
    default:
      break;
  }
}

}  // namespace raylab
