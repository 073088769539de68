#version 460
// The render kernel's compute entry point (the ray-query backend): the raygen of kernel/raygen.glsl, one
// invocation per pixel, each segment traced by a ray query and handed to closestHitProgram or miss. The
// pipeline backend runs the same programs from render.rgen, render.rchit, render.rmiss and sphere.rint.
#extension GL_EXT_ray_query : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "shared/frame.h"
#include "kernel/scene_bindings.glsl"

layout(local_size_x = kRenderWorkgroupSize, local_size_y = kRenderWorkgroupSize) in;

layout(push_constant, scalar) uniform Push { FrameParams params; };
layout(set = 0, binding = kBindingAccumulation, scalar) buffer Accumulation { vec4 accumulation[]; };
layout(set = 0, binding = kBindingAovs, scalar) buffer Aovs { vec4 aovs[]; };
layout(set = 0, binding = kBindingRayStats, scalar) buffer Stats { RayStats stats; };

#include "kernel/query_segment.glsl"
#include "kernel/raygen.glsl"
#include "kernel/lane_utilisation.glsl"

void main() {
  const uvec2 pixel = params.tileOrigin + gl_GlobalInvocationID.xy;
  uvec3 rays = uvec3(0u);
  uint dropped = 0u;
  if (pixel.x < params.width && pixel.y < params.height) renderPixel(pixel, rays, dropped);
  addRayStats(rays, dropped, laneSegments, groupSegments);
}
