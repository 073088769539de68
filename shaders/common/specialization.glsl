// The specialization constants every kernel shares (shared/features.h). Unspecialised kernels (the BRDF
// evaluator) keep the defaults: every model and feature compiled in.
#ifndef RAYLAB_COMMON_SPECIALIZATION_GLSL
#define RAYLAB_COMMON_SPECIALIZATION_GLSL

#include "shared/features.h"

layout(constant_id = kSpecEnabledModels) const uint kEnabledModels = kAllModels;
layout(constant_id = kSpecFeatures) const uint kFeatures = kAllFeatures;
layout(constant_id = kSpecGlassFresnel) const uint kGlassFresnel = kFresnelExact;
layout(constant_id = kSpecIntegrator) const uint kIntegrator = kIntegratorSlides;
layout(constant_id = kSpecSampling) const uint kSampling = kSamplingMis;
layout(constant_id = kSpecLightKinds) const uint kLightKinds = kAllLightKinds;

// After specialization these fold to constants and the driver removes the code they guard.
bool modelEnabled(uint model) { return (kEnabledModels & (1u << model)) != 0u; }
bool featureEnabled(uint feature) { return (kFeatures & feature) != 0u; }
bool lightKindEnabled(uint kind) { return (kLightKinds & (1u << kind)) != 0u; }

#endif
