// Punctual lights: the direction towards the light, its distance and the irradiance it delivers to a
// surface facing it, before the cosine and visibility. Point and spot intensity is W/sr, so
// E = I / r^2; directional lights carry irradiance directly.
#ifndef RAYLAB_KERNEL_LIGHTS_GLSL
#define RAYLAB_KERNEL_LIGHTS_GLSL

#include "kernel/payload.glsl"

struct LightSample {
  vec3 wi;          // unit, from the surface towards the light
  float distance;   // kRayTMax for directional lights
  vec3 irradiance;  // at normal incidence, unoccluded
};

// glTF KHR_lights_punctual's recommended cone falloff: a squared linear ramp in cos between the cones.
float spotFalloff(LightRecord light, vec3 wi) {
  const float cosAngle = dot(-wi, light.direction);
  const float scale = 1.0 / max(1e-4, light.cosInner - light.cosOuter);
  const float ramp = clamp((cosAngle - light.cosOuter) * scale, 0.0, 1.0);
  return ramp * ramp;
}

LightSample sampleLight(LightRecord light, vec3 position) {
  LightSample s;
  if (light.type == kLightDirectional) {
    s.wi = -light.direction;
    s.distance = kRayTMax;
    s.irradiance = light.intensity;
    return s;
  }
  const vec3 toLight = light.position - position;
  const float distance2 = dot(toLight, toLight);
  s.distance = sqrt(distance2);
  s.wi = toLight / s.distance;
  s.irradiance = light.intensity / distance2;
  if (light.type == kLightSpot) s.irradiance *= spotFalloff(light, s.wi);
  return s;
}

#endif
