#version 460
// The render kernel's miss program (the ray-tracing-pipeline backend): miss, the function the ray-query
// backend calls, on the path payload.
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/frame.h"
#include "shared/ray_tracing.h"
#include "kernel/scene_bindings.glsl"

layout(push_constant, scalar) uniform Push { FrameParams params; };

#include "kernel/miss.glsl"

layout(location = kPayloadPath) rayPayloadInEXT Payload path;

void main() { miss(path); }
