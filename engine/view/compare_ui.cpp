#include "view/compare_ui.h"

#include <imgui.h>

#include <cstdio>

#include "view/material_editor.h"

namespace raylab {

namespace {

// The display pass's ramp (shaders/display.comp falseColour), for the colour bar.
constexpr ImU32 kRamp[5] = {IM_COL32(13, 8, 51, 255), IM_COL32(26, 77, 217, 255), IM_COL32(26, 191, 89, 255),
                            IM_COL32(242, 217, 26, 255), IM_COL32(255, 255, 255, 255)};

// `text` broken at spaces into lines no wider than `width` pixels (a word wider than that gets a line of its own).
std::string wrapped(const std::string& text, float width) {
  std::string result, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && ImGui::CalcTextSize(longer.c_str()).x > width) {
      result += (result.empty() ? "" : "\n") + line;
      line = word;
    } else {
      line = longer;
    }
    start = end + 1;
  }
  if (!line.empty()) result += (result.empty() ? "" : "\n") + line;
  return result;
}

// A label on a dark box; `alignRight`: `at` is its top-right corner.
ImVec2 label(ImDrawList* draw, ImVec2 at, const std::string& text, bool alignRight = false) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  if (alignRight) at.x -= size.x;
  draw->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2), IM_COL32(0, 0, 0, 170),
                      3.0f);
  draw->AddText(at, IM_COL32(255, 255, 255, 255), text.c_str());
  return size;
}

}  // namespace

CompareEdits drawCompareSection(const Scene& scene, std::size_t selectedMaterial, std::optional<std::uint32_t> compared,
                                gpu::MaterialRecord& right, CompareView& view, const DifferenceStats& stats) {
  CompareEdits edits;
  if (!ImGui::CollapsingHeader("Compare", ImGuiTreeNodeFlags_DefaultOpen)) return edits;
  ImGui::PushID("compare");
  if (!compared) {
    ImGui::TextWrapped("Split the view: the right side renders the selected material with another model.");
    if (selectedMaterial < scene.materials.size()) {
      const std::string button = "compare '" + scene.materials[selectedMaterial].name + "'";
      edits.start = ImGui::Button(button.c_str());
    }
    ImGui::PopID();
    return edits;
  }
  ImGui::Text("B: '%s' as", scene.materials[*compared].name.c_str());
  edits.rightChanged = drawMaterialEditor(right);
  int show = static_cast<int>(view.show);
  ImGui::RadioButton("split", &show, 0);
  ImGui::SameLine();
  ImGui::RadioButton("|A-B|", &show, 1);
  ImGui::SameLine();
  ImGui::RadioButton("relative", &show, 2);
  view.show = static_cast<CompareShow>(show);
  if (view.show == CompareShow::kSplit) {
    ImGui::SliderFloat("divider", &view.divider, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
  } else {
    ImGui::SliderFloat("scale", &view.differenceScale, 1e-4f, 10.0f, "%.3g",
                       ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
  }
  if (stats.valid) {
    ImGui::Text("mean %.4g  max %.4g  (%u spp)", stats.mean, stats.max, stats.spp);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("|A - B| per pixel, the largest channel%s, over the whole image",
                        view.show == CompareShow::kRelativeDifference ? ", over max(A, B)" : "");
    }
  }
  edits.stop = ImGui::Button("stop comparing");
  ImGui::PopID();
  return edits;
}

void drawPickSection(const std::optional<PickedPixel>& picked) {
  if (!picked || !ImGui::CollapsingHeader("Picked pixel", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Text("(%u, %u): %s", picked->pixel.x, picked->pixel.y, picked->material.c_str());
  const auto row = [](const char* side, const PixelValue& value) {
    ImGui::Text("%s %.4g %.4g %.4g  (%u spp)", side, double(value.radiance.r), double(value.radiance.g),
                double(value.radiance.b), value.samples);
  };
  row("A", picked->left);
  if (picked->right) row("B", *picked->right);
}

void drawCompareOverlay(glm::vec2 imageOrigin, glm::vec2 imageSize, const CompareView& view, const OverlayText& text,
                        glm::vec2 cursor) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 lo(imageOrigin.x, imageOrigin.y);
  const ImVec2 hi(imageOrigin.x + imageSize.x, imageOrigin.y + imageSize.y);
  if (!text.left.empty()) {
    // Each label in the top corner of its side, wrapped to under half the image's width.
    const float width = std::max(imageSize.x * 0.5f - 18.0f, 120.0f);
    const std::string left = wrapped(text.left, width), right = wrapped(text.right, width);
    label(draw, ImVec2(lo.x + 6, lo.y + 6), left);
    label(draw, ImVec2(hi.x - 6, lo.y + 6), right, true);
    if (view.show == CompareShow::kSplit) {
      const float x = lo.x + view.divider * imageSize.x;
      draw->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), IM_COL32(255, 255, 255, 220), 2.0f);
      draw->AddCircleFilled(ImVec2(x, lo.y + imageSize.y * 0.5f), 5.0f, IM_COL32(255, 255, 255, 220));
    } else {
      // The colour bar along the bottom: 0 at the left, the scale at the right.
      const float barWidth = std::min(imageSize.x * 0.5f, 240.0f);
      const ImVec2 barLo(lo.x + 10, hi.y - 30);
      for (int i = 0; i < 4; ++i) {
        const float x0 = barLo.x + barWidth * float(i) / 4.0f, x1 = barLo.x + barWidth * float(i + 1) / 4.0f;
        draw->AddRectFilledMultiColor(ImVec2(x0, barLo.y), ImVec2(x1, barLo.y + 10), kRamp[i], kRamp[i + 1],
                                      kRamp[i + 1], kRamp[i]);
      }
      char scale[96];
      std::snprintf(scale, sizeof scale, "0 .. %.3g  %s", double(view.differenceScale),
                    view.show == CompareShow::kRelativeDifference ? "|A-B| / max(A,B)" : "|A-B|");
      label(draw, ImVec2(barLo.x, barLo.y + 12), scale);
    }
  }
  if (!text.hover.empty()) label(draw, ImVec2(cursor.x + 14, cursor.y + 4), text.hover);
}

}  // namespace raylab
