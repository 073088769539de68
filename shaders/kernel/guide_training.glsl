// The guide's training sums (kernel/guiding.glsl): what a finished path adds to the cells it passed through. Needs
// the raygen's bindings; the sums are 64-bit fixed point kept as (low, high) words of 32-bit atomics, so that they
// need no device feature and come out the same whatever order the lanes add in.
#ifndef RAYLAB_KERNEL_GUIDE_TRAINING_GLSL
#define RAYLAB_KERNEL_GUIDE_TRAINING_GLSL

#include "kernel/guiding.glsl"

layout(set = 0, binding = kBindingGuideTraining, scalar) buffer GuideTraining { uint guideTraining[]; };

// Adds `value` (in units of 1/scale) to 64-bit word `word` of the training sums; one add never exceeds 2^32 - 1 units,
// so it carries at most once.
void guideAdd(uint word, float value, float scale) {
  if (!(value > 0.0)) return;
  const uint units = uint(min(value * scale + 0.5, kGuideMaxUnits));
  if (units == 0u) return;
  const uint before = atomicAdd(guideTraining[2u * word], units);
  if (before + units < before) atomicAdd(guideTraining[2u * word + 1u], 1u);
}

// Adds one vertex of a finished path whose radiance is `radianceEnd` (luminance). Y, the radiance the continuation
// brought back over the throughput that reached the vertex, is f |cos| L_i / pdf: Y / fCos = L_i / pdf trains the
// bin. For `auto`, Y^2 over every eligible vertex estimates the second moment of the continuations as drawn, and over
// the continuations the BSDF drew, (Y pdf / pdfBsdf)^2 = (f |cos| L_i / pdfBsdf)^2 estimates BSDF sampling's alone:
// its own samples, so no weight grows where the BSDF rarely goes (reweighting the guide's samples by pdf / pdfBsdf
// did, and called guiding a 3x gain on a Cornell box where it gained nothing).
void guideSplat(GuideRecord r, float radianceEnd) {
  const uint cellWord = r.cell * kGuideTrainingWords;
  const float y = max(radianceEnd - r.radianceBefore, 0.0) / max(r.throughputBefore, 1e-20);
  if (r.fCos > 0.0) guideAdd(cellWord + r.bin, y / r.fCos, kGuideRadianceScale);
  guideAdd(cellWord + kGuideCountWord, 1.0, 1.0);
  if ((r.flags & kGuideRecordEligible) == 0u) return;
  guideAdd(cellWord + kGuideMomentWord, y * y, kGuideMomentScale);
  guideAdd(cellWord + kGuideMomentCountWord, 1.0, 1.0);
  if ((r.flags & kGuideRecordFromBsdf) != 0u && r.pdfBsdf > 0.0) {
    const float yBsdf = y * (r.pdf / r.pdfBsdf);
    guideAdd(cellWord + kGuideBsdfMomentWord, yBsdf * yBsdf, kGuideMomentScale);
    guideAdd(cellWord + kGuideBsdfCountWord, 1.0, 1.0);
  }
}

// The record a continuation left in the payload, completed with where the continuation goes.
GuideRecord guideRecordFor(GuideRecord r, vec3 direction) {
  r.bin = guideBin(direction);
  return r;
}

#endif
