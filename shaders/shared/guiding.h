// Path guiding (kernel/guiding.glsl, engine/render/path_guide.h): a radiance cache learned while rendering, in the
// spirit of Mueller, Gross & Novak, "Practical Path Guiding for Efficient Light-Transport Simulation" (2017), made
// cheaper: a uniform grid of cells over the scene's bounds instead of their spatial binary tree, and in each cell a
// fixed histogram of equal-area direction bins (z = cos theta and phi, each cut in kGuideDirectionSide) instead of
// their adaptive quadtree. docs/integrators.md, "Path guiding", says why that is enough on raylab's scenes.
#ifndef RAYLAB_SHARED_GUIDING_H
#define RAYLAB_SHARED_GUIDING_H

#include "compat.h"

RL_NAMESPACE_BEGIN

RL_CONST uint kBindingGuide = 30;          // GuideHeader, then float cdf[cells * kGuideBins]: the distributions
RL_CONST uint kBindingGuideTraining = 31;  // 64-bit sums as uint pairs, kGuideTrainingWords per cell (see below)
RL_CONST uint kBindingGuideTrails = 32;    // GuideRecord[kGuideTrailLength per wave slot]: the wavefront's vertices

// The grid's cells are cubes, as small as keeps their number within kGuideCells over the scene's bounds: on a flat
// scene (a floor with objects) they follow the objects' scale rather than the floor's.
RL_CONST uint kGuideCells = 16384;
RL_CONST uint kGuideDirectionSide = 16;  // bins along cos theta and along phi
RL_CONST uint kGuideBins = kGuideDirectionSide * kGuideDirectionSide;
// The vertices of a path that train the guide: the first kGuideTrailLength continuations sampled from a BSDF.
RL_CONST uint kGuideTrailLength = 4;

// Training words per cell: the bins' sums of incident radiance over sampling density (estimates of each bin's
// integral of L_i), the cell's count of recorded vertices, and during `auto`'s trial the second moments of BSDF
// sampling, as drawn, and of the mixture the guide would make, by importance reweighting of the same samples.
RL_CONST uint kGuideTrainingWords = kGuideBins + 3;
RL_CONST uint kGuideCountWord = kGuideBins;
RL_CONST uint kGuideMomentWord = kGuideBins + 1;         // sum of Y^2 over eligible vertices, Y as drawn
RL_CONST uint kGuideMixtureMomentWord = kGuideBins + 2;  // sum of Y^2 pdf / pdfMixture: the mixture's, had it drawn
// Fixed-point scales of the sums: integer atomics add in any order to the same bits, so a guided image depends on
// its seed only (float atomics would make every run differ).
RL_CONST float kGuideRadianceScale = 4096.0;
RL_CONST float kGuideMomentScale = 1024.0;
// No single sample adds more than this many units (a firefly must not overflow a sum of 2^64).
RL_CONST float kGuideMaxUnits = 1099511627776.0;  // 2^40

// GuideRecord.flags bits.
RL_CONST uint kGuideRecordEligible = 1;  // the vertex may be guided, and its cell has a distribution

// GuideHeader.mode bits.
RL_CONST uint kGuideSampling = 1;  // cells with a distribution guide their continuations
RL_CONST uint kGuideTraining = 2;  // the kernel records paths' vertices into the training sums
RL_CONST uint kGuideTrial = 4;     // `auto`'s trial: BSDF sampling only, the guide's mixture density recorded beside

struct GuideHeader {
  vec3 gridMin;    // the scene's bounds, a little enlarged
  uint mode;       // kGuide... bits
  uvec3 gridSize;  // cells along each axis (their product at most kGuideCells)
  float cellScale; // cells per unit length
  float guideProbability;  // the share of continuations drawn from the guide in a guided cell (the rest: the BSDF)
  uint pad0;
  uint pad1;
  uint pad2;
};
RL_CHECK_SIZE(GuideHeader, 48);

// A vertex of a path, kept until the path ends so that the radiance that came back through it can train its cell.
struct GuideRecord {
  uint cell;
  uint bin;
  float radianceBefore;    // luminance of the path's radiance when the continuation left the vertex
  float throughputBefore;  // luminance of the throughput that reached the vertex
  float fCos;              // luminance of f |cos| of the continuation (with the mirror weight's (1 - delta))
  float pdf;               // the density it was drawn with (mixture where guided, (1 - delta) included)
  float pdfMixture;        // in `auto`'s trial, the density the guide's mixture would have given it
  uint flags;              // kGuideRecord... bits
};
RL_CHECK_SIZE(GuideRecord, 32);

RL_NAMESPACE_END

#endif
