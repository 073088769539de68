// The ray-tracing-pipeline backend's shared layout: payload locations, miss programs, and the data a hit-group
// record of the shader binding table carries after its handle (OptiX's SBT record data).
#ifndef RAYLAB_SHARED_RAY_TRACING_H
#define RAYLAB_SHARED_RAY_TRACING_H

#include "compat.h"

RL_NAMESPACE_BEGIN

// Payload locations: the path (or probe hit) of the raygen's rays, and the visibility of shadow rays.
RL_CONST int kPayloadPath = 0;  // int: traceRayEXT takes the location as an int constant
RL_CONST int kPayloadShadow = 1;

// Miss programs, in the order of the SBT's miss region.
RL_CONST uint kMissPath = 0;    // the path leaves the scene: miss()
RL_CONST uint kMissShadow = 1;  // the shadow ray reached its light: visible

// Hit groups, in the order the pipeline lists them; each TLAS instance's SBT record uses the group of its
// geometry kind (InstanceRecord.geometryKind).
RL_CONST uint kHitGroupTriangles = 0;
RL_CONST uint kHitGroupSpheres = 1;  // procedural: the sphere intersection program

// What a hit-group record carries after its handle: one record per TLAS instance (the instance's
// instanceShaderBindingTableRecordOffset is its index), holding what the ray-query backend reads from the
// instance custom index.
struct HitGroupData {
  uint instance;  // the InstanceRecord of this TLAS instance
};
RL_CHECK_SIZE(HitGroupData, 4);

RL_NAMESPACE_END

#endif
