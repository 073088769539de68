// An emitting triangle, in world space: p0, p1, p2 its vertices (counter-clockwise seen from the emitting front),
// radiance its L_e, area its area. A point uniform by area (b0 = 1 - sqrt(u), b1 = v sqrt(u), Turk 1990); the
// density per unit solid angle at x is r^2 / (A cos theta_l).
#ifndef RAYLAB_LIGHTS_TRIANGLE_GLSL
#define RAYLAB_LIGHTS_TRIANGLE_GLSL

#include "lights/light_sample.glsl"

// The shadow ray stops this fraction short of an emitter's point: the emitter is scene geometry too.
const float kShortOfEmitter = 1e-4;

LightSample triangleLightSample(LightRecord light, vec3 x, vec3 u) {
  const float su = sqrt(u.x);
  const vec3 y = (1.0 - su) * light.p0 + (u.y * su) * light.p1 + (su - u.y * su) * light.p2;
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
