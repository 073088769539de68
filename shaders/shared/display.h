// The display pass (display.comp): the accumulation buffer, divided by its sample counts, through exposure,
// a tone curve and the sRGB transfer function into 8-bit texels laid out like the window's images, which
// transfer commands then copy and blit there.
#ifndef RAYLAB_SHARED_DISPLAY_H
#define RAYLAB_SHARED_DISPLAY_H

#include "compat.h"

RL_NAMESPACE_BEGIN

RL_CONST uint kDisplayWorkgroupSize = 8;  // display.comp: kDisplayWorkgroupSize squared

// Bindings of display.comp (its own set 0).
RL_CONST uint kBindingDisplayAccumulation = 0;  // vec4[] radiance sum and sample count, `size` pixels
RL_CONST uint kBindingDisplayTexels = 1;        // uint[] one 8-bit RGBA or BGRA texel per pixel, `size` pixels
RL_CONST uint kBindingDisplayCompare = 2;       // vec4[] the compared image's accumulation (the viewer's split view)

// DisplayParams.mode
RL_CONST uint kDisplayImage = 0;               // the accumulation
RL_CONST uint kDisplaySplit = 1;               // the accumulation left of splitColumn, the compared image from it on
RL_CONST uint kDisplayDifference = 2;          // |A - B| (the largest channel) in false colour, 1 at differenceScale
RL_CONST uint kDisplayRelativeDifference = 3;  // |A - B| / max(A, B), likewise

// DisplayParams.toneMap: the curves of engine/image (ToneMap), in the same order.
RL_CONST uint kDisplayToneClamp = 0;
RL_CONST uint kDisplayToneReinhard = 1;
RL_CONST uint kDisplayToneAces = 2;

// DisplayParams.flags
RL_CONST uint kDisplayBgra = 1;  // bytes in B, G, R, A order (the swapchain's format is B8G8R8A8)

// Pixel (x, y) of the accumulation becomes texel (x, y), both with rows of size.x. A dispatch covers the
// pixels [regionOrigin, regionOrigin + dispatch size).
struct DisplayParams {
  uvec2 size;
  uvec2 regionOrigin;
  float exposureScale;  // 2^exposure
  uint toneMap;
  uint flags;
  uint mode;             // kDisplay...
  uint splitColumn;      // kDisplaySplit: the first column of the compared image
  float differenceScale; // kDisplay*Difference: the difference shown at the top of the colour ramp
};
RL_CHECK_SIZE(DisplayParams, 40);

RL_NAMESPACE_END

#endif
