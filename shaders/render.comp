#version 460
// raygen of raylab's renderer: one invocation per pixel adds one sample to the pixel's running sum. Sub-pixel
// jitter comes from the counter-based RNG and every dispatch adds exactly one sample, so the image depends
// only on the scene, the parameters and the seed, not on how dispatches were batched.
#extension GL_EXT_ray_query : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "shared/frame.h"
#include "kernel/scene_bindings.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(push_constant, scalar) uniform Push { FrameParams params; };
layout(set = 0, binding = kBindingAccumulation, scalar) buffer Accumulation { vec4 accumulation[]; };
layout(set = 0, binding = kBindingRayStats, scalar) buffer Stats { RayStats stats; };

#include "kernel/closest_hit.glsl"
#include "kernel/miss.glsl"

// The primary ray through a point of the pixel; `offset` in [0, 1)^2 within the pixel.
vec3 primaryDirection(uvec2 pixel, vec2 offset) {
  const vec2 ndc = vec2(2.0 * (float(pixel.x) + offset.x) / float(params.width) - 1.0,
                        1.0 - 2.0 * (float(pixel.y) + offset.y) / float(params.height));
  return normalize(params.cameraForward + ndc.x * params.cameraRight + ndc.y * params.cameraUp);
}

void main() {
  const uvec2 pixel = params.tileOrigin + gl_GlobalInvocationID.xy;
  const bool inside = pixel.x < params.width && pixel.y < params.height;
  uvec3 rays = uvec3(0u);  // primary, shadow, secondary

  if (inside) {
    Payload p;
    p.rng = rngCreate(pixel, params.sampleIndex, params.seed);
    const vec2 offset = (params.flags & kFrameJitter) != 0u ? rngNext2(p.rng) : vec2(0.5);
    p.origin = params.cameraOrigin;
    p.direction = primaryDirection(pixel, offset);
    p.radiance = vec3(0.0);
    p.throughput = vec3(1.0);
    p.depth = 0u;
    p.done = false;
    p.shadowRays = 0u;
    // closestHit bounds the loop: it stops the path at maxDepth.
    while (!p.done) {
      Hit hit;
      if (traceClosest(p.origin, p.direction, 0.0, kRayTMax, hit)) closestHit(hit, p);
      else miss(p);
    }
    rays = uvec3(1u, p.shadowRays, p.depth);
    accumulation[pixel.y * params.width + pixel.x] += vec4(p.radiance, 1.0);
  }

  // One atomic per subgroup rather than per invocation.
  const uvec3 total = subgroupAdd(rays);
  if (subgroupElect()) {
    atomicAdd(stats.primaryRays, total.x);
    atomicAdd(stats.shadowRays, total.y);
    atomicAdd(stats.secondaryRays, total.z);
  }
}
