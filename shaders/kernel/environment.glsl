// The environment around the scene: an equirectangular image, +Y up (docs/integrators.md, "Environment light"),
// or, without one, the uniform background radiance. A world direction d, turned by -rotation about +Y into the
// image's frame, looks up u = atan2(d.x, -d.z) / 2pi in [0, 1), v = acos(d.y) / pi, bilinear between texel
// centres. sampleEnvironment draws directions from the piecewise-constant density of
// engine/scene/environment_tables.h (pdf f / fMean / (2 pi^2 sin theta) per unit solid angle).
#ifndef RAYLAB_KERNEL_ENVIRONMENT_GLSL
#define RAYLAB_KERNEL_ENVIRONMENT_GLSL

#include "common/specialization.glsl"
#include "kernel/payload.glsl"

const float kPiEnvironment = 3.14159265358979324;

struct EnvironmentSample {
  vec3 wi;        // unit, towards the environment
  vec3 radiance;  // arriving along -wi
  float pdf;      // solid angle; 0: no sample
};

bool hasEnvironmentImage() { return featureEnabled(kFeatureEnvironment) && environment.width > 0u; }

// World to the image's frame and back: a rotation about +Y by -rotation (or +rotation).
vec3 rotateY(vec3 d, float angle) {
  const float c = cos(angle), s = sin(angle);
  return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

vec2 environmentUv(vec3 e) {
  float u = atan(e.x, -e.z) / (2.0 * kPiEnvironment);
  if (u < 0.0) u += 1.0;
  if (u >= 1.0) u = 0.0;
  // acos(e.y) as atan: lavapipe's acos is off by up to 1e-4 rad, its atan by about 1e-7.
  return vec2(u, atan(length(e.xz), e.y) / kPiEnvironment);
}

// Offsets into environmentData (shared/scene_records.h, EnvironmentHeader).
uint environmentTexels() { return environment.width * environment.height; }
uint fOffset() { return 3u * environmentTexels(); }
uint rowCdfOffset() { return 4u * environmentTexels(); }
uint marginalOffset() { return 5u * environmentTexels(); }

vec3 environmentTexel(int x, int y) {
  const int w = int(environment.width), h = int(environment.height);
  x = x < 0 ? x + w : (x >= w ? x - w : x);  // wraps around in u
  y = clamp(y, 0, h - 1);                    // clamps at the poles
  const uint i = 3u * uint(y * w + x);
  return vec3(environmentData[i], environmentData[i + 1u], environmentData[i + 2u]);
}

// Radiance arriving from world direction d (the background when there is no image).
vec3 environmentRadiance(vec3 d) {
  if (!hasEnvironmentImage()) return params.background;
  const vec2 uv = environmentUv(rotateY(d, -params.environmentRotation));
  const vec2 texel = uv * vec2(environment.width, environment.height) - 0.5;
  const vec2 base = floor(texel);
  const vec2 t = texel - base;
  const int x = int(base.x), y = int(base.y);
  const vec3 top = mix(environmentTexel(x, y), environmentTexel(x + 1, y), t.x);
  const vec3 bottom = mix(environmentTexel(x, y + 1), environmentTexel(x + 1, y + 1), t.x);
  return params.environmentStrength * mix(top, bottom, t.y);
}

// True when sampleEnvironment has something to draw (an image that is not black).
bool environmentSamplable() {
  return hasEnvironmentImage() && environment.fMean > 0.0 && params.environmentStrength > 0.0;
}

// The solid-angle density of a direction in a texel of density f, at polar angle theta: f / fMean per unit
// (u, v) area, over the 2 pi^2 sin(theta) of the map's Jacobian.
float solidAngleDensity(float f, float sinTheta) {
  return f / (environment.fMean * 2.0 * kPiEnvironment * kPiEnvironment * sinTheta);
}

// Density per unit solid angle of sampleEnvironment producing world direction d.
float environmentPdf(vec3 d) {
  if (!environmentSamplable()) return 0.0;
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
EnvironmentSample sampleEnvironment(vec2 u) {
  EnvironmentSample s;
  s.pdf = 0.0;
  s.radiance = vec3(0.0);
  s.wi = vec3(0.0, 1.0, 0.0);
  if (!environmentSamplable()) return s;
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
  s.pdf = solidAngleDensity(f, sinTheta);
  s.radiance = environmentRadiance(s.wi);
  return s;
}

#endif
