// What every kind of light gives next event estimation (shaders/lights/<kind>.glsl, dispatched by
// generated/light_dispatch.glsl): a direction, how far a shadow ray may go along it, the radiance arriving and
// its density. Delta lights (points, directions) give the irradiance they deliver at normal incidence and
// density 1, as pbrt-v4's LightLiSample does for them.
#ifndef RAYLAB_LIGHTS_LIGHT_SAMPLE_GLSL
#define RAYLAB_LIGHTS_LIGHT_SAMPLE_GLSL

#include "kernel/payload.glsl"

struct LightSample {
  vec3 wi;          // unit, from the shading point towards the light
  float distance;   // free length of the shadow ray: short of an emitting surface, kRayTMax for a direction
  vec3 radiance;    // L_e arriving along -wi; a delta light's irradiance at normal incidence, unoccluded
  float pdf;        // per unit solid angle, without the light's selection probability; 1 for delta lights; 0: none
  bool delta;       // a point or a direction: no continuation can reach it, so no MIS weight
};

LightSample noLightSample() {
  LightSample s;
  s.wi = vec3(0.0, 0.0, 1.0);
  s.distance = 0.0;
  s.radiance = vec3(0.0);
  s.pdf = 0.0;
  s.delta = true;
  return s;
}

// A point source of intensity I (W/sr) at `position` seen from x: E = I / r^2 along the unit direction to it.
LightSample punctualSample(vec3 position, vec3 intensity, vec3 x) {
  const vec3 toLight = position - x;
  const float distance2 = dot(toLight, toLight);
  if (!(distance2 > 0.0)) return noLightSample();  // a light exactly on the surface: no direction
  LightSample s;
  s.distance = sqrt(distance2);
  s.wi = toLight / s.distance;
  s.radiance = intensity / distance2;
  s.pdf = 1.0;
  s.delta = true;
  return s;
}

#endif
