#version 460
// The viewer's display pass: one invocation per window texel reads the accumulated radiance (sum / count),
// applies exposure, the tone curve and the sRGB transfer function exactly as the PNG writer does
// (engine/image/png.cpp), and writes the 8-bit image that is blitted to the swapchain. While the camera moves
// the accumulation holds a reduced-resolution image, which this pass stretches bilinearly over the target.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/display.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(push_constant, scalar) uniform Push { DisplayParams params; };
layout(set = 0, binding = kBindingDisplayAccumulation, scalar) readonly buffer Accumulation { vec4 accumulation[]; };
layout(set = 0, binding = kBindingDisplayImage, rgba8) uniform writeonly image2D displayImage;

float toneCurve(float x) {
  if (params.toneMap == kDisplayToneReinhard) return x / (1.0 + x);
  if (params.toneMap == kDisplayToneAces) return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);  // Narkowicz 2015
  return x;
}

float linearToSrgb(float x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055; }

float toDisplay(float linear) {
  // NaN and negative values show as black, as in the PNG writer.
  if (!(linear > 0.0)) return 0.0;
  const float mapped = clamp(toneCurve(linear * params.exposureScale), 0.0, 1.0);
  return (params.flags & kDisplayEncodeSrgb) != 0u ? linearToSrgb(mapped) : mapped;
}

vec4 sourceTexel(ivec2 p) { return accumulation[uint(p.y) * params.sourceSize.x + uint(p.x)]; }

void main() {
  const uvec2 target = gl_GlobalInvocationID.xy;
  if (target.x >= params.targetSize.x || target.y >= params.targetSize.y) return;

  vec3 radiance = vec3(0.0);
  float weight = 0.0;
  if (params.sourceSize == params.targetSize) {
    const vec4 texel = sourceTexel(ivec2(target));
    if (texel.w > 0.0) {
      radiance = texel.rgb / texel.w;
      weight = 1.0;
    }
  } else {
    const vec2 position = (vec2(target) + 0.5) * vec2(params.sourceSize) / vec2(params.targetSize) - 0.5;
    const ivec2 base = ivec2(floor(position));
    const vec2 f = position - vec2(base);
    const ivec2 last = ivec2(params.sourceSize) - 1;
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
        const vec4 texel = sourceTexel(clamp(base + ivec2(i, j), ivec2(0), last));
        // Pixels without samples yet take no part, so a pass in progress never darkens its neighbours.
        if (texel.w > 0.0 && w > 0.0) {
          radiance += w * texel.rgb / texel.w;
          weight += w;
        }
      }
    }
    if (weight > 0.0) radiance /= weight;
  }
  if (weight == 0.0 && (params.flags & kDisplayKeepEmpty) != 0u) return;
  imageStore(displayImage, ivec2(target),
             vec4(toDisplay(radiance.r), toDisplay(radiance.g), toDisplay(radiance.b), 1.0));
}
