// The ray-query backend's part of the render programs, shared by its compute entry points (render.comp,
// render_heatmap.comp, wavefront.comp): one path segment as a ray query handed to closestHitProgram or miss, and
// the counters each invocation adds to RayStats, one atomic per subgroup. Needs `params`, `stats` and the scene.
#ifndef RAYLAB_KERNEL_QUERY_SEGMENT_GLSL
#define RAYLAB_KERNEL_QUERY_SEGMENT_GLSL

#include "kernel/trace_query.glsl"
#include "kernel/hit_program.glsl"
#include "kernel/miss.glsl"

void traceSegment(inout Payload p) {
  Hit hit;
  if (traceClosest(p.path.origin, p.path.direction, 0.0, kRayTMax, hit)) {
    closestHitProgram(hit, p);
  } else {
    miss(p);
  }
}

// Adds this invocation's rays (primary, shadow, secondary), dropped samples and path segments to the counters;
// `groupSegments` is the same in every lane of a subgroup (the segments its lanes spent together).
void addRayStats(uvec3 rays, uint dropped, uint laneSegments, uint groupSegments) {
  const uvec3 total = subgroupAdd(rays);
  const uint totalDropped = subgroupAdd(dropped);
  const uint totalLaneSegments = subgroupAdd(laneSegments);
  const uint totalGroupSegments = subgroupMax(groupSegments);
  if (subgroupElect()) {
    if (totalDropped > 0u) atomicAdd(stats.droppedSamples, totalDropped);
    atomicAdd(stats.laneSegments, totalLaneSegments);
    atomicAdd(stats.groupSegments, totalGroupSegments);
    atomicAdd(stats.primaryRays, total.x);
    atomicAdd(stats.shadowRays, total.y);
    atomicAdd(stats.secondaryRays, total.z);
  }
}

#endif
