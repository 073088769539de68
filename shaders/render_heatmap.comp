#version 460
// render.comp with a clock around every pixel's samples (VK_KHR_shader_clock's device clock), for `raylab render
// --heatmap`: where a scene's time goes. A lane's time is its group's (lavapipe runs 8 lanes in lockstep), so the
// map shows the cost of each group of 8 pixels as every one of them. A separate entry point because the clock's
// SPIR-V capability needs the extension, which raylab's other kernels must not require.
#extension GL_EXT_ray_query : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_realtime_clock : require
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
layout(set = 0, binding = kBindingHeatmap, scalar) buffer Heatmap { float clockTicks[]; };

#include "kernel/query_segment.glsl"
#include "kernel/raygen.glsl"
#include "kernel/lane_utilisation.glsl"

// Ticks from `start` to `end` of the 64-bit clock, read as two 32-bit halves (no 64-bit integers needed). A
// thread moved to another core may read a clock behind the first: such a negative span is no measurement, 0,
// not the 1.8e19 its unsigned difference would wrap to.
float ticksBetween(uvec2 start, uvec2 end) {
  const uint borrow = end.x < start.x ? 1u : 0u;
  if (end.y < start.y || end.y - start.y < borrow) return 0.0;
  const uint low = end.x - start.x;
  const uint high = end.y - start.y - borrow;
  return float(high) * 4294967296.0 + float(low);
}

void main() {
  const uvec2 pixel = params.tileOrigin + gl_GlobalInvocationID.xy;
  uvec3 rays = uvec3(0u);
  uint dropped = 0u;
  if (pixel.x < params.width && pixel.y < params.height) {
    const uvec2 start = clockRealtime2x32EXT();
    renderPixel(pixel, rays, dropped);
    // The cheapest dispatch's cost per sample, not the mean: a thread the OS preempts inflates one dispatch's
    // clock, and the minimum over a render's dispatches (as benchmarks take the fastest run) leaves it out.
    const float perSample = ticksBetween(start, clockRealtime2x32EXT()) / float(max(params.sampleCount, 1u));
    const uint index = pixel.y * params.width + pixel.x;
    clockTicks[index] = params.sampleIndex == 0u ? perSample : min(clockTicks[index], perSample);
  }
  addRayStats(rays, dropped, laneSegments, groupSegments);
}
