#include "view/lobe_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "brdf_params/material_params.h"
#include "view/plot_style.h"
#include "image/image.h"

namespace raylab {

namespace {

constexpr float kPi = 3.14159265f;
constexpr ImU32 kLightColour = IM_COL32(255, 240, 120, 255);

bool sameMaterial(const gpu::MaterialRecord& a, const gpu::MaterialRecord& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}


LobeCurves evaluate(const Device& device, BrdfEvaluator& evaluator, const gpu::MaterialRecord& material, float theta,
                    const LobeCurves* previous) {
  LobeCurves curves;
  curves.material = material;
  curves.cases = lobeCases(material, theta);
  curves.values = evaluateBrdfCases(device, evaluator, curves.cases);
  curves.fcos = lobeValues(curves.cases, curves.values);
  // The albedo does not depend on the incident angle slider: keep it while only the angle moves.
  curves.albedo = previous != nullptr && sameMaterial(previous->material, material) ? previous->albedo
                                                                                   : albedoCurve(material);
  return curves;
}

void update(const Device& device, LobePlot& plot, std::optional<LobeCurves>& curves, const gpu::MaterialRecord* material,
            bool angleChanged) {
  if (material == nullptr) {
    curves.reset();
    return;
  }
  if (curves && !angleChanged && sameMaterial(curves->material, *material)) return;
  LobeCurves next = evaluate(device, *plot.evaluator, *material, plot.thetaIDegrees, curves ? &*curves : nullptr);
  curves = std::move(next);
}

float largest(const std::optional<LobeCurves>& curves) {
  float value = 0.0f;
  if (curves) {
    for (glm::vec3 v : curves->fcos) value = std::max(value, luminance(v));
  }
  return value;
}

bool twoSided(const std::optional<LobeCurves>& curves) { return curves && lobeIsTwoSided(curves->material); }

// The polar plot: the surface along the bottom (the middle for a two-sided model, whose lower half is inside),
// the normal up, theta_o measured from it; radius f |cos| / scale.
void drawPolar(const LobePlot& plot, ImVec2 size, bool wholePlane) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##lobe", size);
  const ImVec2 centre(corner.x + size.x * 0.5f, wholePlane ? corner.y + size.y * 0.5f + 6.0f : corner.y + size.y - 4.0f);
  const float radius = std::min(size.x * 0.5f, wholePlane ? size.y * 0.5f - 6.0f : size.y) - 6.0f;
  for (int ring = 1; ring <= 4; ++ring) {
    draw->PathArcTo(centre, radius * float(ring) / 4.0f, wholePlane ? 0.0f : kPi, 2.0f * kPi, wholePlane ? 64 : 32);
    draw->PathStroke(kPlotGridColour, 0, 1.0f);
  }
  draw->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y), kPlotGridColour);
  draw->AddLine(centre, ImVec2(centre.x, centre.y - radius), kPlotGridColour);
  const float theta = glm::radians(plot.thetaIDegrees);
  draw->AddLine(centre, ImVec2(centre.x - radius * std::sin(theta), centre.y - radius * std::cos(theta)), kLightColour,
                2.0f);
  const float scale = std::max(largest(plot.left), largest(plot.right));
  if (!(scale > 0.0f) || !std::isfinite(scale)) return;
  const auto curve = [&](const LobeCurves& curves, ImU32 colour) {
    const bool curveTwoSided = lobeIsTwoSided(curves.material);
    for (std::uint32_t i = 0; i < curves.fcos.size(); ++i) {
      const float angle = glm::radians(lobeAngleDegrees(i, curveTwoSided));
      const float r = radius * std::min(luminance(curves.fcos[i]) / scale, 1.0f);
      draw->PathLineTo(ImVec2(centre.x + r * std::sin(angle), centre.y - r * std::cos(angle)));
    }
    draw->PathStroke(colour, curveTwoSided ? ImDrawFlags_Closed : 0, 2.0f);
  };
  if (plot.left) curve(*plot.left, kPlotLeftColour);
  if (plot.right) curve(*plot.right, kPlotRightColour);
  char text[64];
  std::snprintf(text, sizeof text, "outer ring: f |cos| = %.3g /sr", double(scale));
  draw->AddText(ImVec2(corner.x, corner.y), IM_COL32(200, 200, 200, 255), text);
}

float largestAlbedo(const std::optional<LobeCurves>& curves) {
  float value = 0.0f;
  if (curves) {
    for (glm::vec3 a : curves->albedo.albedo) value = std::max(value, luminance(a));
  }
  return value;
}

// The albedo against angle, 0 to 90 degrees across, 0 to 1 up (or to the largest value: models that are not
// energy-conserving, such as the slides' Cook-Torrance at grazing angles, go above 1).
void drawAlbedo(const LobePlot& plot, ImVec2 size) {
  const float top = std::max({1.0f, largestAlbedo(plot.left), largestAlbedo(plot.right)});
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##albedo", size);
  const ImVec2 lo(corner.x + 4.0f, corner.y + size.y - 4.0f);
  const ImVec2 extent(size.x - 8.0f, size.y - 16.0f);
  for (int line = 0; line <= 4; ++line) {
    const float y = lo.y - extent.y * float(line) / 4.0f;
    draw->AddLine(ImVec2(lo.x, y), ImVec2(lo.x + extent.x, y), kPlotGridColour);
  }
  const auto curve = [&](const LobeCurves& curves, ImU32 colour) {
    for (std::size_t i = 0; i < curves.albedo.thetaDegrees.size(); ++i) {
      const float a = std::clamp(luminance(curves.albedo.albedo[i]) / top, 0.0f, 1.0f);
      draw->PathLineTo(ImVec2(lo.x + extent.x * curves.albedo.thetaDegrees[i] / 90.0f, lo.y - extent.y * a));
    }
    draw->PathStroke(colour, 0, 2.0f);
  };
  if (plot.left) curve(*plot.left, kPlotLeftColour);
  if (plot.right) curve(*plot.right, kPlotRightColour);
  char text[80];
  std::snprintf(text, sizeof text, "albedo (0..%.3g) against theta 0..90 deg", double(top));
  draw->AddText(ImVec2(corner.x, corner.y), IM_COL32(200, 200, 200, 255), text);
}

}  // namespace

void destroyLobePlot(const Device& device, LobePlot& plot) {
  if (plot.evaluator) destroyBrdfEvaluator(device, *plot.evaluator);
  plot = {};
}

void updateLobePlot(const Device& device, LobePlot& plot, const gpu::MaterialRecord& material,
                    const gpu::MaterialRecord* compared) {
  if (!plot.evaluator) plot.evaluator = createBrdfEvaluator(device, std::max(kLobeSamples, kLobeSamplesTwoSided));
  const bool angleChanged = plot.plottedTheta != plot.thetaIDegrees;
  update(device, plot, plot.left, &material, angleChanged);
  update(device, plot, plot.right, compared, angleChanged);
  plot.plottedTheta = plot.thetaIDegrees;
}

bool drawLobePlot(LobePlot& plot) {
  const bool changed =
      ImGui::SliderFloat("theta_i", &plot.thetaIDegrees, 0.0f, 89.0f, "%.0f deg", ImGuiSliderFlags_AlwaysClamp);
  if (plot.left && isDeltaOnly(plot.left->material.model)) {
    ImGui::TextWrapped("%s is a delta BSDF (a mirror and a refraction direction): it has no lobe to plot",
                       std::string(modelInfo(plot.left->material.model).name).c_str());
    return changed;
  }
  const float width = ImGui::GetContentRegionAvail().x;
  const bool wholePlane = twoSided(plot.left) || twoSided(plot.right);
  drawPolar(plot, ImVec2(width, width * (wholePlane ? 1.0f : 0.55f)), wholePlane);
  drawAlbedo(plot, ImVec2(width, width * 0.4f));
  ImGui::TextColored(kPlotLeftText, "A");
  if (plot.right) {
    ImGui::SameLine();
    ImGui::TextColored(kPlotRightText, "B (compared)");
  }
  ImGui::SameLine();
  ImGui::TextDisabled(wholePlane ? "luminance of f |cos theta_o|; light from the left; below the line: inside"
                                 : "luminance of f_r cos theta_o; light from the left");
  return changed;
}

std::string lobeCsv(const LobePlot& plot) {
  if (!plot.left) return "";
  return formatLobeCsv(plot.left->material, plot.plottedTheta, plot.left->cases, plot.left->values, plot.left->albedo);
}

}  // namespace raylab
