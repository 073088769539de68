// miss: the path leaves the scene and sees the environment (kernel/environment.glsl). In the path integrator
// an environment image is also a light for next event estimation (lights/environment.glsl), so what a
// BSDF-sampled continuation sees of it is weighted against that (misWeight); the uniform background is left to BSDF sampling alone, which
// for constant radiance is the better strategy.
#ifndef RAYLAB_KERNEL_MISS_GLSL
#define RAYLAB_KERNEL_MISS_GLSL

#include "kernel/aov.glsl"
#include "kernel/environment.glsl"
#include "kernel/light_sampling.glsl"
#include "kernel/mis.glsl"
#include "kernel/payload.glsl"

// The weight of environment light that a continuation reached, against next event estimation of it.
float environmentWeight(Payload p) {
  if (kIntegrator != kIntegratorPath || p.path.lastSpecular != 0u || !hasEnvironmentImage() ||
      environment.light == kNoLight) {
    return 1.0;
  }
  const float lightPdfHere = lightPdf(environment.light, p.path.lastPosition, p.path.direction, vec3(0.0));
  return misWeight(kSamplingBsdf, p.path.lastPdf, lightPdfHere);
}

void miss(inout Payload p) {
  // A path that leaves a volume without crossing its surface again (a mesh that is not closed) travelled an endless
  // way through it: Beer-Lambert leaves nothing.
  if (maxComponent(p.path.absorption) > 0.0) {
    p.done = true;
    return;
  }
  const vec3 seen = environmentRadiance(p.path.direction);
  if (recordsAov(p)) recordAov(p, seen, vec3(0.0));
  p.path.radiance += p.path.throughput * seen * environmentWeight(p);
  p.done = true;
}

#endif
