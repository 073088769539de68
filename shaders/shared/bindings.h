// Descriptor bindings (set 0) shared by every kernel, and the specialization-constant ids.
#ifndef RAYLAB_SHARED_BINDINGS_H
#define RAYLAB_SHARED_BINDINGS_H

#include "compat.h"

RL_NAMESPACE_BEGIN

// Scene: filled once per scene by engine/render/gpu_scene.cpp.
RL_CONST uint kBindingTlas = 0;
RL_CONST uint kBindingInstances = 1;  // InstanceRecord[], indexed by the instance custom index
RL_CONST uint kBindingPositions = 2;  // vec3[] object-space positions of every mesh, concatenated
RL_CONST uint kBindingNormals = 3;    // vec3[] per-vertex normals (same indexing as positions)
RL_CONST uint kBindingUvs = 4;        // vec2[] TEXCOORD_0 (same indexing as positions)
RL_CONST uint kBindingIndices = 5;    // uint[] triangle indices, relative to InstanceRecord.firstVertex
RL_CONST uint kBindingSpheres = 6;    // SphereRecord[]
RL_CONST uint kBindingMaterials = 7;  // MaterialRecord[]
RL_CONST uint kBindingLights = 8;     // LightRecord[]: every light, with the light-selection cdf
RL_CONST uint kBindingTextures = 13;  // TextureRecord[]
RL_CONST uint kBindingTexels = 14;    // uint[] RGBA8 texels of every texture, concatenated
RL_CONST uint kBindingMaterialTextures = 25;  // MaterialTextures[], indexed by MaterialRecord.textures
RL_CONST uint kBindingUvs1 = 26;      // vec2[] TEXCOORD_1 (same indexing as positions)
RL_CONST uint kBindingTangents = 27;  // vec4[] tangents, w the bitangent's sign (same indexing as positions)
RL_CONST uint kBindingEnvironment = 18;  // EnvironmentHeader, then the image and its sampling tables
// The BRDF library's tables (shared/brdf_tables.h), bound for every kernel that evaluates BRDFs.
RL_CONST uint kBindingBrdfTables = 24;

// Per-kernel outputs.
RL_CONST uint kBindingAccumulation = 9;  // vec4[] running sum of radiance samples per pixel
RL_CONST uint kBindingRayStats = 10;     // RayStats, counters reset before every dispatch
RL_CONST uint kBindingAovs = 28;         // vec4[2 per pixel]: sums of first-hit albedo and normal (kFeatureAovs)
RL_CONST uint kBindingHeatmap = 23;      // render_heatmap.comp: float[] clock ticks per pixel, summed over samples
RL_CONST uint kBindingProbeRays = 11;    // trace_rays.comp: ProbeRay[] in
RL_CONST uint kBindingProbeHits = 12;    // trace_rays.comp: ProbeHit[] out
RL_CONST uint kBindingBrdfCases = 13;    // brdf_eval.comp: BrdfEvalCase[] in
RL_CONST uint kBindingBrdfValues = 14;   // brdf_eval.comp: BrdfEvalValue[] out
RL_CONST uint kBindingBrdfUniforms = 15; // brdf_sample.comp: vec3[] uniform numbers in [0, 1), one per sample
RL_CONST uint kBindingBrdfSamples = 16;  // brdf_sample.comp: BrdfSampleValue[] out

RL_NAMESPACE_END

#endif
