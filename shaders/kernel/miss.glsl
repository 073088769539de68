// miss: the path leaves the scene and sees the background.
#ifndef RAYLAB_KERNEL_MISS_GLSL
#define RAYLAB_KERNEL_MISS_GLSL

#include "kernel/payload.glsl"

void miss(inout Payload p) {
  p.radiance += p.throughput * params.background;
  p.done = true;
}

#endif
