// Spot light (glTF KHR_lights_punctual "spot"): p0 its position, p1 the unit direction light travels, radiance
// its intensity I in W/sr inside the inner cone, p2 = (cos inner angle, cos outer angle, 0).
#ifndef RAYLAB_LIGHTS_SPOT_GLSL
#define RAYLAB_LIGHTS_SPOT_GLSL

#include "lights/light_sample.glsl"

// glTF KHR_lights_punctual's recommended cone falloff: a squared linear ramp in cos between the cones.
float spotFalloff(LightRecord light, vec3 wi) {
  const float cosAngle = dot(-wi, light.p1);
  // Equal cones would divide by zero: the ramp then becomes a hard edge.
  const float scale = 1.0 / max(1e-4, light.p2.x - light.p2.y);
  const float ramp = clamp((cosAngle - light.p2.y) * scale, 0.0, 1.0);
  return ramp * ramp;
}

LightSample spotLightSample(LightRecord light, vec3 x, vec3 u) {
  LightSample s = punctualSample(light.p0, light.radiance, x);
  s.radiance *= spotFalloff(light, s.wi);
  return s;
}

#endif
