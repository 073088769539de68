#version 460
// The path integrator as a wavefront (the ray-query backend's choice for path kernels; docs/performance.md):
// a wave of paths advances one segment per dispatch, and only the paths still alive go on, compacted into a
// queue. The megakernel (render.comp) keeps each group of 8 lanes until its longest path ends, idling the lanes
// whose paths ended early (Russian roulette, escaping rays); here every lane of a segment dispatch has a live
// path, and the paths of a dispatch are all at the same depth. Each path is the same computation as in
// render.comp (the same traceSegment, closestHitProgram and miss on the same state and random numbers), and each
// pixel adds its samples in the same order, so the image is bit for bit the megakernel's.
#extension GL_EXT_ray_query : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_basic : require

#include "shared/frame.h"
#include "shared/guiding.h"
#include "shared/wavefront.h"
#include "kernel/scene_bindings.glsl"

layout(local_size_x = kWaveWorkgroupSize) in;

layout(push_constant, scalar) uniform Push {
  FrameParams params;
  WaveParams wave;
};
layout(set = 0, binding = kBindingAccumulation, scalar) buffer Accumulation { vec4 accumulation[]; };
layout(set = 0, binding = kBindingAovs, scalar) buffer Aovs { vec4 aovs[]; };
layout(set = 0, binding = kBindingRayStats, scalar) buffer Stats { RayStats stats; };
layout(set = 0, binding = kBindingPathStates, scalar) buffer PathStates { PathState states[]; };
layout(set = 0, binding = kBindingPathResults, scalar) buffer PathResults { vec4 results[]; };
layout(set = 0, binding = kBindingPathQueues, scalar) buffer PathQueues { uint queues[]; };
layout(set = 0, binding = kBindingWaveControl, scalar) buffer Control { WaveControl control; };
layout(set = 0, binding = kBindingPathAovs, scalar) buffer PathAovs { vec4 pathAovs[]; };
layout(set = 0, binding = kBindingGuideTrails, scalar) buffer GuideTrails { GuideRecord trails[]; };

#include "kernel/query_segment.glsl"
#include "kernel/raygen.glsl"

void lanesJoin(uint segments) {}

uvec2 pixelOfSlot(uint slot) {
  const uint pixelInTile = slot / params.sampleCount;
  return params.tileOrigin + uvec2(pixelInTile % wave.tileWidth, pixelInTile / wave.tileWidth);
}

Payload loadPath(uint slot) {
  Payload p;
  p.path = states[slot];
  p.done = false;
  p.split = false;
  return p;
}

void storePath(uint slot, Payload p) { states[slot] = p.path; }

// One segment of the path in slot `slot` (started here for the first segment); a finished path leaves its
// radiance in `results`, a live one goes to the other queue. Every lane reaches the ballot, live or not.
void segment(uint i, inout uvec3 rays, inout uint laneSegments) {
  const bool first = wave.mode == kWaveFirstSegment;
  const uint count = first ? control.slots : control.live[wave.queue];
  const bool live = i < count;
  bool keep = false;
  uint slot = 0u;
  if (live) {
    slot = first ? i : queues[wave.queue * control.capacity + i];
    Payload p = first ? startSample(pixelOfSlot(slot), params.sampleIndex + slot % params.sampleCount) : loadPath(slot);
    p.path.segments += 1u;
    traceSegment(p);
    laneSegments += 1u;
    // The guide's training vertices wait in the slot's trail until the path ends (kernel/guide_training.glsl).
    if (guideTrains()) {
      if (p.guideRecorded && !p.done && p.path.guideVertices < kGuideTrailLength) {
        trails[slot * kGuideTrailLength + p.path.guideVertices] = guideRecordFor(p.guideRecord, p.path.direction);
        p.path.guideVertices += 1u;
      }
      if (p.done) {
        for (uint k = 0u; k < p.path.guideVertices; ++k) {
          guideSplat(trails[slot * kGuideTrailLength + k], guideLuminance(p.path.radiance));
        }
      }
    }
    // The first segment met the first hit: its auxiliary values wait beside the path's result.
    if (first && featureEnabled(kFeatureAovs)) {
      pathAovs[2u * slot] = vec4(p.aovAlbedo, 0.0);
      pathAovs[2u * slot + 1u] = vec4(p.aovNormal, 0.0);
    }
    if (p.done) {
      results[slot] = vec4(p.path.radiance, 0.0);
      rays += uvec3(1u, p.path.shadowRays, p.path.segments - 1u);
    } else {
      storePath(slot, p);
      keep = true;
    }
  }
  // Live paths are appended to the other queue, one atomic per subgroup.
  const uvec4 ballot = subgroupBallot(keep);
  const uint kept = subgroupBallotBitCount(ballot);
  uint base = 0u;
  if (subgroupElect() && kept > 0u) base = atomicAdd(control.live[1u - wave.queue], kept);
  base = subgroupBroadcastFirst(base);
  if (keep) queues[(1u - wave.queue) * control.capacity + base + subgroupBallotExclusiveBitCount(ballot)] = slot;
}

// Sizes the next segment's dispatch by the paths the last one kept, and empties the queue it read.
void prepare() {
  const uint next = 1u - wave.queue;
  control.dispatch[next * 3u] = (control.live[next] + kWaveWorkgroupSize - 1u) / kWaveWorkgroupSize;
  control.dispatch[next * 3u + 1u] = 1u;
  control.dispatch[next * 3u + 2u] = 1u;
  control.live[wave.queue] = 0u;
}

// Adds each pixel's finished samples to its running sum in sample order, as render.comp does.
void accumulate(uint pixelInTile, inout uint dropped) {
  if (pixelInTile * params.sampleCount >= control.slots) return;
  const uvec2 pixel = params.tileOrigin + uvec2(pixelInTile % wave.tileWidth, pixelInTile / wave.tileWidth);
  const uint index = pixel.y * params.width + pixel.x;
  PixelSums sums = loadPixelSums(index);
  for (uint s = 0u; s < params.sampleCount; ++s) {
    const uint slot = pixelInTile * params.sampleCount + s;
    SampleValue value = SampleValue(results[slot].rgb, vec3(0.0), vec3(0.0));
    if (featureEnabled(kFeatureAovs)) {
      value.albedo = pathAovs[2u * slot].rgb;
      value.normal = pathAovs[2u * slot + 1u].xyz;
    }
    addSample(value, sums, dropped);
  }
  storePixelSums(index, sums);
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (wave.mode == kWavePrepare) {
    if (i == 0u) prepare();
    return;
  }
  uvec3 rays = uvec3(0u);
  uint dropped = 0u;
  uint laneSegments = 0u;
  if (wave.mode == kWaveAccumulate) {
    accumulate(i, dropped);
  } else {
    segment(i, rays, laneSegments);
  }
  // A segment dispatch spends one segment of every group with a live lane.
  addRayStats(rays, dropped, laneSegments, laneSegments);
}
