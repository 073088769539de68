// Which BRDF models and kernel features a scene needs: the specialization constants of its render kernel.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace raylab {

struct KernelFeatures {
  std::uint32_t models = 0;    // bit (1 << gpu::kModel...) per model compiled in
  std::uint32_t features = 0;  // gpu::kFeature... bits
  bool schlickFresnel = false; // glass uses Schlick's approximation instead of the exact Fresnel term

  bool operator==(const KernelFeatures&) const = default;
};

// Exactly what `scene` uses: unused models, glass, the mirror loop, absent light types and textures compile away.
KernelFeatures featuresOf(const Scene& scene);

// Everything compiled in (the unspecialised kernel, for comparisons and for the viewer's model switching).
KernelFeatures allFeatures();

// "models: lambert, phong; features: mirror, point lights"
std::string describe(const KernelFeatures& features);

}  // namespace raylab
