// Next event estimation, both integrators' (docs/integrators.md, "Lights"): every light is a LightRecord of
// one family (kernel/light_sampling.glsl, shaders/lights/). The light-selection distribution takes every delta
// light with probability 1, as the slides' equation sums them (directLighting), and one of the other lights by
// power (sampleOneLight, the path integrator's). Needs a traceVisibility (kernel/trace_query.glsl or
// kernel/trace_pipeline.glsl, by backend).
#ifndef RAYLAB_KERNEL_NEXT_EVENT_GLSL
#define RAYLAB_KERNEL_NEXT_EVENT_GLSL

#include "brdf/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "kernel/guiding.glsl"
#include "kernel/hit_common.glsl"
#include "kernel/light_sampling.glsl"
#include "kernel/mis.glsl"
#include "kernel/surface.glsl"

// sum_k f_r(w_k, w_o) E_k over the delta lights (the first params.punctualLightCount LightRecords, each selected
// with probability 1; sampleLight gives their irradiance E_k with density 1), a shadow ray each: equation 2 of
// the slides, and the path integrator's estimate of the same lights. ng and frame are those of shadingSide
// (kernel/hit_common.glsl): a one-sided BRDF sees the lights on the viewer's side, a two-sided one those on both.
vec3 directLighting(vec3 position, vec3 ng, ShadingFrame frame, vec3 woLocal, MaterialRecord material,
                    inout Payload p) {
  vec3 sum = vec3(0.0);
  for (uint k = 0u; k < params.punctualLightCount; ++k) {
    const LightSample light = sampleLight(k, position, vec3(0.5));
    const vec3 wiLocal = toLocal(frame, light.wi);
    // Light the geometric surface blocks cannot arrive, whatever the shading normal says.
    if (!seesSameSide(light.wi, ng, wiLocal.z)) continue;
    const vec3 contribution = bsdfEval(material, wiLocal, woLocal) * light.radiance * abs(wiLocal.z);
    // Only light that would contribute is worth a shadow ray.
    if (!(maxComponent(contribution) > 0.0)) continue;
    p.path.shadowRays += 1u;
    if (traceVisibility(offsetRayOrigin(position, leavingSide(ng, light.wi)), light.wi, light.distance)) sum += contribution;
  }
  return sum;
}

// The path integrator's estimate of the lights that are not delta lights: one drawn from the light-selection
// distribution (selectLight), one direction towards it, and what it brings through the (1 - delta) f_r part of
// the BSDF if nothing blocks it, weighted by misWeight against the continuation's sampling (the BSDF's, or at a
// guided vertex the mixture of guide and BSDF, kernel/guiding.glsl). Draws its random numbers whatever happens next,
// so that the vertex's later dimensions mean the same in every sample of a scene.
vec3 sampleOneLight(Surface s, vec3 ng, ShadingFrame frame, vec3 woLocal, MaterialRecord material, float delta,
                    GuideVertex guideHere, inout Payload p) {
  const vec4 u = rngNext4(p.path.rng);
  const LightChoice choice = selectLight(u.x);
  if (!(choice.pmf > 0.0)) return vec3(0.0);
  const LightSample light = sampleLight(choice.index, s.position, u.yzw);
  if (!(light.pdf > 0.0)) return vec3(0.0);
  const vec3 wiLocal = toLocal(frame, light.wi);
  if (!seesSameSide(light.wi, ng, wiLocal.z)) return vec3(0.0);
  const float pdf = choice.pmf * light.pdf;
  const float weight =
      misWeight(kSamplingLight, pdf,
                light.delta ? 0.0 : (1.0 - delta) * continuationPdf(guideHere, material, wiLocal, woLocal, light.wi));
  if (!(weight > 0.0)) return vec3(0.0);
  const vec3 f = (1.0 - delta) * bsdfEval(material, wiLocal, woLocal);
  const vec3 contribution = f * light.radiance * (abs(wiLocal.z) / pdf);
  if (!(maxComponent(contribution) > 0.0)) return vec3(0.0);
  p.path.shadowRays += 1u;
  if (!traceVisibility(offsetRayOrigin(s.position, leavingSide(ng, light.wi)), light.wi, light.distance)) return vec3(0.0);
  return weight * contribution;
}

#endif
