// A path between two segments: the part of the one Payload (kernel/payload.glsl) that lives on from one segment
// to the next. The megakernel keeps it in registers; the wavefront (wavefront.comp) stores it as it is, so the two
// cannot drift apart.
#ifndef RAYLAB_SHARED_PATH_STATE_H
#define RAYLAB_SHARED_PATH_STATE_H

#include "compat.h"

RL_NAMESPACE_BEGIN

// The counter-based generator's state (common/rng.glsl).
struct Rng {
  uvec4 key;  // (packed pixel, sample index, seed, next dimension)
};
RL_CHECK_SIZE(Rng, 16);

struct PathState {
  vec3 radiance;      // gathered so far, already weighted by the throughput of the segment that saw it
  uint depth;         // bounces taken after the primary hit
  vec3 throughput;    // weight of whatever the next segment brings back
  uint shadowRays;
  vec3 origin;        // the next segment
  uint segments;      // traced so far
  vec3 direction;     // unit length
  // The path integrator's last scattering vertex, for MIS of the emitter a continuation reaches: where it was,
  // the solid-angle density with which the continuation was sampled, and whether that was a delta event
  // (camera ray, mirror, glass), which light sampling cannot produce (0 or 1).
  uint lastSpecular;
  vec3 lastPosition;
  float lastPdf;
  Rng rng;
  // The absorption coefficient of the medium the next segment travels in (a transmissive material's volume, entered
  // through its surface; zero outside), by which the path integrator attenuates it: Beer-Lambert, exp(-sigma t).
  vec3 absorption;
  uint guideVertices;  // the path's vertices kept for training the guide (kernel/guide_training.glsl)
};
RL_CHECK_SIZE(PathState, 112);

RL_NAMESPACE_END

#endif
