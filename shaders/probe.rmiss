#version 460
// The probe's miss program (trace_rays.rgen): nothing on the ray.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "shared/ray_tracing.h"
#include "kernel/probe_payload.glsl"

layout(location = kPayloadPath) rayPayloadInEXT ProbePayload probe;

void main() { probe.found = false; }
