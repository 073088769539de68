// Per-dispatch parameters of the render kernel (push constants) and its ray counters.
#ifndef RAYLAB_SHARED_FRAME_H
#define RAYLAB_SHARED_FRAME_H

#include "compat.h"

RL_NAMESPACE_BEGIN

// Workgroup sizes of the compute entry points, used by their layout qualifiers and by the host's dispatches.
RL_CONST uint kRenderWorkgroupSize = 8;  // render.comp, render_heatmap.comp: kRenderWorkgroupSize squared
RL_CONST uint kProbeWorkgroupSize = 64;  // trace_rays.comp

// FrameParams.flags
RL_CONST uint kFrameJitter = 1;  // jittered sub-pixel positions (anti-aliasing); else pixel centres

// A pinhole camera: the ray through normalised device coordinates (x, y) in [-1, 1]^2 has direction
// cameraForward + x cameraRight + y cameraUp; right and up are pre-scaled by the field of view.
struct FrameParams {
  vec3 cameraOrigin;
  uint width;
  vec3 cameraRight;
  uint height;
  vec3 cameraUp;
  uint seed;
  vec3 cameraForward;
  uint sampleIndex;  // the first sample of every pixel this dispatch adds; keys the RNG
  vec3 background;   // radiance of rays that miss everything
  uint maxDepth;     // bounces after the primary hit
  uint lightCount;  // LightRecords: the light-selection distribution's support
  uint flags;
  float throughputCutoff;  // a path whose throughput drops below this stops
  uvec2 tileOrigin;  // first pixel of this dispatch; tiles are multiples of the 8x8 workgroup
  uint sampleCount;  // samples sampleIndex, sampleIndex + 1, ... this dispatch adds to each pixel
  uint punctualLightCount;  // the first LightRecords: the delta lights the slides' integrator sums
  float environmentStrength;  // multiplies the environment image
  float environmentRotation;  // radians about +Y: the image turned counter-clockwise seen from above
};
RL_CHECK_SIZE(FrameParams, 116);

struct RayStats {
  uint primaryRays;
  uint shadowRays;
  uint secondaryRays;
  uint droppedSamples;  // NaN or Inf samples left out of the image
  // Lane utilisation (the ray-query backend; the pipeline's stages have no subgroup operations): path segments
  // the lanes traced, and the segments their groups spent, the longest lane's count between two points where the
  // lanes join again. Utilisation = laneSegments / (subgroup size x groupSegments).
  uint laneSegments;
  uint groupSegments;
};
RL_CHECK_SIZE(RayStats, 24);

// trace_rays.comp: one ray in, its closest hit out.
struct ProbeRay {
  vec3 origin;
  float tMin;
  vec3 direction;
  float tMax;
};
RL_CHECK_SIZE(ProbeRay, 32);

RL_CONST uint kProbeMiss = 0xFFFFFFFFu;

// ProbeParams.mode
RL_CONST uint kProbeClosest = 0;       // closest hit with the surface reconstructed, as closestHit sees it
RL_CONST uint kProbeOcclusion = 1;     // shadow-ray query: instance 0 when blocked, kProbeMiss when clear
RL_CONST uint kProbeClosestBare = 2;   // closest hit distance and ids only: the bare cost of traversal

struct ProbeParams {
  uint rayCount;
  uint mode;
};
RL_CHECK_SIZE(ProbeParams, 8);

struct ProbeHit {
  float t;
  uint instance;   // instance custom index, kProbeMiss on a miss
  uint primitive;
  uint frontFace;  // 1 when the ray hit the outside of the surface
  vec3 position;   // world-space hit point as the kernel reconstructs it
  uint reserved;
  vec3 geometricNormal;  // world space, unit length, outward
  uint reserved2;
};
RL_CHECK_SIZE(ProbeHit, 48);

RL_NAMESPACE_END

#endif
