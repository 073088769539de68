// lanesJoin of the megakernel's compute entry points: counts what each lane traced and what its group spent
// between the points where its lanes join again (kernel/raygen.glsl), for the lane utilisation in RayStats.
#ifndef RAYLAB_KERNEL_LANE_UTILISATION_GLSL
#define RAYLAB_KERNEL_LANE_UTILISATION_GLSL

uint laneSegments = 0u;
uint groupSegments = 0u;

void lanesJoin(uint segments) {
  laneSegments += segments;
  groupSegments += subgroupMax(segments);
}

#endif
