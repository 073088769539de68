// The environment around the scene: an equirectangular image, +Y up (docs/integrators.md, "Environment light"),
// or, without one, the uniform background radiance. A world direction d, turned by -rotation about +Y into the
// image's frame, looks up u = atan2(d.x, -d.z) / 2pi in [0, 1), v = acos(d.y) / pi, bilinear between texel
// centres. Its sampling as a light is lights/environment.glsl.
#ifndef RAYLAB_KERNEL_ENVIRONMENT_GLSL
#define RAYLAB_KERNEL_ENVIRONMENT_GLSL

#include "common/specialization.glsl"
#include "kernel/payload.glsl"

const float kPiEnvironment = 3.14159265358979324;

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

#endif
