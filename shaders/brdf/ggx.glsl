// GGX (Trowbridge-Reitz) microfacet terms, anisotropic (docs/brdfs.md, "GGX terms"), each from the components of
// the unnormalised half vector h or a direction w, never through tan or acos.
//   D_GGX:   Trowbridge & Reitz, "Average irregularity representation of a rough surface for ray reflection",
//            JOSA 65(5), 1975; Walter, Marschner, Li & Torrance, EGSR 2007 (anisotropic form of Heitz 2014).
//   Lambda:  Smith's masking for GGX (Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based
//            BRDFs", JCGT 3(2), 2014).
//   sampleGgxVisibleNormal: Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4), 2018.
#ifndef RAYLAB_BRDF_GGX_GLSL
#define RAYLAB_BRDF_GGX_GLSL

#include "brdf/common.glsl"

// D(m) = 1 / (pi ax ay B^2), B = (h_x^2/ax^2 + h_y^2/ay^2 + h_z^2) / |h|^2 for any length of h. B >= min(1,
// 1/a^2 ...) >= 1 for a <= 1, so D <= 1 / (pi ax ay) <= 3.2e5 at the smallest roughness, and B <= 1e6 keeps B^2
// in range.
float D_GGX(vec3 h, float ax, float ay) {
  if (!(h.z > 0.0)) return 0.0;
  const float b = (h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + h.z * h.z) / dot(h, h);
  return 1.0 / (kPi * ax * ay * b * b);
}

// Lambda(w) = (-1 + sqrt(1 + x)) / 2, x = (ax^2 w_x^2 + ay^2 w_y^2) / w_z^2, as x / (2 (1 + sqrt(1 + x))): no
// cancellation for small x (smooth surfaces seen near the normal). w_z >= 1e-15 (liftOffHorizon) keeps x < 1e30.
float Lambda_GGX(vec3 w, float ax, float ay) {
  const float x = (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z);
  return x / (2.0 * (1.0 + sqrt(1.0 + x)));
}

float G1_GGX(vec3 w, float ax, float ay) { return 1.0 / (1.0 + Lambda_GGX(w, ax, ay)); }

// A microfacet normal m drawn with density D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo_z, for wo above the horizon.
vec3 sampleGgxVisibleNormal(vec3 wo, float ax, float ay, vec2 u) {
  // The hemisphere configuration: stretch wo to roughness 1.
  const vec3 vh = normalize(vec3(ax * wo.x, ay * wo.y, wo.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  const vec3 t2 = cross(vh, t1);
  // A point on the projected disk, its far half squashed by the visible fraction.
  const float r = sqrt(u.x);
  const float phi = kTwoPi * u.y;
  const float p1 = r * cos(phi);
  const float s = 0.5 * (1.0 + vh.z);
  const float p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * (r * sin(phi));
  const vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  // Unstretch. nh.z >= 0; the floor keeps m above the horizon when rounding puts it on it.
  return normalize(vec3(ax * nh.x, ay * nh.y, max(nh.z, 1e-7)));
}

// The density of wi = reflect(wo, m) when m has density D_wo(m): D_wo(m) / (4 wo.m) = G1(wo) D(m) / (4 wo_z).
float ggxReflectionPdf(vec3 h, vec3 wo, float ax, float ay) { return G1_GGX(wo, ax, ay) * D_GGX(h, ax, ay) / (4.0 * wo.z); }

#endif
