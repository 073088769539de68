// closestHit of the path integrator: one vertex of a path tracer that solves the rendering equation
// (Kajiya 1986, equation 1 of the slides):
//   L_o(x, wo) = L_e(x, wo) + integral f(wi, wo) L_i(x, wi) cos(theta_i) dwi.
// At each vertex: the emission seen along the path, next event estimation (kernel/next_event.glsl) of every
// punctual light (directLighting) and of one emitting triangle, sphere or the environment image drawn by power
// (sampleOneLight), then one continuation chosen by the BSDF's own sampler (bsdfSample), with the
// mirror weight delta as a mixture f = (1 - delta) f_r + delta mirror; a specular-only BSDF (glass, by its lobe
// flags) continues along one delta lobe (bsdfSampleSpecular), and a two-sided one (rough glass) is shaded on both
// sides, its lights and its continuation on either (kernel/hit_common.glsl, shadingSide). Light samples and
// emission reached by a continuation are weighted against each other by misWeight (kernel/mis.glsl: the power
// heuristic, Veach 1997, or one strategy alone for studies); delta lights are light-sampled only. The uniform
// background is left to BSDF sampling. With kFeatureGuiding, a vertex with a diffuse lobe in a cell that learned where
// light comes from draws its continuation from the mixture of that guide and the BSDF (kernel/guiding.glsl), and
// leaves a training record for the raygen. Russian roulette after kRouletteDepth bounces keeps the estimator unbiased (docs/integrators.md).
// Depth: --max-depth D allows D + 1 continuations after the camera ray, so a path has at most D + 2 segments
// (Mitsuba 3's max_depth = D + 2); D = 0 is direct lighting only.
#ifndef RAYLAB_KERNEL_PATH_HIT_GLSL
#define RAYLAB_KERNEL_PATH_HIT_GLSL

#include "kernel/aov.glsl"
#include "kernel/emission.glsl"
#include "kernel/guiding.glsl"
#include "kernel/hit_common.glsl"
#include "kernel/next_event.glsl"

// Bounces before Russian roulette may end a path; after them a path survives with probability equal to its
// largest throughput channel (at most kRouletteMax), and survivors are weighted up by its inverse.
const uint kRouletteDepth = 3u;
const float kRouletteMax = 0.95;

// The weight of emission that a continuation reached, against next event estimation of the same point.
float emissionWeight(Hit hit, Surface s, Payload p) {
  const uint first = instances[hit.instance].firstLight;
  if (p.path.lastSpecular != 0u || first == kNoLight) return 1.0;
  const float lightPdfHere = lightPdf(first + hit.primitive, p.path.lastPosition, p.path.direction, s.position);
  return misWeight(kSamplingBsdf, p.path.lastPdf, lightPdfHere);
}

// Sets up the continuation (origin, direction, weight) or ends the path; applies Russian roulette.
void continueOrEnd(inout Payload p, vec3 origin, vec3 direction, vec3 throughput) {
  p.done = true;
  if (!(maxComponent(throughput) > 0.0)) return;
  if (p.path.depth >= kRouletteDepth) {
    const float survive = min(maxComponent(throughput), kRouletteMax);
    if (rngNext4(p.path.rng).x >= survive) return;
    throughput /= survive;
  }
  p.path.origin = origin;
  p.path.direction = direction;
  p.path.throughput = throughput;
  p.path.depth += 1u;
  p.done = false;
}

// A vertex of a specular-only BSDF (glass): one delta lobe, chosen by bsdfSampleSpecular.
void specularVertex(Surface s, MaterialRecord material, vec3 wo, inout Payload p) {
  const SpecularSample b = bsdfSampleSpecular(material, wo, s.shadingNormal, rngNext4(p.path.rng).x);
  const bool entering = dot(wo, s.geometricNormal) > 0.0;
  const bool reflected = (b.flags & kLobeReflection) != 0u;
  // Each continuation leaves from the side of the geometric surface it travels into.
  const vec3 side = (reflected == entering) ? s.geometricNormal : -s.geometricNormal;
  if (!(dot(b.wi, side) > 0.0)) {
    p.done = true;
    return;
  }
  p.path.lastSpecular = 1u;
  continueOrEnd(p, offsetRayOrigin(s.position, side), b.wi, p.path.throughput * b.weight);
}

// A continuation that crosses the surface of a transmissive material with a volume enters or leaves that volume
// (the surface's outward normal tells which; closed surfaces are assumed, as in every renderer with interior media).
void crossMedium(inout Payload p, Surface s, MaterialRecord material, vec3 wo, vec3 wi) {
  const bool fromOutside = dot(wo, s.geometricNormal) > 0.0, toOutside = dot(wi, s.geometricNormal) > 0.0;
  if (fromOutside && !toOutside) p.path.absorption = bsdfMediumAbsorption(material);
  if (!fromOutside && toOutside) p.path.absorption = vec3(0.0);
}

void closestHitPath(Hit hit, inout Payload p) {
  // Beer-Lambert along the segment that reached here, inside a volume.
  if (maxComponent(p.path.absorption) > 0.0) p.path.throughput *= exp(-p.path.absorption * hit.t);
  Surface s = surfaceAt(hit);
  MaterialRecord material = materials[s.material];
  const vec3 wo = -p.path.direction;
  p.done = true;
  p.split = false;
  p.guideRecorded = false;
  rngStartVertex(p.path.rng, p.path.depth);

  // Emission from the front face only, the side the counter-clockwise winding's normal points to.
  if (s.frontFace && maxComponent(material.emission) > 0.0) {
    p.path.radiance += p.path.throughput * emittedRadiance(material, s.uv, s.uv1) * emissionWeight(hit, s, p);
  }
  if (p.path.depth > params.maxDepth) return;  // the segment that reached here was the last one allowed

  if (isSpecularOnly(bsdfFlags(material))) {
    if (recordsAov(p)) recordAov(p, vec3(1.0), facing(s.shadingNormal, wo));
    specularVertex(s, material, wo, p);
    return;
  }
  applyTextures(material, s);
  const uint flags = bsdfFlags(material);
  const float delta = featureEnabled(kFeatureMirror) ? material.delta : 0.0;
  const ShadingSide side = shadingSide(s, wo, flags, delta);
  const vec3 ng = side.ng;
  const vec3 ns = side.ns;
  const ShadingFrame frame = side.frame;
  applyCoatNormal(material, s, frame);
  const vec3 woLocal = toLocal(frame, wo);

  // Next event estimation: the (1 - delta) f_r part of the mixture sees the lights.
  if (delta < 1.0 && params.punctualLightCount > 0u) {
    p.path.radiance += p.path.throughput * (1.0 - delta) * directLighting(s.position, ng, frame, woLocal, material, p);
  }
  const GuideVertex guideHere = guideVertex(s.position, flags);
  if (kSampling != kSamplingBsdf && delta < 1.0 && params.lightCount > params.punctualLightCount) {
    p.path.radiance += p.path.throughput * sampleOneLight(s, ng, frame, woLocal, material, delta, guideHere, p);
  }
  p.path.lastPosition = s.position;

  if (recordsAov(p)) recordAov(p, firstHitAlbedo(p, material, woLocal, delta), facing(ns, wo));

  // The continuation: the mirror with probability delta, else a sample of f_r (weight f |cos| / pdf).
  const vec4 u = rngNext4(p.path.rng);
  if (u.w < delta) {
    const vec3 viewerSide = leavingSide(ng, wo);
    const vec3 mirror = reflect(p.path.direction, dot(ns, viewerSide) > 0.0 ? ns : -ns);
    p.path.lastSpecular = 1u;
    if (dot(mirror, viewerSide) > 0.0) continueOrEnd(p, offsetRayOrigin(s.position, viewerSide), mirror, p.path.throughput);
    return;
  }
  // In a guided cell (kernel/guiding.glsl) the sample comes from the mixture of guide and BSDF, b.pdf the mixture's.
  GuidedSample g = GuidedSample(noSample(), 0.0);
  if (guideHere.share > 0.0) {
    g = guidedSample(guideHere, material, frame, woLocal, u.xyz, rngNext4(p.path.rng).xyz);
  } else {
    g.b = bsdfSample(material, woLocal, u.xyz);
    g.pdfBsdf = g.b.pdf;
  }
  const BsdfSample b = g.b;
  if (!(b.pdf > 0.0)) return;
  const vec3 wi = toWorld(frame, b.wi);
  // A shading-normal sample on the other side of the geometric surface than its lobe meant cannot go there.
  if (!seesSameSide(wi, ng, b.wi.z)) return;
  p.path.lastSpecular = 0u;
  p.path.lastPdf = (1.0 - delta) * b.pdf;
  if (isTwoSided(flags)) crossMedium(p, s, material, wo, wi);
  const vec3 fCos = (1.0 - delta) * b.f * abs(b.wi.z);
  if (guideTrains() && guideHere.cell != kNoGuideCell) {
    p.guideRecorded = true;
    p.guideRecord = guideRecordOf(guideHere, p.path.radiance, p.path.throughput, fCos, g, wi, delta);
  }
  continueOrEnd(p, offsetRayOrigin(s.position, leavingSide(ng, wi)), wi, p.path.throughput * b.f * (abs(b.wi.z) / b.pdf));
}

#endif
