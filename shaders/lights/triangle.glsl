// An emitting triangle, in world space: p0, p1, p2 its vertices (counter-clockwise seen from the emitting front),
// radiance its L_e, area its area. A point uniform by area (b0 = 1 - sqrt(u), b1 = v sqrt(u), Turk 1990); the
// density per unit solid angle at x is r^2 / (A cos theta_l). With an emissive texture, L_e is its material's at
// the point's UVs (kernel/emission.glsl); the texture weighs which triangle is chosen (its mean over the triangle,
// engine/render/light_records.cpp), not where on it the point falls.
#ifndef RAYLAB_LIGHTS_TRIANGLE_GLSL
#define RAYLAB_LIGHTS_TRIANGLE_GLSL

#include "kernel/emission.glsl"
#include "kernel/surface.glsl"
#include "lights/light_sample.glsl"

// The shadow ray stops this fraction short of an emitter's point: the emitter is scene geometry too.
const float kShortOfEmitter = 1e-4;

LightSample triangleLightSample(LightRecord light, vec3 x, vec3 u) {
  const float su = sqrt(u.x);
  const vec2 b = vec2(u.y * su, su - u.y * su);  // of p1 and p2
  const vec3 y = (1.0 - b.x - b.y) * light.p0 + b.x * light.p1 + b.y * light.p2;
  const vec3 n = normalize(cross(light.p1 - light.p0, light.p2 - light.p0));
  const vec3 toY = y - x;
  const float d2 = dot(toY, toY);
  LightSample s = noLightSample();
  const float distance = sqrt(d2);
  s.wi = toY / distance;
  const float cosL = -dot(n, s.wi);
  if (!(cosL > 0.0) || !(distance > 0.0)) return s;  // its back face, or degenerate
  s.distance = distance * (1.0 - kShortOfEmitter);
  s.radiance = light.radiance;
  if (featureEnabled(kFeatureTextures) && light.texturedInstance != kNoInstance) {
    const InstanceRecord instance = instances[light.texturedInstance];
    vec2 uv0, uv1;
    triangleUvsAt(instance, light.primitive, b, uv0, uv1);
    s.radiance = coveredEmittedRadiance(materials[instance.material], uv0, uv1);
  }
  s.pdf = d2 / (light.area * cosL);
  s.delta = false;
  return s;
}

// The density of reaching point y of the triangle from x along wi.
float triangleLightPdf(LightRecord light, vec3 x, vec3 wi, vec3 y) {
  const vec3 n = normalize(cross(light.p1 - light.p0, light.p2 - light.p0));
  const vec3 toY = y - x;
  const float d2 = dot(toY, toY);
  const float cosL = abs(dot(n, toY)) * inversesqrt(d2);
  return cosL > 0.0 ? d2 / (light.area * cosL) : 0.0;
}

#endif
