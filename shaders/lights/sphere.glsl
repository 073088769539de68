// An emitting sphere, in world space: p0 its centre, p1.x its radius, radiance its L_e (with an emissive texture:
// its material's at the point's UVs, kernel/emission.glsl). A direction uniform in
// the cone of directions from x that reach it (Shirley et al. 1996; pbrt-v4's SampleSphere): density
// 1 / (2 pi (1 - cos theta_max)) per unit solid angle, 0 from inside, whose back faces emit nothing.
#ifndef RAYLAB_LIGHTS_SPHERE_GLSL
#define RAYLAB_LIGHTS_SPHERE_GLSL

#include "lights/triangle.glsl"  // kShortOfEmitter
#include "common/frame.glsl"

const float kTwoPiSphereLight = 6.28318530717958648;

// 1 - cos(theta_max) of the cone a sphere of radius r subtends at distance d > r, without cancellation for
// small spheres: sin^2 / (1 + cos).
float sphereConeOneMinusCos(float r, float d) {
  const float sin2 = (r * r) / (d * d);
  return sin2 / (1.0 + sqrt(max(0.0, 1.0 - sin2)));
}

LightSample sphereLightSample(LightRecord light, vec3 x, vec3 u) {
  LightSample s = noLightSample();
  const vec3 axis = light.p0 - x;
  const float d = length(axis);
  const float r = light.p1.x;
  if (d <= r) return s;
  const float oneMinusCosMax = sphereConeOneMinusCos(r, d);
  const float oneMinusCos = u.x * oneMinusCosMax;
  const float cosTheta = 1.0 - oneMinusCos;
  const float sinTheta = sqrt(max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
  const vec3 w = axis / d;
  const vec3 t = anyTangent(w);
  const float phi = kTwoPiSphereLight * u.y;
  s.wi = normalize(cosTheta * w + sinTheta * (cos(phi) * t + sin(phi) * cross(w, t)));
  // The near intersection of the sampled direction with the sphere.
  const float b = dot(axis, s.wi);
  const vec3 closest = axis - b * s.wi;
  const float h2 = max(0.0, r * r - dot(closest, closest));
  s.distance = (b - sqrt(h2)) * (1.0 - kShortOfEmitter);
  s.radiance = light.radiance;
  if (featureEnabled(kFeatureTextures) && light.texturedInstance != kNoInstance) {
    // The spheres' instance has the identity transform: world and object space agree.
    const vec3 normal = (x + (b - sqrt(h2)) * s.wi - light.p0) / r;
    const SphereRecord sphere = spheres[instances[light.texturedInstance].firstSphere + light.primitive];
    const vec2 uv = sphereUv(normal);
    s.radiance = coveredEmittedRadiance(materials[sphere.material], uv, uv);
  }
  s.pdf = 1.0 / (kTwoPiSphereLight * oneMinusCosMax);
  s.delta = false;
  return s;
}

float sphereLightPdf(LightRecord light, vec3 x, vec3 wi, vec3 y) {
  const float d = length(light.p0 - x);
  if (d <= light.p1.x) return 0.0;
  return 1.0 / (kTwoPiSphereLight * sphereConeOneMinusCos(light.p1.x, d));
}

#endif
