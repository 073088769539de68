// The display pass (display.comp): the accumulation buffer, divided by its sample counts, through exposure,
// a tone curve and the sRGB transfer function into the 8-bit image that is blitted to the window.
#ifndef RAYLAB_SHARED_DISPLAY_H
#define RAYLAB_SHARED_DISPLAY_H

#include "compat.h"

RL_NAMESPACE_BEGIN

// Bindings of display.comp (its own set 0).
RL_CONST uint kBindingDisplayAccumulation = 0;  // vec4[] radiance sum and sample count, sourceSize pixels
RL_CONST uint kBindingDisplayImage = 1;         // rgba8 storage image, targetSize pixels

// DisplayParams.toneMap: the curves of engine/image (ToneMap), in the same order.
RL_CONST uint kDisplayToneClamp = 0;
RL_CONST uint kDisplayToneReinhard = 1;
RL_CONST uint kDisplayToneAces = 2;

// DisplayParams.flags
RL_CONST uint kDisplayEncodeSrgb = 1;  // write sRGB-encoded values (the window's format is UNORM)
RL_CONST uint kDisplayKeepEmpty = 2;   // leave texels whose source pixels have no sample yet untouched

// The source (the accumulation at the traced resolution) is stretched over the target with bilinear
// filtering; at equal sizes every target texel reads exactly its own pixel.
struct DisplayParams {
  uvec2 sourceSize;
  uvec2 targetSize;
  float exposureScale;  // 2^exposure
  uint toneMap;
  uint flags;
  uint reserved;
};
RL_CHECK_SIZE(DisplayParams, 32);

RL_NAMESPACE_END

#endif
