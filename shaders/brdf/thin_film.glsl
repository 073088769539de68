// Thin-film interference in RGB, as engine/reference/thin_film.cpp derives it (docs/brdfs.md, "Thin film"): per
// polarisation, R = 1 - T [1 + 2 Re sum_m (-x exp(i arg r23))^m G_c(m OPD)], T = (1 - R12)(1 - R23) / (1 - R12 R23),
// x = r12 |r23|, with the channels' spectral transforms G_c tabulated in the BRDF tables, kThinFilmTerms terms and
// a geometric tail. Complex numbers are vec2 (re, im). lavapipe inlines every call and unrolls loops of known
// count: every loop here is [[dont_unroll]] and each function has one call site per use, or the film alone made a
// path kernel that LLVM took over 10 minutes and 4 GB to compile.
#ifndef RAYLAB_BRDF_THIN_FILM_GLSL
#define RAYLAB_BRDF_THIN_FILM_GLSL

#extension GL_EXT_control_flow_attributes : require

#include "brdf/brdf_tables.glsl"

vec2 complexMul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 complexDiv(vec2 a, vec2 b) { return complexMul(a, vec2(b.x, -b.y)) / dot(b, b); }
// The principal root (real part >= 0).
vec2 complexSqrt(vec2 z) {
  const float r = length(z);
  const float re = sqrt(max(0.5 * (r + z.x), 0.0));
  const float im = sqrt(max(0.5 * (r - z.x), 0.0));
  return vec2(re, z.y < 0.0 ? -im : im);
}

// G_c(t) of the three channels at t nm (real and imaginary parts), linear in the table, 0 beyond it.
void thinFilmSpectrum(float t, out vec3 re, out vec3 im) {
  re = vec3(0.0);
  im = vec3(0.0);
  const float x = t / kThinFilmStepNm;
  if (!(x < float(kThinFilmSamples - 1u))) return;
  const uint k = uint(x);
  const uint i = kThinFilmOffset + 6u * k;
  const float f = x - float(k);
  re = mix(vec3(brdfTables[i], brdfTables[i + 2u], brdfTables[i + 4u]),
           vec3(brdfTables[i + 6u], brdfTables[i + 8u], brdfTables[i + 10u]), f);
  im = mix(vec3(brdfTables[i + 1u], brdfTables[i + 3u], brdfTables[i + 5u]),
           vec3(brdfTables[i + 7u], brdfTables[i + 9u], brdfTables[i + 11u]), f);
}

// One polarisation's RGB reflectance from its amplitudes r12 (real) and r23, and the optical path (nm): the series'
// terms a_m = p^m G_c(m OPD), p = -x exp(i arg r23), in every channel at once.
vec3 thinFilmPolarisation(float r12, vec2 r23, float opd) {
  const float R12 = r12 * r12, R23 = dot(r23, r23);
  const float denominator = 1.0 - R12 * R23;
  if (!(denominator > 1e-7)) return vec3(1.0);  // both interfaces mirrors
  const float T = (1.0 - R12) * (1.0 - R23) / denominator;
  const vec2 step = -r12 * r23;
  vec2 power = vec2(1.0, 0.0);
  vec3 termRe = vec3(0.0), termIm = vec3(0.0), sumRe = vec3(0.0);
  [[dont_unroll]] for (uint m = 1u; m <= kThinFilmTerms; ++m) {
    power = complexMul(power, step);
    vec3 gRe, gIm;
    thinFilmSpectrum(float(m) * opd, gRe, gIm);
    termRe = power.x * gRe - power.y * gIm;
    termIm = power.x * gIm + power.y * gRe;
    sumRe += termRe;
    // Most films stop here after a few terms: |x|^m below 1e-5 (x is 0.05 for a film of index 2 on glass at normal
    // incidence), and the tail below is then smaller still.
    if (dot(power, power) < 1e-10) break;
  }
  // The geometric tail a_M ratio / (1 - ratio), ratio = p G_c(OPD), per channel.
  vec3 gRe, gIm;
  thinFilmSpectrum(opd, gRe, gIm);
  const vec3 ratioRe = step.x * gRe - step.y * gIm, ratioIm = step.x * gIm + step.y * gRe;
  const vec3 numRe = termRe * ratioRe - termIm * ratioIm, numIm = termRe * ratioIm + termIm * ratioRe;
  const vec3 denRe = 1.0 - ratioRe, denIm = -ratioIm;
  sumRe += (numRe * denRe + numIm * denIm) / (denRe * denRe + denIm * denIm);
  return 1.0 - T * (1.0 + 2.0 * sumRe);
}

// The unpolarised RGB reflectance, from a medium of index 1, of a film (index etaFilm, thickness nm) over a base of
// complex index eta3 = (n, k).
vec3 thinFilmReflectance(float cosTheta, float etaFilm, float thicknessNm, vec2 eta3) {
  const float sin2 = max(0.0, 1.0 - cosTheta * cosTheta);
  const float cos2Film = 1.0 - sin2 / (etaFilm * etaFilm);
  if (!(cos2Film > 0.0)) return vec3(1.0);  // a film of index below 1 past its critical angle
  const float cosFilm = sqrt(cos2Film);
  // r_s = (a c - w) / (a c + w), r_p = (b^2 c - a w) / (b^2 c + a w), w = b cos_b, at each interface a -> b.
  const float wFilm = etaFilm * cosFilm;
  const float topS = (cosTheta - wFilm) / (cosTheta + wFilm);
  const float topP = (etaFilm * etaFilm * cosTheta - wFilm) / (etaFilm * etaFilm * cosTheta + wFilm);
  const vec2 eta3Squared = complexMul(eta3, eta3);
  const vec2 w = complexSqrt(eta3Squared - vec2(sin2, 0.0));  // Snell: eta_film sin(theta_film) = sin(theta)
  const vec2 a = vec2(wFilm, 0.0);
  const vec2 bottomS = complexDiv(a - w, a + w);
  const vec2 bc = eta3Squared * cosFilm, aw = etaFilm * w;
  const vec2 bottomP = complexDiv(bc - aw, bc + aw);
  const float opd = 2.0 * etaFilm * thicknessNm * cosFilm;
  vec3 R = vec3(0.0);
  [[dont_unroll]] for (uint polarisation = 0u; polarisation < 2u; ++polarisation) {
    const bool s = polarisation == 0u;
    R += 0.5 * thinFilmPolarisation(s ? topS : topP, s ? bottomS : bottomP, opd);
  }
  return clamp(R, 0.0, 1.0);
}

// Gulbrandsen's complex index (n, k) of a metal of reflectivity r and edge tint g (reference/thin_film.h).
vec2 metalIndexFromTint(float r, float g) {
  r = clamp(r, 0.0, 0.99);
  const float root = sqrt(r);
  const float n = g * (1.0 - r) / (1.0 + r) + (1.0 - g) * (1.0 + root) / (1.0 - root);
  return vec2(n, sqrt(max((r * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - r), 0.0)));
}

// The unpolarised Fresnel reflectance of a bare base of complex index eta.
float bareReflectance(float cosTheta, vec2 eta) {
  const vec2 eta2 = complexMul(eta, eta);
  const vec2 w = complexSqrt(eta2 - vec2(1.0 - cosTheta * cosTheta, 0.0));
  const vec2 c = vec2(cosTheta, 0.0), bc = eta2 * cosTheta;
  const vec2 s = complexDiv(c - w, c + w), p = complexDiv(bc - w, bc + w);
  return 0.5 * (dot(s, s) + dot(p, p));
}

// A film over a metal whose Fresnel term is f82, from the film's reflectance over Gulbrandsen's index of the
// metal: F = 1 - (1 - f82)(1 - R_film)/(1 - R_bare) (reference: openpbr.cpp, filmOverMetal).
float thinFilmOverMetal(float f82, float film, vec2 eta, float cosTheta) {
  const float absorbedBare = max(1.0 - bareReflectance(cosTheta, eta), 1e-7);
  return clamp(1.0 - (1.0 - f82) * (1.0 - film) / absorbedBare, 0.0, 1.0);
}

#endif
