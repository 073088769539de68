// Directional light (glTF KHR_lights_punctual "directional"): p1 the unit direction light travels, radiance the
// irradiance E in W/m^2 it delivers to a surface facing it.
#ifndef RAYLAB_LIGHTS_DIRECTIONAL_GLSL
#define RAYLAB_LIGHTS_DIRECTIONAL_GLSL

#include "lights/light_sample.glsl"

LightSample directionalLightSample(LightRecord light, vec3 x, vec3 u) {
  LightSample s;
  s.wi = -light.p1;
  s.distance = kRayTMax;
  s.radiance = light.radiance;
  s.pdf = 1.0;
  s.delta = true;
  return s;
}

#endif
