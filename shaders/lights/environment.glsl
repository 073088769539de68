// The environment image as a light: directions drawn in proportion to the piecewise-constant density of
// engine/scene/environment_tables.h (pdf f / fMean / (2 pi^2 sin theta) per unit solid angle), the row from the
// marginal cdf, then the column within it. The record carries nothing: the image and its tables are the
// environment binding (kernel/environment.glsl), and the light exists only when the image is not black.
#ifndef RAYLAB_LIGHTS_ENVIRONMENT_GLSL
#define RAYLAB_LIGHTS_ENVIRONMENT_GLSL

#include "kernel/environment.glsl"
#include "lights/light_sample.glsl"

// The solid-angle density of a direction in a texel of density f, at polar angle theta: f / fMean per unit
// (u, v) area, over the 2 pi^2 sin(theta) of the map's Jacobian.
float solidAngleDensity(float f, float sinTheta) {
  return f / (environment.fMean * 2.0 * kPiEnvironment * kPiEnvironment * sinTheta);
}

// Density per unit solid angle of environmentLightSample producing world direction d.
float environmentLightPdf(LightRecord light, vec3 shadingPoint, vec3 d, vec3 lightPoint) {
  const vec3 e = rotateY(d, -params.environmentRotation);
  const float sinTheta = sqrt(max(0.0, 1.0 - e.y * e.y));
  if (!(sinTheta > 0.0)) return 0.0;
  const vec2 uv = environmentUv(e);
  const uint x = min(uint(uv.x * float(environment.width)), environment.width - 1u);
  const uint y = min(uint(uv.y * float(environment.height)), environment.height - 1u);
  return solidAngleDensity(environmentData[fOffset() + y * environment.width + x], sinTheta);
}

// The first of `count` entries from `offset` whose inclusive cdf exceeds u: a binary search.
uint searchCdf(uint offset, uint count, float u) {
  uint low = 0u, high = count - 1u;
  while (low < high) {
    const uint mid = (low + high) / 2u;
    if (u < environmentData[offset + mid]) high = mid;
    else low = mid + 1u;
  }
  return low;
}

// Where u falls inside entry i of a cdf, in [0, 1).
float withinEntry(uint offset, uint i, float u) {
  const float before = i > 0u ? environmentData[offset + i - 1u] : 0.0;
  const float width = environmentData[offset + i] - before;
  return width > 0.0 ? clamp((u - before) / width, 0.0, 0.99999994) : 0.5;
}

// A direction drawn in proportion to f: the row from the marginal cdf, then the column within it.
LightSample environmentLightSample(LightRecord light, vec3 shadingPoint, vec3 u) {
  LightSample s = noLightSample();
  const uint w = environment.width, h = environment.height;
  const uint y = searchCdf(marginalOffset(), h, u.y);
  const float v = (float(y) + withinEntry(marginalOffset(), y, u.y)) / float(h);
  const uint rowOffset = rowCdfOffset() + y * w;
  const uint x = searchCdf(rowOffset, w, u.x);
  const float uu = (float(x) + withinEntry(rowOffset, x, u.x)) / float(w);
  const float theta = v * kPiEnvironment, phi = 2.0 * kPiEnvironment * uu;
  const float sinTheta = sin(theta);
  const float f = environmentData[fOffset() + y * w + x];
  if (!(sinTheta > 0.0) || !(f > 0.0)) return s;
  s.wi = rotateY(vec3(sinTheta * sin(phi), cos(theta), -sinTheta * cos(phi)), params.environmentRotation);
  s.distance = kRayTMax;
  s.pdf = solidAngleDensity(f, sinTheta);
  s.radiance = environmentRadiance(s.wi);
  s.delta = false;
  return s;
}

#endif
