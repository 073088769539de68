// Next event estimation's one family of lights (docs/integrators.md, "Lights"): every light is a LightRecord of
// some kind (shaders/lights/lights.cmake), selected with probability LightRecord.pmf (the light-selection
// distribution, engine/render/light_records.cpp: 1 for each delta light, which the first punctualLightCount
// records are; the others by power, one at a time through their cdf), then sampled by its kind (sampleLight).
// lightPdf is the density, selection included, with which next event estimation produces a direction that a
// continuation reached, for misWeight (kernel/mis.glsl).
#ifndef RAYLAB_KERNEL_LIGHT_SAMPLING_GLSL
#define RAYLAB_KERNEL_LIGHT_SAMPLING_GLSL

#include "common/specialization.glsl"
#include "kernel/payload.glsl"
#include "lights/light_sample.glsl"
#include "generated/light_dispatch.glsl"

struct LightChoice {
  uint index;
  float pmf;  // its probability; 0: nothing to sample
};

// One of the lights after the delta lights, in proportion to power: the first whose inclusive cdf exceeds u.
LightChoice selectLight(float u) {
  LightChoice choice;
  choice.index = 0u;
  choice.pmf = 0.0;
  if (params.lightCount <= params.punctualLightCount) return choice;
  uint low = params.punctualLightCount, high = params.lightCount - 1u;
  while (low < high) {
    const uint mid = (low + high) / 2u;
    if (u < lights[mid].cdf) high = mid;
    else low = mid + 1u;
  }
  choice.index = low;
  choice.pmf = lights[low].pmf;
  return choice;
}

// A direction towards light `index` from x (u: three uniform numbers its kind may use), without its selection
// probability.
LightSample sampleLight(uint index, vec3 x, vec3 u) { return sampleLightKind(lights[index], x, u); }

// The density, per unit solid angle and selection included, of next event estimation from x producing the
// direction wi that reaches point y of light `index`.
float lightPdf(uint index, vec3 x, vec3 wi, vec3 y) {
  const LightRecord light = lights[index];
  return light.pmf > 0.0 ? light.pmf * lightKindPdf(light, x, wi, y) : 0.0;
}

#endif
