// Multiple importance sampling (Veach 1997): the weights that combine light sampling with BSDF sampling.
#ifndef RAYLAB_KERNEL_MIS_GLSL
#define RAYLAB_KERNEL_MIS_GLSL

#include "common/specialization.glsl"

// Veach's power heuristic with beta = 2: the weight of a sample of density a against the other strategy's b.
float powerHeuristic(float a, float b) {
  const float a2 = a * a;
  return a2 > 0.0 ? a2 / (a2 + b * b) : 0.0;
}

// The weight of a sample that `strategy` (kSamplingLight or kSamplingBsdf) drew with density `pdf`, when the other
// strategy would draw it with density `otherPdf`. A sample only one strategy can draw (a delta light, a delta
// BSDF lobe, a light the selection never picks) keeps all of it; otherwise kSampling says: the power heuristic,
// or all to the one strategy a study asked for.
float misWeight(uint strategy, float pdf, float otherPdf) {
  if (!(otherPdf > 0.0)) return 1.0;
  if (kSampling == kSamplingMis) return powerHeuristic(pdf, otherPdf);
  return kSampling == strategy ? 1.0 : 0.0;
}

#endif
