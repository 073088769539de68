#version 460
// The render kernel's closest-hit program (the ray-tracing-pipeline backend), in both hit groups: triangles,
// and spheres after sphere.rint. It runs closestHitProgram, the same function the ray-query backend calls,
// on the path payload; its shadow rays are the one level of recursion the pipeline allows.
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/frame.h"
#include "shared/ray_tracing.h"
#include "kernel/scene_bindings.glsl"

layout(push_constant, scalar) uniform Push { FrameParams params; };

#include "kernel/trace_pipeline.glsl"
#include "kernel/hit_pipeline.glsl"
#include "kernel/hit_program.glsl"

layout(location = kPayloadPath) rayPayloadInEXT Payload path;

void main() { closestHitProgram(committedHit(), path); }
