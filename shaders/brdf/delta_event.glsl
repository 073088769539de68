// What a delta BSDF (a model whose lobes are `specular` only) tells the integrators about one arriving direction:
// its two delta directions and the Fresnel weight between them. The integrators combine these with the mirror
// weight delta (bsdfSampleSpecular, and the slides' integrator's split).
#ifndef RAYLAB_BRDF_DELTA_EVENT_GLSL
#define RAYLAB_BRDF_DELTA_EVENT_GLSL

struct DeltaEvent {
  float fresnelExact;         // the exact unpolarised F; 1 under total internal reflection
  float fresnelSchlick;       // Schlick with the cosine on the optically thinner (outside) side; 1 under TIR
  float fresnelSchlickNaive;  // Schlick with cos_i always (the common student form)
  bool tir;
  vec3 reflected;             // 2 cos_i nn - wi
  vec3 refracted;             // zero under TIR
  vec3 transmittance;         // applied to the refracted branch as it enters
};

DeltaEvent noDeltaEvent() {
  return DeltaEvent(0.0, 0.0, 0.0, false, vec3(0.0), vec3(0.0), vec3(0.0));
}

#endif
