// The panel's measured target (`raylab view --target FILE`): a MERL phi_d = 90 slice, or the same plane of a MERL
// .binary file, drawn as BRDF Explorer's slice view does, one theta_d row at a time: the measured f against theta_h
// (points, log scale) with the selected material's f at the same pairs (the double-precision reference), and the
// compared model's when it is the compared material. The plane of incidence of the lobe plot meets a slice only at
// the mirror direction, so a measurement is shown in its own plane.
#pragma once

#include <string>

#include "fit/merl_slice.h"
#include "shared/scene_records.h"

namespace raylab {

struct SlicePlot {
  std::string name;  // the file, as given
  MerlSlice target;
  float thetaDDegrees = 30.0f;  // the row shown (the panel's slider)
};

// The plot of a .slice file, or of a MERL .binary file's phi_d = 90 plane at the slice's bin centres. Throws Error
// naming the file (exit code 2 for a bad slice, as `raylab brdf fit`).
SlicePlot loadSlicePlot(const std::string& path);

// f of `material` at every bin of row `row` (RGB, 1/sr).
std::vector<glm::dvec3> sliceRowOf(const gpu::MaterialRecord& material, int row);

// Draws the plot into the current ImGui window (with its theta_d slider).
void drawSlicePlot(SlicePlot& plot, const gpu::MaterialRecord& material, const gpu::MaterialRecord* compared);

}  // namespace raylab
