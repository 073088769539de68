// The panel's lobe plot (brdf_eval/lobe.h): the selected material's f_r cos theta_o in its plane of incidence,
// evaluated by the BRDF library on the device (brdf_eval.comp, the kernel of `raylab brdf eval`), and its
// directional albedo against angle from the double-precision reference. With a comparison of that material the
// right side's model is drawn over it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "brdf_eval/device_evaluator.h"
#include "brdf_eval/lobe.h"

namespace raylab {

struct LobeCurves {
  gpu::MaterialRecord material{};
  std::vector<gpu::BrdfEvalCase> cases;
  std::vector<gpu::BrdfEvalValue> values;
  std::vector<glm::vec3> fcos;
  AlbedoCurve albedo;
};

struct LobePlot {
  float thetaIDegrees = 30.0f;   // the incident angle (the panel's slider)
  std::optional<BrdfEvaluator> evaluator;  // made at the first plot
  float plottedTheta = -1.0f;
  std::optional<LobeCurves> left;   // the selected material
  std::optional<LobeCurves> right;  // the compared model of it, when it is the compared material
};

void destroyLobePlot(const Device& device, LobePlot& plot);

// Re-evaluates what changed since the last call (material, compared material or angle). Submits to the device
// queue and waits: call it between frames, not while the host writes what frames read.
void updateLobePlot(const Device& device, LobePlot& plot, const gpu::MaterialRecord& material,
                    const gpu::MaterialRecord* compared);

// Draws the plot into the current ImGui window (with its angle slider). True when the angle changed.
bool drawLobePlot(LobePlot& plot);

// The left curve as CSV (brdf_eval/lobe.h): `save lobe FILE.csv`.
std::string lobeCsv(const LobePlot& plot);

}  // namespace raylab
