// Punctual lights: the direction towards the light, its distance and the irradiance it delivers to a
// surface facing it, before the cosine and visibility. Point and spot intensity is W/sr, so
// E = I / r^2; directional lights carry irradiance directly. Light types a scene lacks compile away.
#ifndef RAYLAB_KERNEL_LIGHTS_GLSL
#define RAYLAB_KERNEL_LIGHTS_GLSL

#include "common/specialization.glsl"
#include "kernel/payload.glsl"

struct LightSample {
  vec3 wi;          // unit, from the surface towards the light
  float distance;   // kRayTMax for directional lights
  vec3 irradiance;  // at normal incidence, unoccluded
};

// glTF KHR_lights_punctual's recommended cone falloff: a squared linear ramp in cos between the cones.
float spotFalloff(LightRecord light, vec3 wi) {
  const float cosAngle = dot(-wi, light.direction);
  // Equal cones would divide by zero: the ramp then becomes a hard edge.
  const float scale = 1.0 / max(1e-4, light.cosInner - light.cosOuter);
  const float ramp = clamp((cosAngle - light.cosOuter) * scale, 0.0, 1.0);
  return ramp * ramp;
}

LightSample sampleLight(LightRecord light, vec3 position) {
  LightSample s;
  if (featureEnabled(kFeatureDirectionalLights) && light.type == kLightDirectional) {
    s.wi = -light.direction;
    s.distance = kRayTMax;
    s.irradiance = light.intensity;
    return s;
  }
  const vec3 toLight = light.position - position;
  const float distance2 = dot(toLight, toLight);
  if (!(distance2 > 0.0)) {  // a light exactly on the surface: no direction, no contribution
    s.wi = vec3(0.0);
    s.distance = 0.0;
    s.irradiance = vec3(0.0);
    return s;
  }
  s.distance = sqrt(distance2);
  s.wi = toLight / s.distance;
  s.irradiance = light.intensity / distance2;
  if (featureEnabled(kFeatureSpotLights) && light.type == kLightSpot) s.irradiance *= spotFalloff(light, s.wi);
  return s;
}

#endif
