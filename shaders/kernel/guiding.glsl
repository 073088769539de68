// Path guiding in the path integrator (kFeatureGuiding; shared/guiding.h, docs/integrators.md "Path guiding").
// Where a cell of the grid has learned a distribution of incident radiance, a continuation is drawn from it with
// probability guide.guideProbability and from the BSDF otherwise: a one-sample mixture (Veach 1997, section 9.2.4)
// whose density, the mixture's, weighs the sample and enters MIS against next event estimation, so the estimator
// stays unbiased whatever the guide learned. Training: each path keeps its first kGuideTrailLength BSDF-sampled
// continuations (GuideRecord); when it ends, the radiance that came back through each one, divided by the density
// it was drawn with, is added to its cell's direction bin (an estimate of the bin's integral of L_i, as in Mueller et
// al. 2017), and the cell's second moments of both strategies are added for `auto` (engine/render/path_guide.cpp).
#ifndef RAYLAB_KERNEL_GUIDING_GLSL
#define RAYLAB_KERNEL_GUIDING_GLSL

#include "brdf/bsdf.glsl"
#include "common/frame.glsl"
#include "common/specialization.glsl"
#include "shared/guiding.h"

layout(set = 0, binding = kBindingGuide, scalar) readonly buffer GuideBuffer {
  GuideHeader guide;
  float guideCdf[];  // per cell: the cumulative distribution over its bins; all zero where the cell does not guide
};

const uint kNoGuideCell = 0xFFFFFFFFu;
const float kGuideBinSolidAngle = 4.0 * 3.14159265358979 / float(kGuideBins);

bool guidingCompiled() { return kIntegrator == kIntegratorPath && featureEnabled(kFeatureGuiding); }
bool guideTrains() { return guidingCompiled() && (guide.mode & kGuideTraining) != 0u; }

float guideLuminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

uint guideCell(vec3 position) {
  const vec3 c = floor((position - guide.gridMin) * guide.cellScale);
  if (any(lessThan(c, vec3(0.0))) || any(greaterThanEqual(c, vec3(guide.gridSize)))) return kNoGuideCell;
  const uvec3 i = uvec3(c);
  return (i.z * guide.gridSize.y + i.y) * guide.gridSize.x + i.x;
}

// The equal-area bin of a world direction: z = cos theta and phi, each cut in kGuideDirectionSide.
uint guideBin(vec3 direction) {
  const float z = clamp(direction.z, -1.0, 1.0);
  float phi = atan(direction.y, direction.x);
  if (phi < 0.0) phi += 2.0 * 3.14159265358979;
  const uint iz = min(uint((z + 1.0) * 0.5 * float(kGuideDirectionSide)), kGuideDirectionSide - 1u);
  const uint iphi = min(uint(phi * (0.5 / 3.14159265358979) * float(kGuideDirectionSide)), kGuideDirectionSide - 1u);
  return iz * kGuideDirectionSide + iphi;
}

// What a vertex of the path integrator knows of the guide: its cell and the share of continuations drawn from it
// (0 where nothing guides: outside the grid, a cell without a distribution, a BSDF without a diffuse lobe, whose
// narrow lobes its own sampler follows better than a 16 x 16 histogram can).
struct GuideVertex {
  uint cell;
  bool eligible;  // in the grid with a diffuse lobe, its cell with a distribution
  float share;    // of continuations drawn from the guide: guide.guideProbability where eligible and guiding
};

GuideVertex guideVertex(vec3 position, uint flags) {
  GuideVertex g = GuideVertex(kNoGuideCell, false, 0.0);
  if (!guidingCompiled()) return g;
  g.cell = guideCell(position);
  g.eligible = g.cell != kNoGuideCell && (flags & kLobeDiffuse) != 0u &&
               guideCdf[g.cell * kGuideBins + kGuideBins - 1u] > 0.0;
  if (g.eligible && (guide.mode & kGuideSampling) != 0u) g.share = guide.guideProbability;
  return g;
}

// The guide's density (solid angle) of a world direction in a guided cell.
float guidePdf(uint cell, vec3 direction) {
  const uint bin = guideBin(direction);
  const uint base = cell * kGuideBins;
  const float below = bin > 0u ? guideCdf[base + bin - 1u] : 0.0;
  return (guideCdf[base + bin] - below) / kGuideBinSolidAngle;
}

// A direction from the guide of `cell`: a bin by its cumulative distribution, then a uniform point of the bin.
vec3 guideSampleDirection(uint cell, vec2 u) {
  const uint base = cell * kGuideBins;
  uint lo = 0u, hi = kGuideBins - 1u;
  while (lo < hi) {  // the first bin whose cumulative value exceeds u.x
    const uint mid = (lo + hi) / 2u;
    if (guideCdf[base + mid] > u.x) hi = mid; else lo = mid + 1u;
  }
  const float below = lo > 0u ? guideCdf[base + lo - 1u] : 0.0;
  const float within = clamp((u.x - below) / max(guideCdf[base + lo] - below, 1e-20), 0.0, 0.99999994);
  const float z = -1.0 + 2.0 * (float(lo / kGuideDirectionSide) + within) / float(kGuideDirectionSide);
  const float phi = 2.0 * 3.14159265358979 * (float(lo % kGuideDirectionSide) + u.y) / float(kGuideDirectionSide);
  const float r = sqrt(max(0.0, 1.0 - z * z));
  return vec3(r * cos(phi), r * sin(phi), z);
}

// The density with which the continuation of a guided vertex draws the local direction wiLocal (world wi): the
// mixture's, or the BSDF's alone where the vertex does not guide. MIS of the lights weighs against this.
float continuationPdf(GuideVertex g, MaterialRecord material, vec3 wiLocal, vec3 woLocal, vec3 wi) {
  const float bsdf = bsdfPdf(material, wiLocal, woLocal);
  if (!(g.share > 0.0)) return bsdf;
  return g.share * guidePdf(g.cell, wi) + (1.0 - g.share) * bsdf;
}

struct GuidedSample {
  BsdfSample b;   // b.pdf: the mixture's density
  float pdfBsdf;  // BSDF sampling's density of the same direction
};

// The continuation of a guided vertex: from the guide with probability g.share (u.x; u.yz place it), else the BSDF's
// own sample from uBsdf.
GuidedSample guidedSample(GuideVertex g, MaterialRecord material, ShadingFrame frame, vec3 woLocal, vec3 uBsdf,
                          vec3 u) {
  GuidedSample s;
  vec3 wi;
  if (u.x < g.share) {
    wi = guideSampleDirection(g.cell, u.yz);
    s.b.wi = toLocal(frame, wi);
    s.b.f = bsdfEval(material, s.b.wi, woLocal);
    s.pdfBsdf = bsdfPdf(material, s.b.wi, woLocal);
  } else {
    s.b = bsdfSample(material, woLocal, uBsdf);
    if (!(s.b.pdf > 0.0)) return s;
    wi = toWorld(frame, s.b.wi);
    s.pdfBsdf = s.b.pdf;
  }
  s.b.pdf = g.share * guidePdf(g.cell, wi) + (1.0 - g.share) * s.pdfBsdf;
  return s;
}

// The training record of a continuation leaving a vertex: everything but where it went, which the raygen reads
// from the path (its next segment's origin and direction).
// In `auto`'s trial the vertex samples the BSDF alone, and the record also keeps the density the guide's mixture
// would have given the same direction.
GuideRecord guideRecordOf(GuideVertex g, vec3 radiance, vec3 throughput, vec3 fCos, GuidedSample s, vec3 wi,
                          float delta) {
  float pdfMixture = s.b.pdf;
  if (g.eligible && (guide.mode & kGuideTrial) != 0u) {
    pdfMixture = guide.guideProbability * guidePdf(g.cell, wi) + (1.0 - guide.guideProbability) * s.pdfBsdf;
  }
  return GuideRecord(g.cell, 0u, guideLuminance(radiance), guideLuminance(throughput), guideLuminance(fCos),
                     (1.0 - delta) * s.b.pdf, (1.0 - delta) * pdfMixture, g.eligible ? kGuideRecordEligible : 0u);
}

#endif
