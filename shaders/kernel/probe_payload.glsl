// The probe's payload in the ray-tracing-pipeline backend: the committed hit, handed back to the raygen.
#ifndef RAYLAB_KERNEL_PROBE_PAYLOAD_GLSL
#define RAYLAB_KERNEL_PROBE_PAYLOAD_GLSL

#include "kernel/payload.glsl"

struct ProbePayload {
  bool found;
  Hit hit;
};

#endif
