// Lobe flags of a BSDF, as pbrt-v4's BxDFFlags: each model declares its own (the `lobes:` line its GLSL file
// opens with) and integrators ask these, never model ids.
#ifndef RAYLAB_SHARED_BRDF_LOBES_H
#define RAYLAB_SHARED_BRDF_LOBES_H

#include "compat.h"

RL_NAMESPACE_BEGIN

RL_CONST uint kLobeReflection = 1;
RL_CONST uint kLobeTransmission = 2;
RL_CONST uint kLobeDiffuse = 4;
RL_CONST uint kLobeGlossy = 8;
RL_CONST uint kLobeSpecular = 16;  // a delta lobe: no density, only the model's DeltaEvent produces its directions

RL_NAMESPACE_END

#endif
