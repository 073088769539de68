#version 460
// The probe's closest-hit program (trace_rays.rgen), in both hit groups: hands the committed hit back.
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/ray_tracing.h"
#include "kernel/hit_pipeline.glsl"
#include "kernel/probe_payload.glsl"

layout(location = kPayloadPath) rayPayloadInEXT ProbePayload probe;

void main() {
  probe.found = true;
  probe.hit = committedHit();
}
