// `raylab brdf eval --backend cpu`: the double-precision reference (engine/reference) on the cases' float32
// inputs, promoted to double, with the directions normalised and the frame built in double.
#pragma once

#include "brdf_eval/brdf_cases.h"

namespace raylab {

BrdfResult evaluateBrdfCaseOnCpu(const gpu::BrdfEvalCase& input);

}  // namespace raylab
