// The render kernel's closest-hit program as both backends call it: the vertex of the integrator the kernel was
// specialised for (a specialization constant, so each kernel keeps one of the two calls). Needs `params`, the
// scene bindings and a traceVisibility (kernel/trace_query.glsl or kernel/trace_pipeline.glsl).
#ifndef RAYLAB_KERNEL_HIT_PROGRAM_GLSL
#define RAYLAB_KERNEL_HIT_PROGRAM_GLSL

#include "kernel/closest_hit.glsl"
#include "kernel/path_hit.glsl"

void closestHitProgram(Hit hit, inout Payload p) {
  if (kIntegrator == kIntegratorPath) {
    closestHitPath(hit, p);
  } else {
    closestHit(hit, p);
  }
}

#endif
