// Headlight: a point light carried with the camera, so it lights whatever the camera sees (files without lights
// get one, docs/scenes.md). p0 is its offset along the camera's right, up and forward axes in world units,
// radiance its intensity in W/sr. Needs `params` (FrameParams) for the camera of this frame.
#ifndef RAYLAB_LIGHTS_HEADLIGHT_GLSL
#define RAYLAB_LIGHTS_HEADLIGHT_GLSL

#include "lights/light_sample.glsl"

LightSample headlightLightSample(LightRecord light, vec3 x, vec3 u) {
  const vec3 position = params.cameraOrigin + light.p0.x * normalize(params.cameraRight) +
                        light.p0.y * normalize(params.cameraUp) + light.p0.z * params.cameraForward;
  return punctualSample(position, light.radiance, x);
}

#endif
