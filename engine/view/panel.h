// The viewer's ImGui panel: status line, render settings (integrator included), the environment, the materials
// (model and parameters, driven by the
// parameter table of brdf_params/material_params.h) and the lights. It edits plain values and reports what changed;
// the viewer uploads and resets.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "image/image.h"
#include "scene/scene.h"
#include "util/render_options.h"

namespace raylab {

// What the panel edits besides the scene.
struct ViewSettings {
  std::uint32_t integrator = 0;  // gpu::kIntegrator...
  std::uint32_t maxDepth = kMaxDepthOption.defaultValue;
  float exposure = 0.0f;
  ToneMap toneMap = ToneMap::kClamp;
  float resolutionScale = 1.0f;  // full render size over window size
  float targetMs = 50.0f;
  bool denoise = false;  // the still image shown denoised (viewer_denoise.cpp)
};

struct PanelStatus {
  std::uint32_t spp = 0;
  glm::uvec2 traceExtent{0};
  bool preview = false;
  double frameMs = 0.0;
  double raysPerSecond = 0.0;
  bool compiling = false;
  std::string device;   // "ray queries on llvmpipe (...)": the backend and the device it traces on
  std::string message;  // last screenshot, kernel error, ...
  std::string denoise;  // whether the image shown is denoised, and at how many samples; empty when switched off
};

// Which material and light the panel's editors show.
struct PanelSelection {
  std::size_t material = 0;
  std::size_t light = 0;
};

struct PanelEdits {
  bool materials = false;
  bool lights = false;
  bool maxDepth = false;
  bool integrator = false;
  bool environment = false;  // strength, rotation or the uniform background
  bool resolutionScale = false;
  bool resetView = false;
  bool screenshot = false;
  bool denoise = false;  // the denoise switch was clicked: settings.denoise holds the wish
};

// Builds the panel for this ImGui frame: lists of the materials and lights, and editors for the selected
// ones. `sceneSize` (the scene's diagonal) sets how fast lights drag.
// The panel is a strip of this width on the window's left, the full height, beside the image (never over it).
inline constexpr std::uint32_t kPanelWidth = 320;

// Draws the panel in the strip [0, kPanelWidth) x [0, height); it scrolls when taller than the window.
// `materialSections` adds sections after the materials' (the comparison, the picked pixel, the lobe plot).
PanelEdits drawPanel(Scene& scene, ViewSettings& settings, PanelSelection& selection, const PanelStatus& status,
                     float sceneSize, float height, const std::function<void()>& materialSections = {});

// "12 spp  640x360  48.2 ms/frame  3.1 Mrays/s" (also printed by automation runs).
std::string statusLine(const PanelStatus& status);

}  // namespace raylab
