#version 460
// The viewer's display pass: one invocation per pixel reads the accumulated radiance (sum / count), applies
// exposure, the tone curve and the sRGB transfer function exactly as the PNG writer does
// (engine/image/png.cpp, including its rounding), and packs the 8-bit texel in the byte order of the window's
// images. Texels go to a buffer: plain stores are cheap on a CPU device, and a copy puts them in the image.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/display.h"

layout(local_size_x = kDisplayWorkgroupSize, local_size_y = kDisplayWorkgroupSize) in;

layout(push_constant, scalar) uniform Push { DisplayParams params; };
layout(set = 0, binding = kBindingDisplayAccumulation, scalar) readonly buffer Accumulation { vec4 accumulation[]; };
layout(set = 0, binding = kBindingDisplayTexels, scalar) writeonly buffer Texels { uint texels[]; };
layout(set = 0, binding = kBindingDisplayCompare, scalar) readonly buffer Compare { vec4 compare[]; };

float toneCurve(float x) {
  if (params.toneMap == kDisplayToneReinhard) return x / (1.0 + x);
  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve", as in engine/image/png.cpp.
  if (params.toneMap == kDisplayToneAces) return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
  return x;
}

float linearToSrgb(float x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055; }

float toDisplay(float linear) {
  // NaN and negative values show as black, as in the PNG writer.
  if (!(linear > 0.0)) return 0.0;
  return linearToSrgb(clamp(toneCurve(linear * params.exposureScale), 0.0, 1.0));
}

vec3 meanOf(vec4 texel) { return texel.w > 0.0 ? texel.rgb / texel.w : vec3(0.0); }

// Dark blue, blue, green, yellow, white: the ramp of raylab's cost maps (engine/image/heatmap.cpp), in sRGB.
vec3 falseColour(float t) {
  const vec3 stops[5] = vec3[5](vec3(0.05, 0.03, 0.20), vec3(0.10, 0.30, 0.85), vec3(0.10, 0.75, 0.35),
                                vec3(0.95, 0.85, 0.10), vec3(1.00, 1.00, 1.00));
  const float x = clamp(t, 0.0, 1.0) * 4.0;
  const int i = min(int(x), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
  const uvec2 pixel = params.regionOrigin + gl_GlobalInvocationID.xy;
  if (pixel.x >= params.size.x || pixel.y >= params.size.y) return;
  const uint index = pixel.y * params.size.x + pixel.x;
  vec3 colour;
  if (params.mode == kDisplayDifference || params.mode == kDisplayRelativeDifference) {
    const vec3 a = meanOf(accumulation[index]), b = meanOf(compare[index]);
    const vec3 difference = abs(a - b);
    float shown = max(difference.r, max(difference.g, difference.b));
    if (params.mode == kDisplayRelativeDifference) {
      const float level = max(max(max(a.r, a.g), a.b), max(max(b.r, b.g), b.b));
      shown = level > 0.0 ? shown / level : 0.0;
    }
    colour = falseColour(shown / params.differenceScale);
  } else {
    const bool compared = params.mode == kDisplaySplit && pixel.x >= params.splitColumn;
    const vec3 radiance = meanOf(compared ? compare[index] : accumulation[index]);
    colour = vec3(toDisplay(radiance.r), toDisplay(radiance.g), toDisplay(radiance.b));
  }
  if ((params.flags & kDisplayBgra) != 0u) colour = colour.bgr;
  texels[index] = packUnorm4x8(vec4(colour, 1.0));  // round(255 c), the PNG writer's rounding
}
