// The auxiliary images a denoiser reads beside the colour (kFeatureAovs; docs/integrators.md, "Auxiliary images"):
// for every sample, the albedo and the shading normal where its camera ray first met the scene, summed per pixel by
// the same samples as the radiance, so that they are antialiased and masked exactly as the image is. Open Image
// Denoise keeps the detail these images show (texture, edges, normals) and smooths the rest.
// - Albedo of a surface that is not specular-only: the fraction of light it reflects towards the viewer, estimated
//   as each integrator shades. The path integrator's is the weight f |cos| / pdf of its own continuation sample at
//   that vertex, mixed with the mirror weight as its shading is: delta + (1 - delta) f |cos| / pdf; its mean is the
//   directional albedo, and for Lambert every sample is exactly the diffuse colour. The slides' integrator lights
//   f_r by its point lights and adds delta times the mirror image: the same mixture, with a BSDF sample drawn from
//   a random stream of its own, so that its image stays the same bit for bit with the feature on or off.
// - Glass and other specular-only surfaces: 1, as Open Image Denoise's documentation advises for them.
// - A camera ray that leaves the scene: the radiance it sees, clamped to 1; normal 0.
// Normals are in world space, facing the camera.
#ifndef RAYLAB_KERNEL_AOV_GLSL
#define RAYLAB_KERNEL_AOV_GLSL

#include "common/specialization.glsl"
#include "kernel/payload.glsl"

// The slides' integrator's albedo samples come from the dimensions of this path vertex, deeper than any path goes
// (--max-depth is at most 64).
const uint kAovRngVertex = 1024u;

// True at the vertex whose albedo and normal the images keep: the camera ray's first hit (or miss).
bool recordsAov(Payload p) { return featureEnabled(kFeatureAovs) && p.path.depth == 0u; }

void recordAov(inout Payload p, vec3 albedo, vec3 normalFacingViewer) {
  p.aovAlbedo = clamp(albedo, 0.0, 1.0);
  p.aovNormal = normalFacingViewer;
}

// The sample weight f |cos| / pdf of a BSDF sample, 0 where it failed: one estimate of the directional albedo.
vec3 albedoEstimate(vec3 f, float cosine, float pdf) { return pdf > 0.0 ? f * (abs(cosine) / pdf) : vec3(0.0); }

// n turned to the side of the surface w (towards the viewer) is on.
vec3 facing(vec3 n, vec3 w) { return dot(n, w) < 0.0 ? -n : n; }

#endif
