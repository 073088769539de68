// miss: the path leaves the scene and sees the environment (kernel/environment.glsl). In the path integrator
// an environment image is also sampled by next event estimation, so what a BSDF-sampled continuation sees of
// it is weighted against that (powerHeuristic); the uniform background is left to BSDF sampling alone, which
// for constant radiance is the better strategy.
#ifndef RAYLAB_KERNEL_MISS_GLSL
#define RAYLAB_KERNEL_MISS_GLSL

#include "kernel/environment.glsl"
#include "kernel/mis.glsl"
#include "kernel/payload.glsl"

// The weight of environment light that a continuation reached, against next event estimation of it.
float environmentWeight(Payload p) {
  if (kIntegrator != kIntegratorPath || p.path.lastSpecular != 0u || kSampling == kSamplingBsdf || !environmentSamplable()) {
    return 1.0;
  }
  if (kSampling == kSamplingLight) return 0.0;
  return powerHeuristic(p.path.lastPdf, environmentPdf(p.path.direction));
}

void miss(inout Payload p) {
  p.path.radiance += p.path.throughput * environmentRadiance(p.path.direction) * environmentWeight(p);
  p.done = true;
}

#endif
