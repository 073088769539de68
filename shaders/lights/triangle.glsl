// An emitting triangle, in world space: p0, p1, p2 its vertices (counter-clockwise seen from the emitting front),
// radiance its L_e, area its area. Next event estimation samples it by the solid angle it subtends (Arvo 1995,
// "Stratified Sampling of Spherical Triangles", as pbrt-v4's SampleSphericalTriangle): density 1 / Omega, so a
// shading point next to a large emitter no longer meets the r^2 / cos of area sampling. Where the spherical
// triangle is too small for its trigonometry in single precision, or almost a hemisphere, a point uniform by
// area (b0 = 1 - sqrt(u), b1 = v sqrt(u), Turk 1990) at density r^2 / (A cos theta_l) instead, the same
// thresholds as pbrt-v4 (docs/performance.md, "Solid-angle sampling of emitting triangles").
#ifndef RAYLAB_LIGHTS_TRIANGLE_GLSL
#define RAYLAB_LIGHTS_TRIANGLE_GLSL

#include "brdf/common.glsl"
#include "lights/light_sample.glsl"

// The shadow ray stops this fraction short of an emitter's point: the emitter is scene geometry too.
const float kShortOfEmitter = 1e-4;
// Solid angles (sr) outside which the triangle is sampled by area: below, Arvo's angles lose their digits in
// single precision; above, the triangle covers almost the whole hemisphere and the inversion is ill-conditioned.
const float kMinSphericalTriangle = 3e-4;
const float kMaxSphericalTriangle = 6.22;

// The solid angle of the spherical triangle of unit directions a, b, c (Van Oosterom and Strackee 1983).
float sphericalTriangleArea(vec3 a, vec3 b, vec3 c) {
  return abs(2.0 * atan(dot(a, cross(b, c)), 1.0 + dot(a, b) + dot(a, c) + dot(b, c)));
}

// The angle between unit vectors, accurate near 0 and pi (unlike acos of their dot product).
float angleBetween(vec3 v1, vec3 v2) {
  if (dot(v1, v2) < 0.0) return kPi - 2.0 * asin(clamp(length(v1 + v2) * 0.5, 0.0, 1.0));
  return 2.0 * asin(clamp(length(v2 - v1) * 0.5, 0.0, 1.0));
}

// The unit component of v orthogonal to unit w.
vec3 orthogonalTo(vec3 v, vec3 w) { return normalize(v - dot(v, w) * w); }

// The solid angle the triangle subtends at x, if it is to be sampled by it; 0: sample by area.
float triangleSolidAngleToSample(LightRecord light, vec3 x) {
  const float omega =
      sphericalTriangleArea(normalize(light.p0 - x), normalize(light.p1 - x), normalize(light.p2 - x));
  return omega >= kMinSphericalTriangle && omega <= kMaxSphericalTriangle ? omega : 0.0;
}

// A direction uniform in the solid angle of the spherical triangle a, b, c (unit, seen from the shading point),
// by Arvo's inversion: u.x picks the sub-triangle's area, u.y the point along the arc from b.
vec3 sampleSphericalTriangle(vec3 a, vec3 b, vec3 c, vec2 u) {
  const vec3 nAb = normalize(cross(a, b));
  const vec3 nBc = normalize(cross(b, c));
  const vec3 nCa = normalize(cross(c, a));
  const float alpha = angleBetween(nAb, -nCa);
  const float beta = angleBetween(nBc, -nAb);
  const float gamma = angleBetween(nCa, -nBc);
  const float areaPlusPi = mix(kPi, alpha + beta + gamma, u.x);
  const float cosAlpha = cos(alpha), sinAlpha = sin(alpha);
  const float sinPhi = sin(areaPlusPi) * cosAlpha - cos(areaPlusPi) * sinAlpha;
  const float cosPhi = cos(areaPlusPi) * cosAlpha + sin(areaPlusPi) * sinAlpha;
  const float k1 = cosPhi + cosAlpha;
  const float k2 = sinPhi - sinAlpha * dot(a, b);
  // Clamped: rounding takes it just past +-1 when the triangle is nearly a hemisphere.
  const float cosBp = clamp((k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha),
                            -1.0, 1.0);
  const float sinBp = sqrt(max(1.0 - cosBp * cosBp, 0.0));
  const vec3 cp = cosBp * a + sinBp * orthogonalTo(c, a);
  const float cosTheta = 1.0 - u.y * (1.0 - dot(cp, b));
  const float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  return normalize(cosTheta * b + sinTheta * orthogonalTo(cp, b));
}

LightSample triangleLightSample(LightRecord light, vec3 x, vec3 u) {
  LightSample s = noLightSample();
  const vec3 n = normalize(cross(light.p1 - light.p0, light.p2 - light.p0));
  // Behind its plane every point shows its back face: nothing to sample.
  if (!(dot(n, x - light.p0) > 0.0)) return s;
  const float omega = triangleSolidAngleToSample(light, x);
  if (omega > 0.0) {
    const vec3 wi = sampleSphericalTriangle(normalize(light.p0 - x), normalize(light.p1 - x),
                                            normalize(light.p2 - x), u.xy);
    // The point of the plane along wi; inside the triangle up to rounding.
    const float distance = dot(n, light.p0 - x) / dot(n, wi);
    if (!(distance > 0.0) || isinf(distance)) return s;
    s.wi = wi;
    s.distance = distance * (1.0 - kShortOfEmitter);
    s.radiance = light.radiance;
    s.pdf = 1.0 / omega;
    s.delta = false;
    return s;
  }
  const float su = sqrt(u.x);
  const vec3 y = (1.0 - su) * light.p0 + (u.y * su) * light.p1 + (su - u.y * su) * light.p2;
  const vec3 toY = y - x;
  const float d2 = dot(toY, toY);
  const float distance = sqrt(d2);
  s.wi = toY / distance;
  const float cosL = -dot(n, s.wi);
  if (!(cosL > 0.0) || !(distance > 0.0)) return s;  // degenerate
  s.distance = distance * (1.0 - kShortOfEmitter);
  s.radiance = light.radiance;
  s.pdf = d2 / (light.area * cosL);
  s.delta = false;
  return s;
}

// The density of reaching point y of the triangle from x along wi: the same choice of strategy as the sampler.
float triangleLightPdf(LightRecord light, vec3 x, vec3 wi, vec3 y) {
  const vec3 n = normalize(cross(light.p1 - light.p0, light.p2 - light.p0));
  if (!(dot(n, x - light.p0) > 0.0)) return 0.0;
  const float omega = triangleSolidAngleToSample(light, x);
  if (omega > 0.0) return 1.0 / omega;
  const vec3 toY = y - x;
  const float d2 = dot(toY, toY);
  const float cosL = abs(dot(n, toY)) * inversesqrt(d2);
  return cosL > 0.0 ? d2 / (light.area * cosL) : 0.0;
}

#endif
