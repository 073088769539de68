// Parity and robustness of the GLSL BRDF library (shaders/brdf) against the double-precision reference
// (engine/reference), issue 3 item 4. Every case is evaluated by brdf_eval.comp on the device and by the
// reference from the SAME float32 inputs, promoted to double and used as they are (not renormalised, as the
// reference's contract says), so input rounding is not part of the error. The inputs are unit vectors
// rounded to float, so the device's own normalisation changes them by an ulp at most.
//
// Tolerance. Ordinary cases must agree to a relative 1e-4. A case gets a looser bound only where float32
// input rounding alone moves the exact value more: the bound is kConditioningFactor x the reference's
// relative change when one local component of wi or wo moves by one float ulp of itself (plus 1 ulp of 1 in
// a non-canonical frame, the absolute error of the device's frame and dot products) or a direction's length
// moves by one ulp, summed over these eight perturbations. The device's normalisation and frame move its directions by about that much, so its result is
// the exact value at directions that close; the factor 4 covers a few ulps and the linearisation. These are
// the sharp lobes off their peak (s = 10^4, m = 0.001, where an ulp of the directions moves tan^2
// noticeably) and grazing mirror configurations (cosines of 1e-7, where an ulp of the x components moves h).
// A tabulated model (measured) is a step function: within kJumpUlps ulps of a bin edge (the device's angles are
// a few ulps off the reference's) either bin is correct, and the bound is the step.
//
// Near-zero values are compared against an absolute floor of 1e-15 (1/sr): 3e-15 of a white Lambertian,
// far below anything a render can show, and 100x above the largest value the library rounds to 0 where
// exp(-x) underflows float32 (about 1e-17, ward_gmd at cosines of 1e-7).
#include <algorithm>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "brdf_eval/device_evaluator.h"
#include "reference/brdf_reference.h"
#include "reference/models.h"
#include "brdf_params/material_params.h"
#include "support/gpu_test.h"
#include "support/measured_files.h"

namespace raylab::test {
namespace {

using glm::dvec3;
using glm::vec3;

constexpr double kOrdinaryTolerance = 1e-4;
constexpr double kConditioningFactor = 4.0;
constexpr double kFloor = 1e-15;         // f, 1/sr
constexpr double kFresnelFloor = 1e-12;  // glass Fresnel factors (F is 2.5e-9 at eta = 1.0001)
constexpr double kUlp = 0x1p-23;         // relative spacing of float32 numbers
constexpr double kFrameUlps = 1.0;       // absolute error of the device's frame and dot products, in ulps of 1
constexpr double kJumpUlps = 16.0;       // how far from a step of f (a measured table's bin edge) a case is at one

// Every registered model with an f (delta BSDFs have their own test below), from the registry: a new model is
// covered without an edit here.
std::vector<std::uint32_t> brdfModels() {
  std::vector<std::uint32_t> models;
  for (const ModelInfo& model : allModels()) {
    if (!isDeltaOnly(model)) models.push_back(model.id);
  }
  return models;
}
const std::vector<std::uint32_t> kBrdfModels = brdfModels();

struct ParityCase {
  gpu::BrdfEvalCase input;
  bool canonicalFrame = true;  // n = z, t = x: the device's frame is exact
};

dvec3 spherical(double cosTheta, double phi) {
  const double sinTheta = std::sqrt(std::max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double a = 0.0, double b = 1.0) { return std::uniform_real_distribution<double>(a, b)(engine_); }
  double logUniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  double normal() { return std::normal_distribution<double>()(engine_); }
  // A cosine for the hard end too: a third of them log-uniform down to 1e-7.
  double cosine() { return uniform() < 0.33 ? logUniform(1e-7, 1.0) : uniform(1e-7, 1.0); }
  dvec3 unitVector() { return spherical(uniform(-1.0, 1.0), uniform(0.0, 2.0 * M_PI)); }

 private:
  std::mt19937_64 engine_;
};

gpu::MaterialRecord randomMaterial(std::uint32_t model, Random& random) {
  gpu::MaterialRecord record = defaultRecord(model);
  for (const ParamInfo& p : modelInfo(model).params) {
    glm::vec3 value;
    if (isFileParam(p)) {
      value = glm::vec3(float(testFileFor(p, random.uniform() < 0.5 ? 0 : 1)));
      setParam(record, p.name, value, "random material");
      continue;
    }
    if (p.rgb) {
      value = random.uniform() < 0.3 ? glm::vec3(float(random.uniform()))
                                     : glm::vec3(float(random.uniform()), float(random.uniform()), float(random.uniform()));
    } else {
      value = glm::vec3(float(p.logScale ? random.logUniform(p.min, p.max) : random.uniform(p.min, p.max)));
    }
    setParam(record, p.name, glm::clamp(value, p.min, p.max), "random material");
  }
  return record;
}

// The angular width of the model's specular lobe (the reference's SpecularLobe), to aim cases at the part of the
// lobe that matters.
double lobeWidth(const gpu::MaterialRecord& m) {
  const std::optional<reference::SpecularLobe> lobe = reference::specularLobe(reference::fromRecord(m));
  return lobe ? std::max(lobe->widths.x, lobe->widths.y) : 1.0;
}

ParityCase canonicalCase(const gpu::MaterialRecord& material, const dvec3& wi, const dvec3& wo) {
  ParityCase c;
  c.input.material = material;
  c.input.wi = vec3(wi);
  c.input.wo = vec3(wo);
  c.input.n = vec3(0.0f, 0.0f, 1.0f);
  c.input.t = vec3(1.0f, 0.0f, 0.0f);
  return c;
}

// Local wi and wo seen through the frame of normal n and tangent hint tHint, as world-space inputs.
ParityCase caseInFrame(const gpu::MaterialRecord& material, const dvec3& wi, const dvec3& wo, const dvec3& n,
                       const dvec3& tHint) {
  const reference::Frame frame = reference::makeFrame(n, tHint);
  const auto toWorld = [&](const dvec3& v) { return v.x * frame.t + v.y * frame.b + v.z * frame.n; };
  ParityCase c;
  c.input.material = material;
  c.input.wi = vec3(toWorld(wi));
  c.input.wo = vec3(toWorld(wo));
  c.input.n = vec3(n);
  c.input.t = vec3(tHint);
  c.canonicalFrame = false;
  return c;
}

// The same local directions seen through a random frame (world-space inputs, tangent not orthogonal to n).
ParityCase framedCase(const gpu::MaterialRecord& material, const dvec3& wi, const dvec3& wo, Random& random) {
  const dvec3 n = random.unitVector();
  const dvec3 tHint = random.unitVector();
  return caseInFrame(material, wi, wo, n, tHint);
}

// A case near the specular peak in a random frame whose tangent hint is `degrees` away from n.
ParityCase leaningFrameCase(const gpu::MaterialRecord& material, Random& random, double degrees) {
  const dvec3 n = random.unitVector();
  const dvec3 side = glm::normalize(glm::cross(n, random.unitVector()));
  const double angle = degrees * M_PI / 180.0;
  const dvec3 tHint = std::cos(angle) * n + std::sin(angle) * side;
  const dvec3 wo = spherical(random.uniform(0.3, 1.0), random.uniform(0.0, 2.0 * M_PI));
  const dvec3 mirror(-wo.x, -wo.y, wo.z);
  const dvec3 wi = glm::normalize(mirror + random.unitVector() * (lobeWidth(material) * random.uniform()));
  return caseInFrame(material, wi, wo, n, tHint);
}

// Random materials and directions: half uniform over the hemisphere, half aimed at the specular lobe.
void addRandomCases(std::uint32_t model, int count, Random& random, std::vector<ParityCase>& cases) {
  for (int i = 0; i < count; ++i) {
    const gpu::MaterialRecord material = randomMaterial(model, random);
    dvec3 wo = spherical(random.cosine(), random.uniform(0.0, 2.0 * M_PI));
    dvec3 wi = spherical(random.cosine(), random.uniform(0.0, 2.0 * M_PI));
    if (i % 2 == 1) {
      // Off the mirror direction by up to three lobe widths.
      const dvec3 mirror(-wo.x, -wo.y, wo.z);
      const dvec3 offset = random.unitVector() * (lobeWidth(material) * 3.0 * random.uniform());
      wi = glm::normalize(mirror + offset);
      if (wi.z <= 0.0) wi = glm::normalize(dvec3(wi.x, wi.y, -wi.z));
    }
    if (isTwoSided(modelInfo(model)) && i % 3 != 0) {
      // Rough glass: two cases in three across the surface, wi near the direction wo refracts to (up to three lobe
      // widths off it; beyond the critical angle the straight-through direction), from either side.
      if (random.uniform() < 0.5) wo.z = -wo.z;
      const auto& params = modelInfo(model).params;  // the index: the parameter of kind eta
      const double eta = getParam(material, std::find_if(params.begin(), params.end(), [](const ParamInfo& q) {
                                              return q.role == "eta" && !q.rgb;
                                            })->name).x;
      const double ratio = wo.z > 0.0 ? 1.0 / eta : eta;  // eta_o / eta_t
      const double sin2T = ratio * ratio * (1.0 - wo.z * wo.z);
      const dvec3 n(0.0, 0.0, wo.z > 0.0 ? 1.0 : -1.0);
      const dvec3 refracted = sin2T < 1.0 ? -ratio * wo + (ratio * std::abs(wo.z) - std::sqrt(1.0 - sin2T)) * n : -wo;
      wi = glm::normalize(refracted + random.unitVector() * (lobeWidth(material) * 3.0 * random.uniform()));
      if (wi.z * wo.z > 0.0) wi.z = -wi.z;
    }
    cases.push_back(i % 4 == 3 ? framedCase(material, wi, wo, random) : canonicalCase(material, wi, wo));
  }
}


// The values of a scalar parameter a corner takes: a log-scale parameter its ends and a decade inside each
// (s of 1, 10, 1000 and 10^4; m and alpha of 0.001, 0.01, 0.1 and 1), an index of refraction 1, 1.0001, 1.5 and
// its maximum, any other its ends and middle.
std::vector<float> cornerValues(const ParamInfo& p) {
  if (p.logScale) return {p.min, 10.0f * p.min, p.max / 10.0f, p.max};
  if (p.role == "eta") return {p.min, p.min + 1e-4f, std::clamp(1.5f, p.min, p.max), p.max};
  return {p.min, 0.5f * (p.min + p.max), p.max};
}

// Parameter corners of the issue, for any model from its table: every combination of two scalar parameters'
// corner values (more than two: each alone), anisotropic slopes 0.0063 and 0.142 (the case issue 9 found), and
// reflectances white, coloured and zero for the diffuse colour and the model's other colours.
std::vector<gpu::MaterialRecord> cornerMaterials(std::uint32_t model) {
  const ModelInfo& info = modelInfo(model);
  std::vector<const ParamInfo*> scalars;
  for (const ParamInfo& p : info.params) {
    if (!p.rgb && !isFileParam(p)) scalars.push_back(&p);
  }
  std::vector<std::vector<std::pair<std::string_view, float>>> scalarSets;
  if (scalars.size() == 2) {
    for (float a : cornerValues(*scalars[0])) {
      for (float b : cornerValues(*scalars[1])) scalarSets.push_back({{scalars[0]->name, a}, {scalars[1]->name, b}});
    }
  } else {
    for (const ParamInfo* p : scalars) {
      for (float v : cornerValues(*p)) scalarSets.push_back({{p->name, v}});
    }
  }
  if (scalarSets.empty()) scalarSets.push_back({});
  const ParamInfo* slopeX = findRole(info, "slope_x");
  const ParamInfo* slopeY = findRole(info, "slope_y");
  if (slopeX && slopeY) scalarSets.push_back({{slopeX->name, 0.0063f}, {slopeY->name, 0.142f}});
  const ParamInfo* diffuse = findRole(info, "diffuse");
  const std::vector<std::pair<glm::vec3, glm::vec3>> reflectances = {
      {glm::vec3(1.0f), glm::vec3(1.0f)}, {glm::vec3(0.9f, 0.5f, 0.1f), glm::vec3(0.2f, 0.6f, 1.0f)},
      {glm::vec3(1.0f), glm::vec3(0.0f)},
      // The specular lobe alone: with a diffuse term beside it, a lobe wrong by 20% at 1e-8 hides under 1/pi.
      {glm::vec3(0.0f), glm::vec3(1.0f)}};
  std::vector<gpu::MaterialRecord> materials;
  for (const auto& set : scalarSets) {
    for (const auto& [d, other] : reflectances) {
      gpu::MaterialRecord record = defaultRecord(model);
      for (const ParamInfo& p : info.params) {
        if (isFileParam(p)) setParam(record, p.name, glm::vec3(float(testFileFor(p, 0))), "corner");
        if (!p.rgb) continue;
        const glm::vec3 value = &p == diffuse ? d : other;
        setParam(record, p.name, glm::clamp(value, glm::vec3(p.min), glm::vec3(p.max)), "corner");
      }
      for (const auto& [name, value] : set) setParam(record, name, glm::vec3(value), "corner");
      materials.push_back(record);
    }
  }
  return materials;
}

// Cosines of 1e-4 to 1e-7 (and down to 1e-15, the library's stated limit of accuracy) at both directions, exactly at the normal and exactly on the horizon, at several
// azimuths between them (mirror plane, retro, perpendicular, just off the mirror plane).
void addHardCases(std::uint32_t model, Random& random, std::vector<ParityCase>& cases) {
  const double cosines[] = {1e-15, 1e-10, 1e-7, 1e-6, 1e-5, 1e-4, 0.5, 1.0, 0.0};
  const double azimuths[] = {M_PI, 0.0, 0.5 * M_PI, M_PI - 1e-3, 0.25 * M_PI};
  for (const gpu::MaterialRecord& material : cornerMaterials(model)) {
    for (double ci : cosines) {
      for (double co : cosines) {
        for (double phi : azimuths) cases.push_back(canonicalCase(material, spherical(ci, 0.0), spherical(co, phi)));
      }
    }
    // Below the horizon, and degenerate frames: zero tangent, tangent along n.
    cases.push_back(canonicalCase(material, spherical(-1e-7, 0.0), spherical(0.5, M_PI)));
    cases.push_back(canonicalCase(material, spherical(0.5, 0.0), spherical(-0.5, M_PI)));
    cases.push_back(canonicalCase(material, dvec3(-1.0, 0.0, 0.0), dvec3(1.0, 0.0, 0.0)));  // wi = -wo
    for (const vec3 t : {vec3(0.0f), vec3(0.0f, 0.0f, 2.0f)}) {
      ParityCase c = canonicalCase(material, spherical(0.6, 0.3), spherical(0.7, 3.0));
      c.input.t = t;
      c.canonicalFrame = false;
      cases.push_back(c);
    }
    // Near the peak through a random frame whose tangent hint leans towards n (30 to 80 degrees off it), where
    // a one-step Gram-Schmidt tilted t by ulp(1) / |t|: sharp anisotropic lobes amplify that.
    for (int i = 0; i < 8; ++i) cases.push_back(leaningFrameCase(material, random, 30.0 + 50.0 * i / 7.0));
    // Grazing mirror configuration through a random frame. Not closer to the horizon than 1e-2: the frame's
    // float32 rounding (~1e-7 in each local component) must stay well below V.H, which is the cosine here.
    cases.push_back(framedCase(material, spherical(1e-2, 0.0), spherical(1e-2, M_PI), random));
  }
}

// A two-sided model (rough glass): every pair of the hard cosines with wi and wo on each side of the surface,
// reflection inside included (beyond the critical angle at cos 0.5 for eta 1.5, and at grazing for every eta),
// and transmission both ways.
void addTwoSidedHardCases(std::uint32_t model, std::vector<ParityCase>& cases) {
  const double cosines[] = {1e-15, 1e-7, 1e-4, 0.2, 0.5, 0.745, 1.0};
  const double azimuths[] = {M_PI, 0.0, 0.5 * M_PI, M_PI - 1e-3};
  for (const gpu::MaterialRecord& material : cornerMaterials(model)) {
    for (double si : {1.0, -1.0}) {
      for (double so : {1.0, -1.0}) {
        for (double ci : cosines) {
          for (double co : cosines) {
            for (double phi : azimuths) {
              cases.push_back(canonicalCase(material, spherical(si * ci, 0.0), spherical(so * co, phi)));
            }
          }
        }
      }
    }
  }
}

double maxRelative(const dvec3& value, const dvec3& reference, double floor) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(value[c] - reference[c]) / std::max(std::abs(reference[c]), floor));
  return worst;
}

struct Local {
  dvec3 wi, wo;
};

Local referenceDirections(const gpu::BrdfEvalCase& c, bool canonicalFrame) {
  if (canonicalFrame) return {dvec3(c.wi), dvec3(c.wo)};
  const reference::Frame frame = reference::makeFrame(glm::normalize(dvec3(c.n)), dvec3(c.t));
  return {reference::toLocal(frame, dvec3(c.wi)), reference::toLocal(frame, dvec3(c.wo))};
}

// Sum over the perturbations of float32 input rounding of the reference's relative change: each of the six
// local components moved by one ulp of itself (and by kFrameUlps ulps of 1 more in a non-canonical frame), and each
// direction's length moved by one ulp (a float vector is unit only to that precision).
double conditioning(const reference::Material& material, const Local& d, bool canonicalFrame, const dvec3& f,
                    double ulps = 1.0) {
  const auto change = [&](const Local& moved) {
    return maxRelative(reference::eval(material, moved.wi, moved.wo), f, kFloor);
  };
  double sum = 0.0;
  for (int which = 0; which < 2; ++which) {
    for (int j = 0; j < 4; ++j) {
      double worst = 0.0;
      for (double sign : {-1.0, 1.0}) {
        Local moved = d;
        dvec3& w = which == 0 ? moved.wi : moved.wo;
        if (j == 3) {
          w *= 1.0 + sign * ulps * kUlp;
        } else {
          const double delta = ulps * (std::abs(w[j]) * kUlp + (canonicalFrame ? 0.0 : kFrameUlps * kUlp));
          if (delta == 0.0) continue;
          w[j] += sign * delta;
        }
        worst = std::max(worst, change(moved));
      }
      sum += worst;
    }
  }
  return sum;
}

bool finiteNonNegative(const vec3& f) {
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(f[c]) || f[c] < 0.0f) return false;
  }
  return true;
}

std::string describe(const gpu::BrdfEvalCase& c) {
  char text[512];
  std::snprintf(text, sizeof text, " | wi %.9g %.9g %.9g | wo %.9g %.9g %.9g | n %.9g %.9g %.9g | t %.9g %.9g %.9g",
                c.wi.x, c.wi.y, c.wi.z, c.wo.x, c.wo.y, c.wo.z, c.n.x, c.n.y, c.n.z, c.t.x, c.t.y, c.t.z);
  return describeModelParams(c.material) + text;
}

class BrdfParityTest : public GpuTest {};

TEST_F(BrdfParityTest, EveryModelMatchesTheReferenceAndIsNeverNanInfOrNegative) {
  Random random(20261122);
  std::vector<ParityCase> cases;
  std::vector<std::size_t> firstOfModel;
  for (std::uint32_t model : kBrdfModels) {
    firstOfModel.push_back(cases.size());
    addRandomCases(model, 2000, random, cases);
    addHardCases(model, random, cases);
    if (isTwoSided(modelInfo(model))) addTwoSidedHardCases(model, cases);
  }
  firstOfModel.push_back(cases.size());

  std::vector<gpu::BrdfEvalCase> inputs;
  for (const ParityCase& c : cases) inputs.push_back(c.input);
  const std::vector<gpu::BrdfEvalValue> values = evaluateBrdfCasesOnce(device(), inputs);
  ASSERT_EQ(values.size(), cases.size());

  for (std::size_t m = 0; m < kBrdfModels.size(); ++m) {
    const std::string name(modelInfo(kBrdfModels[m]).name);
    int bad = 0, horizonNonZero = 0, failures = 0, conditioned = 0, loose = 0;
    double worstOrdinary = 0.0, worstConditioned = 0.0, worstRatio = 0.0;
    std::string worstCase;
    for (std::size_t i = firstOfModel[m]; i < firstOfModel[m + 1]; ++i) {
      const ParityCase& c = cases[i];
      const vec3 f = values[i].f;
      if (!finiteNonNegative(f)) {
        ++bad;
        ADD_FAILURE() << name << ": f = " << f.x << " " << f.y << " " << f.z << " for " << describe(c.input);
        continue;
      }
      const bool offTheHorizon = isTwoSided(modelInfo(kBrdfModels[m])) ? c.input.wi.z != 0.0f && c.input.wo.z != 0.0f
                                                                         : c.input.wi.z > 0.0f && c.input.wo.z > 0.0f;
      if (c.canonicalFrame && !offTheHorizon && f != vec3(0.0f)) {
        ++horizonNonZero;
        ADD_FAILURE() << name << ": f is not 0 below the horizon for " << describe(c.input);
      }
      const reference::Material material = reference::fromRecord(c.input.material);
      const Local d = referenceDirections(c.input, c.canonicalFrame);
      const dvec3 expected = reference::eval(material, d.wi, d.wo);
      const double error = maxRelative(dvec3(f), expected, kFloor);
      const double linear = conditioning(material, d, c.canonicalFrame, expected);
      // A step within kJumpUlps ulps (a bin edge of a tabulated model, measured): the value on either side is the
      // exact value of directions that close, so the bound takes the whole step. A smooth function moves about
      // kJumpUlps times as much there as at one ulp; a step moves far more.
      const double wide = conditioning(material, d, c.canonicalFrame, expected, kJumpUlps);
      const double step = wide > 4.0 * kJumpUlps * linear + kOrdinaryTolerance ? wide : 0.0;
      const double bound = std::max(kOrdinaryTolerance, kConditioningFactor * std::max(linear, step));
      if (bound > kOrdinaryTolerance) {
        ++conditioned;
        loose += bound > 1e-2;
        worstConditioned = std::max(worstConditioned, error);
      } else {
        worstOrdinary = std::max(worstOrdinary, error);
      }
      if (error / bound > worstRatio) {
        worstRatio = error / bound;
        worstCase = describe(c.input) + " device " + std::to_string(f.x) + " reference " + std::to_string(expected.x);
      }
      if (error > bound && ++failures <= 5) {
        ADD_FAILURE() << name << ": relative error " << error << " > bound " << bound << " for " << describe(c.input)
                      << "\n  device " << f.x << " " << f.y << " " << f.z << ", reference " << expected.x << " "
                      << expected.y << " " << expected.z;
      }
    }
    std::printf("%-18s %5zu cases: max rel error %.1e on %zu ordinary cases; %d cases need a conditioning "
                "bound (%d of them above 1e-2), max rel error there %.1e, max error/bound %.2f; NaN/Inf/negative %d\n",
                name.c_str(), firstOfModel[m + 1] - firstOfModel[m], worstOrdinary,
                firstOfModel[m + 1] - firstOfModel[m] - conditioned, conditioned, loose, worstConditioned, worstRatio,
                bad);
    std::printf("%-18s largest error/bound at %s\n", "", worstCase.c_str());
    EXPECT_EQ(bad, 0) << name;
    EXPECT_EQ(horizonNonZero, 0) << name;
    EXPECT_EQ(failures, 0) << name;
    EXPECT_LE(worstOrdinary, kOrdinaryTolerance) << name;
  }
}

// Inputs no parity can be asked of: cosines below the library's 1e-15 (down to the smallest denormal), signed
// zeros, wi = -wo and wi = wo on the horizon, infinite and NaN components. f must still be finite and
// non-negative, and exactly 0 unless both directions are strictly above the horizon (a two-sided model's: off it).
TEST_F(BrdfParityTest, DegenerateInputsGiveFiniteNonNegativeValues) {
  const float tiny[] = {1e-20f, 1e-30f, 1e-38f, 1e-45f, 0.0f, -0.0f, -1e-30f};
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<gpu::BrdfEvalCase> inputs;
  std::vector<bool> mustBeZero;
  const auto add = [&](const gpu::MaterialRecord& material, vec3 wi, vec3 wo, bool zero) {
    gpu::BrdfEvalCase c{};
    c.material = material;
    c.wi = wi;
    c.wo = wo;
    c.n = vec3(0.0f, 0.0f, 1.0f);
    c.t = vec3(1.0f, 0.0f, 0.0f);
    inputs.push_back(c);
    mustBeZero.push_back(zero);
  };
  for (std::uint32_t model : kBrdfModels) {
    for (const gpu::MaterialRecord& material : cornerMaterials(model)) {
      for (float zi : tiny) {
        for (float zo : {1e-20f, 1e-45f, 0.5f, 0.0f}) {
          const bool zero = isTwoSided(modelInfo(model)) ? zi == 0.0f || zo == 0.0f : !(zi > 0.0f && zo > 0.0f);
          add(material, vec3(1.0f, 0.0f, zi), vec3(-1.0f, 0.0f, zo), zero);  // mirror plane
          add(material, vec3(1.0f, 0.0f, zi), vec3(1.0f, 0.0f, zo), zero);   // wi = wo
          add(material, vec3(0.6f, 0.8f, zi), vec3(-0.8f, 0.6f, zo), zero);  // perpendicular
        }
      }
      add(material, vec3(nan, 0.0f, 1.0f), vec3(0.0f, 0.0f, 1.0f), true);
      add(material, vec3(0.0f, 0.0f, nan), vec3(0.0f, 0.0f, 1.0f), true);
      add(material, vec3(0.0f, 0.0f, 1.0f), vec3(inf, 0.0f, 1.0f), true);
      add(material, vec3(0.0f), vec3(0.0f, 0.0f, 1.0f), true);
    }
  }
  const std::vector<gpu::BrdfEvalValue> values = evaluateBrdfCasesOnce(device(), inputs);
  ASSERT_EQ(values.size(), inputs.size());
  int bad = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const vec3 f = values[i].f;
    const bool ok = finiteNonNegative(f) && (!mustBeZero[i] || f == vec3(0.0f));
    if (!ok && ++bad <= 10) {
      ADD_FAILURE() << modelInfo(inputs[i].material.model).name << ": f = " << f.x << " " << f.y << " " << f.z
                    << " for " << describe(inputs[i]);
    }
  }
  std::printf("degenerate inputs: %zu cases, %d NaN/Inf/negative or non-zero below the horizon\n", inputs.size(), bad);
  EXPECT_EQ(bad, 0);
}

// Glass: the three Fresnel factors relative to the reference (floor 1e-12), the two directions absolutely
// (they are unit vectors), total internal reflection exactly, with the same conditioning rule as above.
struct GlassCase {
  float eta;
  dvec3 wi;
  dvec3 n;
  bool canonicalNormal;
};

struct GlassErrors {
  double fresnel = 0.0;  // max over F_exact, F_schlick, F_schlick_naive of the relative error
  double direction = 0.0;  // max over reflect, refract of the absolute error
};

GlassErrors glassDifference(const reference::DielectricEvent& a, const reference::DielectricEvent& b) {
  GlassErrors e;
  for (auto [x, y] : {std::pair{a.fresnelExact, b.fresnelExact}, std::pair{a.fresnelSchlick, b.fresnelSchlick},
                      std::pair{a.fresnelSchlickNaive, b.fresnelSchlickNaive}}) {
    e.fresnel = std::max(e.fresnel, std::abs(x - y) / std::max(std::abs(y), kFresnelFloor));
  }
  e.direction = std::max(glm::length(a.reflected - b.reflected), glm::length(a.refracted - b.refracted));
  return e;
}

reference::DielectricEvent fromValue(const gpu::BrdfEvalValue& v) {
  reference::DielectricEvent r;
  r.fresnelExact = v.fresnelExact;
  r.fresnelSchlick = v.fresnelSchlick;
  r.fresnelSchlickNaive = v.fresnelSchlickNaive;
  r.tir = v.tir != 0;
  r.reflected = dvec3(v.reflected);
  r.refracted = dvec3(v.refracted);
  return r;
}

// The reference's change under one-ulp moves of wi's and n's components and lengths (n's components also by
// 2 ulps of 1 when it is not an axis: the device's dot product carries that absolute error). `tirFlips`
// reports whether any of them changes the TIR decision: then either answer is right.
GlassErrors glassConditioning(const GlassCase& c, const reference::DielectricEvent& expected, bool& tirFlips) {
  GlassErrors sum;
  tirFlips = false;
  for (int which = 0; which < 2; ++which) {
    for (int j = 0; j < 4; ++j) {
      GlassErrors worst;
      for (double sign : {-1.0, 1.0}) {
        dvec3 wi = c.wi, n = c.n;
        dvec3& w = which == 0 ? wi : n;
        if (j == 3) {
          w *= 1.0 + sign * kUlp;
        } else {
          const double delta = std::abs(w[j]) * kUlp + (which == 1 && !c.canonicalNormal ? 2.0 * kUlp : 0.0);
          if (delta == 0.0) continue;
          w[j] += sign * delta;
        }
        const reference::DielectricEvent moved = reference::dielectricEvent(c.eta, wi, n);
        tirFlips = tirFlips || moved.tir != expected.tir;
        const GlassErrors e = glassDifference(moved, expected);
        worst.fresnel = std::max(worst.fresnel, e.fresnel);
        worst.direction = std::max(worst.direction, e.direction);
      }
      sum.fresnel += worst.fresnel;
      sum.direction += worst.direction;
    }
  }
  return sum;
}

std::vector<GlassCase> glassCases() {
  Random random(7);
  std::vector<GlassCase> cases;
  const auto add = [&](float eta, const dvec3& wi, const dvec3& n, bool canonical) {
    cases.push_back({eta, dvec3(vec3(wi)), dvec3(vec3(n)), canonical});
  };
  const dvec3 z(0.0, 0.0, 1.0);
  const float etas[] = {1.0f, 1.0001f, 1.5f, 10.0f};
  for (float eta : etas) {
    // Outside and inside, from normal incidence to exactly grazing.
    for (double c : {1.0, 0.9, 0.5, 0.1, 1e-4, 1e-7, 0.0}) {
      for (double side : {1.0, -1.0}) add(eta, spherical(side * c, 0.7), z, true);
    }
    // From inside at, just below and just above the critical angle sin(theta_c) = 1 / eta.
    if (eta > 1.0f) {
      const double thetaC = std::asin(1.0 / double(eta));
      for (double offset : {0.0, -1e-3, 1e-3, -1e-6, 1e-6}) add(eta, spherical(-std::cos(thetaC + offset), 2.1), z, true);
    }
    for (int i = 0; i < 200; ++i) add(eta, random.unitVector(), z, true);
    for (int i = 0; i < 100; ++i) add(eta, random.unitVector(), random.unitVector(), false);
  }
  for (int i = 0; i < 1000; ++i) {
    add(float(random.uniform(1.0, 10.0)), random.unitVector(), i % 2 ? z : random.unitVector(), i % 2 == 1);
  }
  return cases;
}

TEST_F(BrdfParityTest, GlassMatchesTheReference) {
  const std::vector<GlassCase> cases = glassCases();
  std::vector<gpu::BrdfEvalCase> inputs;
  for (const GlassCase& c : cases) {
    gpu::BrdfEvalCase input{};
    input.material = defaultRecord(modelId("glass"));
    setParam(input.material, "eta", glm::vec3(c.eta), "glass case");
    input.wi = vec3(c.wi);
    input.n = vec3(c.n);
    inputs.push_back(input);
  }
  const std::vector<gpu::BrdfEvalValue> values = evaluateBrdfCasesOnce(device(), inputs);
  ASSERT_EQ(values.size(), cases.size());

  int bad = 0, failures = 0, ambiguousTir = 0, conditioned = 0;
  GlassErrors worstOrdinary;
  double worstRatio = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const GlassCase& c = cases[i];
    const reference::DielectricEvent device = fromValue(values[i]);
    const reference::DielectricEvent expected = reference::dielectricEvent(c.eta, c.wi, c.n);
    const double deviceNumbers[] = {device.fresnelExact, device.fresnelSchlick, device.fresnelSchlickNaive,
                                    device.reflected.x,  device.reflected.y,    device.reflected.z,
                                    device.refracted.x,  device.refracted.y,    device.refracted.z};
    bool finite = true;
    for (double x : deviceNumbers) finite = finite && std::isfinite(x);
    const bool fresnelInRange = device.fresnelExact >= 0.0 && device.fresnelExact <= 1.0 &&
                                device.fresnelSchlick >= 0.0 && device.fresnelSchlickNaive >= 0.0;
    if (!finite || !fresnelInRange) {
      ++bad;
      ADD_FAILURE() << "glass eta " << c.eta << " wi " << c.wi.x << " " << c.wi.y << " " << c.wi.z
                    << ": non-finite or out-of-range value";
      continue;
    }
    bool tirFlips = false;
    const GlassErrors condition = glassConditioning(c, expected, tirFlips);
    if (device.tir != expected.tir) {
      if (tirFlips) {
        ++ambiguousTir;  // at the critical angle to within input rounding: either answer is right
        continue;
      }
      ++failures;
      ADD_FAILURE() << "glass eta " << c.eta << " wi " << c.wi.x << " " << c.wi.y << " " << c.wi.z
                    << ": tir " << device.tir << " but the reference says " << expected.tir;
      continue;
    }
    if (device.tir) {
      EXPECT_EQ(values[i].refracted, vec3(0.0f)) << "refracted must be zero under TIR";
    }
    const GlassErrors error = glassDifference(device, expected);
    const double fresnelBound = std::max(kOrdinaryTolerance, kConditioningFactor * condition.fresnel);
    const double directionBound = std::max(kOrdinaryTolerance, kConditioningFactor * condition.direction);
    if (fresnelBound > kOrdinaryTolerance || directionBound > kOrdinaryTolerance) ++conditioned;
    if (fresnelBound == kOrdinaryTolerance) worstOrdinary.fresnel = std::max(worstOrdinary.fresnel, error.fresnel);
    if (directionBound == kOrdinaryTolerance) {
      worstOrdinary.direction = std::max(worstOrdinary.direction, error.direction);
    }
    worstRatio = std::max({worstRatio, error.fresnel / fresnelBound, error.direction / directionBound});
    if ((error.fresnel > fresnelBound || error.direction > directionBound) && ++failures <= 5) {
      ADD_FAILURE() << "glass eta " << c.eta << " wi " << c.wi.x << " " << c.wi.y << " " << c.wi.z << " n " << c.n.x
                    << " " << c.n.y << " " << c.n.z << ": Fresnel error " << error.fresnel << " (bound "
                    << fresnelBound << "), direction error " << error.direction << " (bound " << directionBound
                    << ")\n  device F " << device.fresnelExact << " " << device.fresnelSchlick << " "
                    << device.fresnelSchlickNaive << ", reference F " << expected.fresnelExact << " "
                    << expected.fresnelSchlick << " " << expected.fresnelSchlickNaive;
    }
  }
  std::printf("%-18s %5zu cases: max rel error %.2e (Fresnel), max abs error %.2e (directions) on ordinary "
              "cases; %d with a conditioning bound, worst error/bound %.2f; %d TIR decisions within input rounding "
              "of the critical angle; NaN/Inf/out of range %d\n",
              "glass", cases.size(), worstOrdinary.fresnel, worstOrdinary.direction, conditioned, worstRatio,
              ambiguousTir, bad);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(failures, 0);
  EXPECT_LE(worstOrdinary.fresnel, kOrdinaryTolerance);
  EXPECT_LE(worstOrdinary.direction, kOrdinaryTolerance);
}

}  // namespace
}  // namespace raylab::test
