// The auxiliary images a denoiser reads beside the colour (kFeatureAovs; docs/integrators.md, "Auxiliary images"):
// for every sample, the albedo and the shading normal where its camera ray first met the scene, summed per pixel by
// the same samples as the radiance, so that they are antialiased and masked exactly as the image is. Open Image
// Denoise keeps the detail these images show (texture, edges, normals) and smooths the rest.
// - Albedo of a surface that is not specular-only: the share of light it reflects towards the viewer, mixed with the
//   mirror weight as both integrators shade (the slides' f_r lit by the lights plus delta times the mirror image;
//   the path integrator's mixture f = (1 - delta) f_r + delta mirror): delta + (1 - delta) rho(wo), rho the
//   directional albedo of f_r, estimated by one BSDF sample's weight f |cos| / pdf per sample (exactly the diffuse
//   colour for Lambert). The sample's random numbers depend on the sample index but not on the pixel: each pixel's
//   estimate has an error, but the same points give neighbouring pixels the same error, so the image is smooth. The
//   denoiser takes the auxiliary images as noise-free (OIDN's cleanAux); the path's own continuation sample, drawn
//   afresh per pixel, left the albedo of a glossy sphere speckled and the denoised image with it. The stream is
//   one no other sample draws from, so that the colour stays the same bit for bit with the feature on or off.
// - Glass and other specular-only surfaces: 1, as Open Image Denoise's documentation advises for them.
// - A camera ray that leaves the scene: the radiance it sees, clamped to 1; normal 0.
// Normals are in world space, facing the camera.
#ifndef RAYLAB_KERNEL_AOV_GLSL
#define RAYLAB_KERNEL_AOV_GLSL

#include "brdf/bsdf.glsl"
#include "common/specialization.glsl"
#include "kernel/payload.glsl"

// The albedo samples come from the dimensions of this path vertex, deeper than any path goes
// (--max-depth is at most 64).
const uint kAovRngVertex = 1024u;

// True at the vertex whose albedo and normal the images keep: the camera ray's first hit (or miss).
bool recordsAov(Payload p) { return featureEnabled(kFeatureAovs) && p.path.depth == 0u; }

void recordAov(inout Payload p, vec3 albedo, vec3 normalFacingViewer) {
  p.aovAlbedo = clamp(albedo, 0.0, 1.0);
  p.aovNormal = normalFacingViewer;
}

// delta + (1 - delta) times one estimate of f_r's directional albedo at woLocal, from a BSDF sample on the
// pixel-independent stream described above.
vec3 firstHitAlbedo(Payload p, MaterialRecord material, vec3 woLocal, float delta) {
  Rng aovRng = p.path.rng;
  aovRng.key.x = 0u;  // the packed pixel (common/rng.glsl): every pixel draws the same points
  rngStartVertex(aovRng, kAovRngVertex);
  const BsdfSample b = bsdfSample(material, woLocal, rngNext4(aovRng).xyz);
  const vec3 weight = b.pdf > 0.0 ? b.f * (abs(b.wi.z) / b.pdf) : vec3(0.0);
  return delta + (1.0 - delta) * weight;
}

// n turned to the side of the surface w (towards the viewer) is on.
vec3 facing(vec3 n, vec3 w) { return dot(n, w) < 0.0 ? -n : n; }

#endif
