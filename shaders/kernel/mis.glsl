// Multiple importance sampling (Veach 1997): the weights that combine light sampling with BSDF sampling.
#ifndef RAYLAB_KERNEL_MIS_GLSL
#define RAYLAB_KERNEL_MIS_GLSL

// Veach's power heuristic with beta = 2: the weight of a sample of density a against the other strategy's b.
float powerHeuristic(float a, float b) {
  const float a2 = a * a;
  return a2 > 0.0 ? a2 / (a2 + b * b) : 0.0;
}

#endif
