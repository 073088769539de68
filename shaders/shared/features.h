// Kernel variants: specialization constants say which BRDF models and features a scene uses, so that the
// driver compiles everything else away (a Lambert-only scene gets a Lambert-only kernel).
#ifndef RAYLAB_SHARED_FEATURES_H
#define RAYLAB_SHARED_FEATURES_H

#include "compat.h"

RL_NAMESPACE_BEGIN

// Specialization constant ids.
RL_CONST uint kSpecEnabledModels = 0;  // bit (1 << kModel...) per model compiled in
RL_CONST uint kSpecFeatures = 1;       // kFeature... bits
RL_CONST uint kSpecGlassFresnel = 2;   // kFresnel...: which Fresnel term glass uses
RL_CONST uint kSpecIntegrator = 3;     // kIntegrator...: which estimator the raygen runs
RL_CONST uint kSpecSampling = 4;       // kSampling...: how the path integrator estimates emitted light
RL_CONST uint kSpecLightKinds = 5;     // bit (1 << kLight...) per kind of light compiled in (generated/light_kinds.h)

// kSpecFeatures bits.
RL_CONST uint kFeatureDeltaBsdf = 1;         // delta BSDFs (glass): reflection and refraction along delta lobes
RL_CONST uint kFeatureMirror = 2;            // some delta > 0: the mirror-reflection loop
RL_CONST uint kFeatureTextures = 32;         // material textures
RL_CONST uint kFeatureAlpha = 128;           // alpha-tested or stochastically transparent surfaces (non-opaque geometry)
RL_CONST uint kFeatureEnvironment = 64;      // an environment image (else the background is uniform)
RL_CONST uint kFeatureLayerTextures = 256;   // textures of glTF's layered extensions (MaterialTextures.layerModel)
RL_CONST uint kFeatureAovs = 512;            // first-hit albedo and normal images for the denoiser (kernel/aov.glsl)
RL_CONST uint kFeatureGuiding = 1024;        // path guiding in the path integrator (kernel/guiding.glsl)
// Bits 16-31: the models' own features (a model's `feature:` lines, numbered by the registry in
// generated/bsdf_models.glsl and ModelInfo::features), such as openpbr's coat.
RL_CONST uint kFirstModelFeatureBit = 16;

// kSpecGlassFresnel values. Exact is the contract's; Schlick trades accuracy for speed (docs/performance.md).
RL_CONST uint kFresnelExact = 0;
RL_CONST uint kFresnelSchlick = 1;

// kSpecIntegrator values (docs/integrators.md).
RL_CONST uint kIntegratorSlides = 0;  // equation 2 of the slides: delta-weighted mirror plus direct light
RL_CONST uint kIntegratorPath = 1;    // the rendering equation: a path tracer

// kSpecSampling values: multiple importance sampling of lights by light and BSDF sampling (the default), or
// one strategy alone, for studies. All three converge to the same image. A delta light is always light-sampled.
RL_CONST uint kSamplingMis = 0;
RL_CONST uint kSamplingBsdf = 1;
RL_CONST uint kSamplingLight = 2;

RL_CONST uint kAllModels = 0xFFFFFFFFu;
RL_CONST uint kAllFeatures = 0xFFFFFFFFu;
RL_CONST uint kAllLightKinds = 0xFFFFFFFFu;

RL_NAMESPACE_END

#endif
