// The split view's right side: a second renderer over the same GpuScene (geometry, acceleration structures,
// lights, environment) whose materials buffer has one material switched to another model and parameters. Both
// sides trace the same passes with the same camera, seed and sample indices, so they differ only where the
// switched material is seen (directly, in reflections, or in the light it bounces).
#pragma once

#include <string>
#include <vector>

#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "view_logic/compare_spec.h"

namespace raylab {

struct Comparison {
  bool active = false;
  CompareSpec spec;
  Buffer materials;   // the scene's materials with spec applied, bound over the scene's in renderer's set
  Buffer brdfTables;  // the BRDF tables with the measured files those materials use, bound likewise
  std::vector<std::uint32_t> measuredFiles;
  Renderer renderer;  // the right side
};

// The scene's materials with `spec` applied: what the right side renders.
std::vector<Material> comparedMaterials(const Scene& scene, const CompareSpec& spec);
// `scene` with `spec` applied (`raylab render --material`, the tests' reference).
Scene withMaterial(const Scene& scene, const CompareSpec& spec);

// Starts (or restarts with another spec) the right side: a renderer of `settings` (the left side's size, seed,
// depth, backend and schedule) specialised for the compared scene with `integrator`. Creating its pipeline
// takes a fraction of a second on lavapipe; its first dispatch compiles it.
void startComparison(const Device& device, const GpuScene& gpuScene, const Scene& scene, RenderSettings settings,
                     std::uint32_t integrator, const CompareSpec& spec, Comparison& comparison);
void stopComparison(const Device& device, Comparison& comparison);

// After an edit of the scene's materials or of the integrator (the device idle): uploads the right side's
// materials and, when they or the integrator need models its kernel lacks, replaces its pipelines (synchronously:
// the right side is a tool for a few materials, not for hot-swapping large scenes).
void updateComparison(const Device& device, const Scene& scene, std::uint32_t integrator, Comparison& comparison);

// "A: phong rho_d=0.7/0.1/0.1 rho_s=0.3 s=60" and "B: ward ...": the labels over the two sides.
std::string leftLabel(const Scene& scene, const Comparison& comparison);
std::string rightLabel(const Scene& scene, const Comparison& comparison);

}  // namespace raylab
