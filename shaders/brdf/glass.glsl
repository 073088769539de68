// Glass: a smooth dielectric interface, a delta BSDF. bsdfEval and bsdfPdf return 0 for it; the renderer
// follows the two delta directions with the weights computed here.
// lobes: reflection transmission specular
// look: eta=1.5, tint=0.95/0.98/1.0
// figure: eta=1.5
// sweep scene: eta 1 2.5 -> mean decreasing
// sweep why: at eta 1 every pixel sees the lit checker wall straight through; a higher eta reflects more (Fresnel grows
// sweep why: with eta at every angle) and bends rays further, and both send more of each pixel's paths to the dark
// sweep why: background in front of the spheres. The line from the camera through each centre meets the wall at a tile
// sweep why: corner, so each lens shows as much of the light tiles as of the dark ones at any magnification
// | parameter | range   | default | kind | meaning                                  |
// |-----------|---------|---------|------|------------------------------------------|
// | eta       | [1, 10] | 1.5     | eta  | index of refraction, inside over outside |
// | tint      | [0, 1]  | 1       | rgb transmittance | transmittance colour        |
// Snell's law and the Fresnel equations (Born & Wolf, "Principles of Optics", §1.5); Schlick 1994 for the
// approximations; conventions of docs/brdf_contract.md: if wi.n >= 0 the light comes from outside
// (eta_i = 1, eta_t = eta, nn = n), else from inside (eta_i = eta, eta_t = 1, nn = -n).
#ifndef RAYLAB_BRDF_GLASS_GLSL
#define RAYLAB_BRDF_GLASS_GLSL

#include "brdf/delta_event.glsl"
#include "brdf/fresnel.glsl"

// wi towards the light and n the outward normal, both unit, in any common frame.
DeltaEvent glassEvent(float eta, vec3 wi, vec3 n) {
  const float cosN = dot(wi, n);
  const bool outside = cosN >= 0.0;
  const float etaI = outside ? 1.0 : eta;
  const float etaT = outside ? eta : 1.0;
  const vec3 nn = outside ? n : -n;
  const float cosI = abs(cosN);
  // sin^2 theta_i from the cross product: 1 - cos^2 cancels near normal incidence. Rounding can lift it a
  // few ulps above 1 at grazing incidence, hence the min.
  const vec3 c = cross(wi, n);
  const float sin2I = min(1.0, dot(c, c));
  const float ratio = etaI / etaT;
  // (eta_t cos_t)^2 = d + eta_i^2 cos_i^2 with d = eta_t^2 - eta_i^2 a product of exact differences: the
  // same quantity F_DielectricExact uses, and sin^2 theta_t >= 1 exactly when it is <= 0.
  const float A2 = (etaT - etaI) * (etaT + etaI) + etaI * etaI * cosI * cosI;
  const float F0 = F0FromEta(eta);

  DeltaEvent event;
  event.transmittance = vec3(1.0);
  event.reflected = 2.0 * cosI * nn - wi;
  // 1 - cos = sin^2 / (1 + cos), which does not cancel near normal incidence.
  const float oneMinusCosI = sin2I / (1.0 + cosI);
  event.fresnelSchlickNaive = F_Schlick(F0, oneMinusCosI);
  if (eta == 1.0) {
    // No interface: F = 0 and the ray goes straight on, also at cos_i = 0, where Snell's sin^2 theta_t
    // reaches 1 and would otherwise call the grazing ray totally reflected (docs/brdfs.md, "Glass").
    event.tir = false;
    event.fresnelExact = 0.0;
    event.fresnelSchlick = F_Schlick(F0, oneMinusCosI);  // Schlick's (1 - cos)^5 does not vanish at eta = 1
    event.refracted = -wi;
    return event;
  }
  event.tir = A2 <= 0.0;
  event.fresnelExact = F_DielectricExact(cosI, etaI, etaT);
  if (event.tir) {
    event.fresnelSchlick = 1.0;
    event.refracted = vec3(0.0);
  } else {
    const float cosT = sqrt(A2) / etaT;
    // t = -ratio wi + (ratio cos_i - cos_t) nn, written as the tangential part of wi scaled by the ratio
    // plus the normal part, which avoids the cancellation in (ratio cos_i - cos_t) near eta = 1.
    event.refracted = -ratio * (wi - cosI * nn) - cosT * nn;
    const float oneMinusCosT = ratio * ratio * sin2I / (1.0 + cosT);
    event.fresnelSchlick = F_Schlick(F0, outside ? oneMinusCosI : oneMinusCosT);
  }
  return event;
}

// The model's delta lobes for the integrators: the interface, and the tint on the way in.
DeltaEvent glassDeltaEvent(float eta, vec3 tint, vec3 wi, vec3 n) {
  DeltaEvent event = glassEvent(eta, wi, n);
  event.transmittance = tint;
  return event;
}

#endif
