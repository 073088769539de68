#version 460
// The shadow rays' miss program (the ray-tracing-pipeline backend): nothing blocked the ray. Shadow rays skip
// every closest-hit program and stop at their first hit, so reaching here is the only way to be visible.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "shared/ray_tracing.h"

layout(location = kPayloadShadow) rayPayloadInEXT uint shadowVisible;

void main() { shadowVisible = 1u; }
