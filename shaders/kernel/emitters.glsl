// Area lights for next event estimation: emitting triangles and spheres (EmitterRecord), picked in proportion
// to their power, then a point on a triangle uniformly by area, or a direction in a sphere's cone of visible
// directions (uniform in solid angle, Shirley et al. 1996; pbrt-v4's SampleSphere). Densities are per unit
// solid angle at the shading point, for MIS with BSDF sampling (powerHeuristic, kernel/mis.glsl).
#ifndef RAYLAB_KERNEL_EMITTERS_GLSL
#define RAYLAB_KERNEL_EMITTERS_GLSL

#include "kernel/payload.glsl"

const float kTwoPiEmitter = 6.28318530717958648;

struct EmitterSample {
  vec3 wi;         // unit, from the shading point towards the emitter
  float distance;  // to the sampled point
  vec3 radiance;   // L_e arriving along -wi (0 from a back face)
  float pdf;       // solid angle, the emitter's pmf included; 0: no sample
};

// The first emitter whose inclusive cdf exceeds u: a binary search.
uint pickEmitter(float u) {
  uint low = 0u, high = params.emitterCount - 1u;
  while (low < high) {
    const uint mid = (low + high) / 2u;
    if (u < emitters[mid].cdf) high = mid;
    else low = mid + 1u;
  }
  return low;
}

// 1 - cos(theta_max) of the cone a sphere of radius r subtends at distance d > r, without cancellation for
// small spheres: sin^2 / (1 + cos).
float sphereConeOneMinusCos(float r, float d) {
  const float sin2 = (r * r) / (d * d);
  return sin2 / (1.0 + sqrt(max(0.0, 1.0 - sin2)));
}

// Solid-angle density of reaching point y (normal ny) of emitter `index` from x by sampleEmitter.
float emitterPdf(uint index, vec3 x, vec3 y, vec3 ny) {
  const EmitterRecord e = emitters[index];
  if (e.kind == kEmitterSphere) {
    const float d = length(e.p0 - x);
    if (d <= e.p1.x) return 0.0;
    return e.pmf / (kTwoPiEmitter * sphereConeOneMinusCos(e.p1.x, d));
  }
  const vec3 toY = y - x;
  const float d2 = dot(toY, toY);
  const float cosL = abs(dot(ny, toY)) * inversesqrt(d2);
  return cosL > 0.0 ? e.pmf * d2 / (e.area * cosL) : 0.0;
}

EmitterSample sampleEmitter(vec3 x, vec3 u) {
  EmitterSample s;
  s.pdf = 0.0;
  s.radiance = vec3(0.0);
  const uint index = pickEmitter(u.x);
  const EmitterRecord e = emitters[index];
  if (!(e.pmf > 0.0)) return s;
  if (e.kind == kEmitterSphere) {
    const vec3 axis = e.p0 - x;
    const float d = length(axis);
    const float r = e.p1.x;
    if (d <= r) return s;  // inside: the sphere's back faces emit nothing
    const float oneMinusCosMax = sphereConeOneMinusCos(r, d);
    const float oneMinusCos = u.y * oneMinusCosMax;
    const float cosTheta = 1.0 - oneMinusCos;
    const float sinTheta = sqrt(max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    const vec3 w = axis / d;
    const vec3 t = anyTangent(w);
    const float phi = kTwoPiEmitter * u.z;
    s.wi = normalize(cosTheta * w + sinTheta * (cos(phi) * t + sin(phi) * cross(w, t)));
    // The near intersection of the sampled direction with the sphere.
    const float b = dot(axis, s.wi);
    const vec3 closest = axis - b * s.wi;
    const float h2 = max(0.0, r * r - dot(closest, closest));
    s.distance = b - sqrt(h2);
    s.radiance = e.radiance;
    s.pdf = e.pmf / (kTwoPiEmitter * oneMinusCosMax);
    return s;
  }
  // Uniform on the triangle: b0 = 1 - sqrt(u), b1 = v sqrt(u) (Turk 1990).
  const float su = sqrt(u.y);
  const vec3 y = (1.0 - su) * e.p0 + (u.z * su) * e.p1 + (su - u.z * su) * e.p2;
  const vec3 n = normalize(cross(e.p1 - e.p0, e.p2 - e.p0));
  const vec3 toY = y - x;
  const float d2 = dot(toY, toY);
  s.distance = sqrt(d2);
  s.wi = toY / s.distance;
  const float cosL = -dot(n, s.wi);
  if (!(cosL > 0.0) || !(s.distance > 0.0)) return s;  // its back face, or degenerate
  s.radiance = e.radiance;
  s.pdf = e.pmf * d2 / (e.area * cosL);
  return s;
}

#endif
