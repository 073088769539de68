// Point light (glTF KHR_lights_punctual "point"): p0 its position, radiance its intensity I in W/sr.
#ifndef RAYLAB_LIGHTS_POINT_GLSL
#define RAYLAB_LIGHTS_POINT_GLSL

#include "lights/light_sample.glsl"

LightSample pointLightSample(LightRecord light, vec3 x, vec3 u) { return punctualSample(light.p0, light.radiance, x); }

#endif
