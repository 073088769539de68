#include "view/slice_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "brdf_params/material_params.h"
#include "measured/merl.h"
#include "reference/brdf_reference.h"
#include "util/error.h"
#include "view/plot_style.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr ImU32 kTargetColour = IM_COL32(235, 235, 235, 255);

double rowLuminance(const glm::dvec3& f) { return 0.2126 * f.x + 0.7152 * f.y + 0.0722 * f.z; }

}  // namespace

SlicePlot loadSlicePlot(const std::string& path) {
  SlicePlot plot;
  plot.name = path;
  if (std::filesystem::path(path).extension() == ".binary") {
    const MerlTable table = readMerl(path);
    plot.target.values.resize(kSliceBytes / sizeof(float));
    for (int d = 0; d < kSliceThetaD; ++d) {
      for (int h = 0; h < kSliceThetaH; ++h) {
        glm::dvec3 wi, wo;
        merlDirections(sliceThetaH(h, SliceBin::kCentre), sliceThetaD(d, SliceBin::kCentre), 0.5 * kPi, &wi, &wo);
        const glm::dvec3 f = merlLookup(table, wi, wo);
        for (int c = 0; c < 3; ++c) plot.target.values[(std::size_t(d) * kSliceThetaH + h) * 3 + c] = float(f[c]);
      }
    }
  } else if (std::filesystem::path(path).extension() == ".slice") {
    plot.target = readMerlSlice(path);
  } else {
    throw Error(path + ": a target is a MERL .slice or .binary file", kExitUsage);
  }
  return plot;
}

std::vector<glm::dvec3> sliceRowOf(const gpu::MaterialRecord& material, int row) {
  const reference::Material m = reference::fromRecord(material);
  std::vector<glm::dvec3> f(kSliceThetaH);
  for (int h = 0; h < kSliceThetaH; ++h) {
    glm::dvec3 wi, wo;
    merlDirections(sliceThetaH(h, SliceBin::kCentre), sliceThetaD(row, SliceBin::kCentre), 0.5 * kPi, &wi, &wo);
    f[std::size_t(h)] = reference::eval(m, wi, wo);
  }
  return f;
}

void drawSlicePlot(SlicePlot& plot, const gpu::MaterialRecord& material, const gpu::MaterialRecord* compared) {
  ImGui::SliderFloat("theta_d", &plot.thetaDDegrees, 0.0f, 89.0f, "%.0f deg", ImGuiSliderFlags_AlwaysClamp);
  const int row = std::clamp(int(plot.thetaDDegrees), 0, kSliceThetaD - 1);
  std::vector<double> target(kSliceThetaH);
  for (int h = 0; h < kSliceThetaH; ++h) target[std::size_t(h)] = rowLuminance(plot.target.at(h, row));
  std::vector<std::vector<double>> curves;
  std::vector<ImU32> colours;
  for (const gpu::MaterialRecord* m : {&material, compared}) {
    if (m == nullptr || isDeltaOnly(m->model)) continue;
    std::vector<double> values;
    for (const glm::dvec3& f : sliceRowOf(*m, row)) values.push_back(rowLuminance(f));
    curves.push_back(values);
    colours.push_back(m == &material ? kPlotLeftColour : kPlotRightColour);
  }
  // Decades shown: from the largest value down to 1e-4 of it, or the smallest measured value above 0.
  double top = 0.0, bottom = INFINITY;
  for (double v : target) {
    top = std::max(top, v);
    if (v > 0.0) bottom = std::min(bottom, v);
  }
  for (const auto& c : curves) {
    for (double v : c) top = std::max(top, std::isfinite(v) ? v : 0.0);
  }
  if (!(top > 0.0)) {
    ImGui::TextDisabled("the target's row at theta_d = %d deg is zero", row);
    return;
  }
  bottom = std::clamp(bottom, top * 1e-5, top * 1e-1);
  const double lo = std::log10(bottom), hi = std::log10(top);
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 size(width, width * 0.55f);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##slice", size);
  const ImVec2 origin(corner.x + 4.0f, corner.y + size.y - 4.0f);
  const ImVec2 extent(size.x - 8.0f, size.y - 18.0f);
  for (double decade = std::ceil(lo); decade <= hi; decade += 1.0) {
    const float y = origin.y - extent.y * float((decade - lo) / (hi - lo));
    draw->AddLine(ImVec2(origin.x, y), ImVec2(origin.x + extent.x, y), kPlotGridColour);
  }
  // x: the slice's own square-root theta_h axis, bin by bin, as the file stores it.
  const auto point = [&](int h, double v) {
    const double t = std::clamp((std::log10(std::max(v, bottom)) - lo) / (hi - lo), 0.0, 1.0);
    return ImVec2(origin.x + extent.x * (float(h) + 0.5f) / kSliceThetaH, origin.y - extent.y * float(t));
  };
  for (std::size_t c = 0; c < curves.size(); ++c) {
    for (int h = 0; h < kSliceThetaH; ++h) draw->PathLineTo(point(h, curves[c][std::size_t(h)]));
    draw->PathStroke(colours[c], 0, 2.0f);
  }
  for (int h = 0; h < kSliceThetaH; ++h) draw->AddCircleFilled(point(h, target[std::size_t(h)]), 1.8f, kTargetColour);
  char text[160];
  std::snprintf(text, sizeof text, "log f %.2g..%.3g /sr; theta_h 0..90 (sqrt)", bottom, top);
  draw->AddText(ImVec2(corner.x, corner.y), IM_COL32(200, 200, 200, 255), text);
  ImGui::TextColored(ImVec4(0.92f, 0.92f, 0.92f, 1.0f), "measured");
  ImGui::SameLine();
  ImGui::TextColored(kPlotLeftText, "A");
  if (compared != nullptr) {
    ImGui::SameLine();
    ImGui::TextColored(kPlotRightText, "B (compared)");
  }
  ImGui::SameLine();
  ImGui::TextDisabled("%s, phi_d = 90 deg", std::filesystem::path(plot.name).filename().c_str());
}

}  // namespace raylab
