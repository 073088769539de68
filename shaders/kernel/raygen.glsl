// The raygen of raylab's renderer, shared by both backends: the camera ray of a sample and the loop that follows
// a path segment by segment (no recursion), keeping glass's second continuations in a small queue. Each entry
// point defines how one segment is traced (traceSegment: a ray query and a call of closestHitProgram or miss in
// render.comp; traceRayEXT and the pipeline's own programs in render.rgen) and how ray counts are gathered.
// Needs `params` (FrameParams), `accumulation` and `aovs` (the denoiser's first-hit images, kernel/aov.glsl).
#ifndef RAYLAB_KERNEL_RAYGEN_GLSL
#define RAYLAB_KERNEL_RAYGEN_GLSL

#include "kernel/guide_training.glsl"
#include "kernel/payload.glsl"

// Traces the segment (p.path.origin, p.path.direction): closestHit or miss add what they see to the payload and set up
// the next segment or mark the path done.
void traceSegment(inout Payload p);

// Continuations waiting their turn after glass split a path. Deeper splits than this are resolved by
// choosing one branch at random in proportion to its weight (unbiased, a little noise).
const uint kMaxPending = 4u;
struct Pending {
  vec3 origin;
  vec3 direction;
  vec3 throughput;
  uint depth;
};

// The primary ray through a point of the pixel; `offset` in [0, 1)^2 within the pixel.
vec3 primaryDirection(uvec2 pixel, vec2 offset) {
  const vec2 ndc = vec2(2.0 * (float(pixel.x) + offset.x) / float(params.width) - 1.0,
                        1.0 - 2.0 * (float(pixel.y) + offset.y) / float(params.height));
  return normalize(params.cameraForward + ndc.x * params.cameraRight + ndc.y * params.cameraUp);
}

// Keeps the split continuation of `p`: queued if there is room, else one of the two branches survives.
void keepSplit(inout Payload p, inout Pending pending[kMaxPending], inout uint pendingCount) {
  p.split = false;
  if (pendingCount < kMaxPending) {
    pending[pendingCount] = Pending(p.splitOrigin, p.splitDirection, p.splitThroughput, p.path.depth);
    pendingCount += 1u;
    return;
  }
  const float keep = maxComponent(p.path.throughput);
  const float other = maxComponent(p.splitThroughput);
  const float pickOther = other / (keep + other);
  if (rngNext4(p.path.rng).x < pickOther) {
    p.path.origin = p.splitOrigin;
    p.path.direction = p.splitDirection;
    p.path.throughput = p.splitThroughput / pickOther;
  } else {
    p.path.throughput /= 1.0 - pickOther;
  }
}

// The camera path of sample `sampleIndex` of `pixel`, ready for its first segment.
Payload startSample(uvec2 pixel, uint sampleIndex) {
  Payload p;
  p.path.rng = rngCreate(pixel, sampleIndex, params.seed);
  vec2 offset = vec2(0.5);
  if ((params.flags & kFrameJitter) != 0u) {
    offset = rngNext2(p.path.rng);
  } else if (featureEnabled(kFeatureAlpha)) {
    // Pixel centres to a thousandth of a pixel: the coverage coins of stochastic transparency are keyed by the ray
    // (kernel/alpha.glsl), so every sample of a pixel must trace a ray of its own bits, as must the shadow rays
    // from its first hit; at the exact centre each pixel would draw one coin for all its samples.
    offset += (rngNext2(p.path.rng) - 0.5) * 1e-3;
  }
  p.path.origin = params.cameraOrigin;
  p.path.direction = primaryDirection(pixel, offset);
  p.path.radiance = vec3(0.0);
  p.path.throughput = vec3(1.0);
  p.path.absorption = vec3(0.0);
  p.path.depth = 0u;
  p.done = false;
  p.split = false;
  p.path.shadowRays = 0u;
  p.path.segments = 0u;
  p.path.lastPosition = p.path.origin;
  p.path.lastPdf = 0.0;
  p.path.lastSpecular = 1u;
  p.aovAlbedo = vec3(0.0);
  p.aovNormal = vec3(0.0);
  p.guideRecorded = false;
  p.path.guideVertices = 0u;
  return p;
}

// What one sample brings to its pixel: the radiance along its camera path, and with kFeatureAovs what its first
// hit showed the denoiser.
struct SampleValue {
  vec3 radiance;
  vec3 albedo;
  vec3 normal;
};

// A pixel's running sums: radiance and sample count, and with kFeatureAovs the first-hit albedo and normal.
struct PixelSums {
  vec4 radiance;
  vec3 albedo;
  vec3 normal;
};

PixelSums loadPixelSums(uint index) {
  PixelSums sums = PixelSums(accumulation[index], vec3(0.0), vec3(0.0));
  if (featureEnabled(kFeatureAovs)) {
    sums.albedo = aovs[2u * index].rgb;
    sums.normal = aovs[2u * index + 1u].xyz;
  }
  return sums;
}

void storePixelSums(uint index, PixelSums sums) {
  accumulation[index] = sums.radiance;
  if (featureEnabled(kFeatureAovs)) {
    aovs[2u * index] = vec4(sums.albedo, 0.0);
    aovs[2u * index + 1u] = vec4(sums.normal, 0.0);
  }
}

// Adds a finished sample to the pixel's running sums. A NaN or Inf sample is a defect somewhere: it is dropped
// (the pixel's count says how many it has) and counted, never spread over the image; its auxiliary values go with it,
// so that every image of the pixel divides by the same count.
void addSample(SampleValue value, inout PixelSums sums, inout uint dropped) {
  if (any(isnan(value.radiance)) || any(isinf(value.radiance))) {
    dropped += 1u;
  } else {
    sums.radiance += vec4(value.radiance, 1.0);
    sums.albedo += value.albedo;
    sums.normal += value.normal;
  }
}

// Where the lanes of a group (lavapipe: 8 in lockstep) join again after `segments` segments of this lane: the
// entry point may count lane utilisation there (render.comp does, with subgroup operations).
void lanesJoin(uint segments);

// One sample of `pixel`: the radiance along its camera path, every glass branch included, and its first hit's
// auxiliary values. Adds the rays it traced to `rays` (primary, shadow, secondary).
SampleValue traceSample(uvec2 pixel, uint sampleIndex, inout uvec3 rays) {
  Payload p = startSample(pixel, sampleIndex);
  Pending pending[kMaxPending];
  uint pendingCount = 0u;
  uint segments = 0u;
  GuideRecord trail[kGuideTrailLength];  // the vertices that train the guide (kernel/guide_training.glsl)

  // closestHit bounds every path by maxDepth, and each split happens at a bounce: the loop ends.
  while (true) {
    segments += 1u;
    traceSegment(p);
    if (guideTrains() && p.guideRecorded && !p.done && p.path.guideVertices < kGuideTrailLength) {
      trail[p.path.guideVertices] = guideRecordFor(p.guideRecord, p.path.direction);
      p.path.guideVertices += 1u;
    }
    // Only the slides' integrator splits paths (the path integrator chooses one glass branch at random): in a
    // path kernel the queue is dead code and the driver drops it with its registers.
    if (kIntegrator == kIntegratorSlides && p.split) keepSplit(p, pending, pendingCount);
    if (p.done) {
      if (kIntegrator == kIntegratorPath || pendingCount == 0u) break;
      pendingCount -= 1u;
      p.path.origin = pending[pendingCount].origin;
      p.path.direction = pending[pendingCount].direction;
      p.path.throughput = pending[pendingCount].throughput;
      p.path.depth = pending[pendingCount].depth;
      p.done = false;
    }
  }
  if (guideTrains()) {
    for (uint k = 0u; k < p.path.guideVertices; ++k) guideSplat(trail[k], guideLuminance(p.path.radiance));
  }
  lanesJoin(segments);
  rays += uvec3(1u, p.path.shadowRays, segments - 1u);
  return SampleValue(p.path.radiance, p.aovAlbedo, p.aovNormal);
}

// Adds params.sampleCount samples to the pixel's running sum, one at a time and in order, exactly as separate
// dispatches would add them: the sum, and so the image, does not depend on how many samples a dispatch carries.
// Counts the rays traced and the samples dropped.
void renderPixel(uvec2 pixel, inout uvec3 rays, inout uint dropped) {
  const uint index = pixel.y * params.width + pixel.x;
  PixelSums sums = loadPixelSums(index);
  for (uint i = 0u; i < params.sampleCount; ++i) addSample(traceSample(pixel, params.sampleIndex + i, rays), sums, dropped);
  storePixelSums(index, sums);
}

#endif
