// Which BRDF models and kernel features a scene needs: the specialization constants of its render kernel.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace raylab {

struct KernelFeatures {
  std::uint32_t models = 0;    // bit (1 << gpu::kModel...) per model compiled in
  std::uint32_t features = 0;  // gpu::kFeature... bits
  std::uint32_t lightKinds = 0;  // bit (1 << gpu::kLight...) per kind of light compiled in
  bool schlickFresnel = false; // glass uses Schlick's approximation instead of the exact Fresnel term
  std::uint32_t integrator = 0;  // gpu::kIntegrator...; each integrator is its own kernel
  std::uint32_t sampling = 0;    // gpu::kSampling...: MIS, or BSDF or light sampling alone (path integrator)

  bool operator==(const KernelFeatures&) const = default;
};

// Exactly what `scene` uses: unused models, glass, the mirror loop, absent light types and textures compile away;
// the integrator is the one `auto` picks (chooseIntegrator).
KernelFeatures featuresOf(const Scene& scene);

enum class IntegratorChoice { kAuto, kSlides, kPath };

// The integrator a render runs: `auto` takes the path tracer when the scene has an emissive surface or an
// environment image (the slides' equation cannot show either lighting anything), the slides' integrator
// otherwise.
std::uint32_t chooseIntegrator(const Scene& scene, IntegratorChoice choice);
// "slides" or "path" (the option's value naming it).
std::string_view integratorName(std::uint32_t integrator);

// Everything compiled in (the unspecialised kernel, for comparisons and for the viewer's model switching).
KernelFeatures allFeatures();

// What `raylab render` (and the Python Renderer) asks of the kernel beyond the scene.
struct KernelOptions {
  IntegratorChoice integrator = IntegratorChoice::kAuto;
  std::uint32_t sampling = 0;  // gpu::kSampling...
  bool schlickFresnel = false;
  bool allFeatures = false;    // every model and feature, not only the scene's
};
// The kernel a render of `scene` with these options runs.
KernelFeatures kernelFor(const Scene& scene, const KernelOptions& options);

// "models: lambert, phong; features: mirror, point lights"
std::string describe(const KernelFeatures& features);

}  // namespace raylab
