// The one payload the OptiX-shaped programs share, and the hit attributes closestHit receives.
#ifndef RAYLAB_KERNEL_PAYLOAD_GLSL
#define RAYLAB_KERNEL_PAYLOAD_GLSL

#include "common/rng.glsl"

// The far end of rays that should go on forever (primary rays, directional-light shadow rays).
const float kRayTMax = 3.0e38;

// A path in flight. The raygen traces (origin, direction); closestHit or miss add what they see to
// `radiance` and either set up the next segment or mark the path done. Glass splits a path in two: the second
// continuation goes in the `split*` fields and the raygen keeps it for later. No recursion: the raygen loops.
struct Payload {
  vec3 radiance;    // gathered so far, already weighted by the throughput of the segment that saw it
  vec3 throughput;  // weight of whatever the next segment brings back
  vec3 origin;      // the next segment
  vec3 direction;   // unit length
  uint depth;       // bounces taken after the primary hit
  bool done;
  bool split;       // closestHit left a second continuation below
  vec3 splitOrigin;
  vec3 splitDirection;
  vec3 splitThroughput;
  Rng rng;
  uint shadowRays;
  // The path integrator's last scattering vertex, for MIS of the emitter a continuation reaches: where it was,
  // the solid-angle density with which the continuation was sampled, and whether that was a delta event
  // (camera ray, mirror, glass), which light sampling cannot produce.
  vec3 lastPosition;
  float lastPdf;
  bool lastSpecular;
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
