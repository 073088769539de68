// The path integrator's wavefront (wavefront.comp, engine/render/wavefront.h): the state of a path between two
// segments, the queues of live paths, and the parameters of a wave. A wave is a tile of pixels times a number
// of samples per pixel; slot s holds sample s % samples of pixel s / samples of the tile, row by row.
#ifndef RAYLAB_SHARED_WAVEFRONT_H
#define RAYLAB_SHARED_WAVEFRONT_H

#include "compat.h"
#include "path_state.h"  // PathState, what kBindingPathStates holds

RL_NAMESPACE_BEGIN

// Bindings of wavefront.comp, beside the scene's and the renderer's.
RL_CONST uint kBindingPathStates = 19;   // PathState[capacity] (path_state.h)
RL_CONST uint kBindingPathResults = 20;  // vec4[capacity]: the radiance of each finished path
RL_CONST uint kBindingPathQueues = 21;   // uint[2 * capacity]: two queues of live slots, read one, fill the other
RL_CONST uint kBindingWaveControl = 22;  // WaveControl
RL_CONST uint kBindingPathAovs = 29;     // vec4[2 * capacity]: each path's first-hit albedo and normal (kFeatureAovs)

// WaveParams.mode: what one dispatch of wavefront.comp does.
RL_CONST uint kWaveFirstSegment = 0;  // start every slot's camera path and trace its first segment
RL_CONST uint kWaveSegment = 1;       // one segment of every live path of queue `queue`
RL_CONST uint kWavePrepare = 2;       // one invocation: size the next segment's indirect dispatch
RL_CONST uint kWaveAccumulate = 3;    // add each pixel's finished samples to the accumulation, in order

RL_CONST uint kWaveWorkgroupSize = 64;

// After FrameParams in the push constants (116 + 12 = 128 bytes, the least any device offers).
struct WaveParams {
  uint mode;
  uint queue;      // kWaveSegment: the queue read; live paths go to the other one
  uint tileWidth;  // pixels per row of the tile (FrameParams.tileOrigin, .sampleIndex and .sampleCount say the rest)
};
RL_CHECK_SIZE(WaveParams, 12);

// The live paths of each queue and the indirect dispatch that processes them (VkDispatchIndirectCommand).
struct WaveControl {
  uint live[2];
  uint dispatch[6];  // x, y, z per queue
  uint slots;        // of this wave: tile pixels times samples
  uint capacity;     // slots the buffers hold; queue q starts at q * capacity
};
RL_CHECK_SIZE(WaveControl, 40);


RL_NAMESPACE_END

#endif
