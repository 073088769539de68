// The one payload the OptiX-shaped programs share, and the hit attributes closestHit receives.
#ifndef RAYLAB_KERNEL_PAYLOAD_GLSL
#define RAYLAB_KERNEL_PAYLOAD_GLSL

#include "common/rng.glsl"
#include "shared/guiding.h"

// The far end of rays that should go on forever (primary rays, directional-light shadow rays).
const float kRayTMax = 3.0e38;

// A path in flight. The raygen traces (path.origin, path.direction); closestHit or miss add what they see to
// `path.radiance` and either set up the next segment or mark the path done. Glass splits a path in two: the second
// continuation goes in the `split*` fields and the raygen keeps it for later. No recursion: the raygen loops.
struct Payload {
  PathState path;   // what lives on between segments (shared/path_state.h)
  bool done;
  bool split;       // closestHit left a second continuation below
  vec3 splitOrigin;
  vec3 splitDirection;
  vec3 splitThroughput;
  // What the camera ray's first hit showed the denoiser (kernel/aov.glsl), set there with kFeatureAovs.
  vec3 aovAlbedo;
  vec3 aovNormal;
  // With kFeatureGuiding while the guide trains: the continuation closestHit just drew, for the raygen to keep
  // (kernel/guide_training.glsl); its bin follows from path.direction.
  bool guideRecorded;
  GuideRecord guideRecord;
};

// What the traversal knows about the committed hit (OptiX: attributes and built-ins).
struct Hit {
  float t;
  uint instance;  // instance custom index: the InstanceRecord
  uint primitive;
  vec2 barycentrics;  // triangles only
  vec3 objectOrigin;  // the ray in the instance's object space; t is the same in both spaces
  vec3 objectDirection;
  mat4x3 objectToWorld;
  mat4x3 worldToObject;
};

float maxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }

#endif
