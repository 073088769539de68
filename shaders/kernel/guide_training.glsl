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
// bin. In `auto`'s trial the BSDF drew every continuation: Y^2 estimates BSDF sampling's second moment, and
// Y^2 pdf / pdfMixture the mixture's (E_p[Y^2 p / q] = E_q[(f |cos| L_i / q)^2], importance reweighting), with a
// weight of at most 1 / (1 - share) = 2, so the estimate is no noisier than BSDF sampling's own.
void guideSplat(GuideRecord r, float radianceEnd) {
  const uint cellWord = r.cell * kGuideTrainingWords;
  const float y = max(radianceEnd - r.radianceBefore, 0.0) / max(r.throughputBefore, 1e-20);
  if (r.fCos > 0.0) guideAdd(cellWord + r.bin, y / r.fCos, kGuideRadianceScale);
  guideAdd(cellWord + kGuideCountWord, 1.0, 1.0);
  if ((guide.mode & kGuideTrial) == 0u || (r.flags & kGuideRecordEligible) == 0u || !(r.pdfMixture > 0.0)) return;
  guideAdd(cellWord + kGuideMomentWord, y * y, kGuideMomentScale);
  guideAdd(cellWord + kGuideMixtureMomentWord, y * y * (r.pdf / r.pdfMixture), kGuideMomentScale);
}

// The record a continuation left in the payload, completed with where the continuation goes.
GuideRecord guideRecordFor(GuideRecord r, vec3 direction) {
  r.bin = guideBin(direction);
  return r;
}

#endif
