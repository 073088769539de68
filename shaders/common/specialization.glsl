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

// Macros, not functions: with a literal argument each is a specialization-constant expression, so the host folds
// it and drops the code it guards before the driver sees the kernel (engine/vk/spirv_specialization.h). A
// function call would stay a call until inlined, and the driver would translate every model of the library
// before removing the unused ones.
#define modelEnabled(model) ((kEnabledModels & (1u << (model))) != 0u)
#define featureEnabled(feature) ((kFeatures & (feature)) != 0u)
#define lightKindEnabled(kind) ((kLightKinds & (1u << (kind))) != 0u)

#endif
