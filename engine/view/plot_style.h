// The colours the panel's plots share (lobe_plot, slice_plot): side A, the compared side B, grid lines.
#pragma once

#include <imgui.h>

namespace raylab {

inline constexpr ImU32 kPlotLeftColour = IM_COL32(255, 170, 60, 255);
inline constexpr ImU32 kPlotRightColour = IM_COL32(90, 200, 255, 255);
inline constexpr ImU32 kPlotGridColour = IM_COL32(110, 110, 110, 160);
inline const ImVec4 kPlotLeftText(1.0f, 0.67f, 0.24f, 1.0f);
inline const ImVec4 kPlotRightText(0.35f, 0.78f, 1.0f, 1.0f);

}  // namespace raylab
