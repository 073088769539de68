// OpenPBR Surface 1.1.1 (Academy Software Foundation), its "Reduction to a mixture of lobes" with non-reciprocal
// albedo scaling, as the specification's sections write each piece (docs/brdfs.md, "openpbr"): the F82-tint
// metal with Kulla & Conty's multiple scattering, the glossy-diffuse dielectric (GGX reflection over EON scaled by
// 1 - E_spec(wo)), the metalness mix, the coat (its reflection, view-dependent absorption, roughening and
// darkening), the thin film, the fuzz over all (Zeltner et al.'s LTC, reference/fuzz.h), the translucent base
// (refraction through the base's interface; two-sided), the subsurface in its short-radius limit and thin walls.
// The directional albedos E come from the build-time table (reference/albedo_tables.h); the rest is written here in
// double from the formulas, not from the GLSL.
#include <algorithm>
#include <cmath>
#include <complex>

#include "generated/reference_params.h"
#include "reference/albedo_tables.h"
#include "reference/fuzz.h"
#include "reference/ggx.h"
#include "reference/sampling.h"
#include "reference/terms.h"
#include "reference/thin_film.h"

namespace raylab::reference {
namespace {

struct Alphas {
  double t, b;
};

// alpha_t = r^2 sqrt(2 / (1 + (1 - a)^2)), alpha_b = (1 - a) alpha_t; the library's floor of 0.001 on each.
Alphas alphasOf(double roughness, double anisotropy) {
  const double alphaT = roughness * roughness * std::sqrt(2.0 / (1.0 + (1.0 - anisotropy) * (1.0 - anisotropy)));
  return {std::max(alphaT, 1e-3), std::max((1.0 - anisotropy) * alphaT, 1e-3)};
}

double baseRoughness(const OpenpbrParams& p) {
  const double r = p.specular_roughness, c = p.coat_roughness;
  return (1.0 - p.coat_weight) * r + p.coat_weight * std::pow(std::min(1.0, std::pow(r, 4) + 2.0 * std::pow(c, 4)), 0.25);
}
// The coat's own frame in the base's (openpbr.glsl, openpbrCoatFrame): normal (x, y, sqrt(1 - x^2 - y^2)) at most 88
// degrees from the base's, tangent the base's turned by the angle and made orthogonal to it. Directions below the
// coat's horizon are lifted to 1e-15 above it, as the device's one-sided lobes lift theirs.
struct CoatFrame {
  dvec3 t{1.0, 0.0, 0.0}, b{0.0, 1.0, 0.0}, n{0.0, 0.0, 1.0};
  dvec3 to(const dvec3& w) const { return {glm::dot(w, t), glm::dot(w, b), glm::dot(w, n)}; }
  dvec3 from(const dvec3& w) const { return w.x * t + w.y * b + w.z * n; }
};
CoatFrame coatFrameOf(const OpenpbrParams& p) {
  CoatFrame f;
  // The base's own frame, exactly, and without the trigonometry (a fit evaluates the coat millions of times).
  if (p.geometry_coat_normal_x == 0.0 && p.geometry_coat_normal_y == 0.0 && p.geometry_coat_tangent_angle == 0.0) {
    return f;
  }
  dvec2 slope(p.geometry_coat_normal_x, p.geometry_coat_normal_y);
  constexpr double kMaxSine2 = 0.9988;
  if (glm::dot(slope, slope) > kMaxSine2) slope *= std::sqrt(kMaxSine2 / glm::dot(slope, slope));
  f.n = dvec3(slope, std::sqrt(1.0 - glm::dot(slope, slope)));
  const dvec3 t(std::cos(p.geometry_coat_tangent_angle), std::sin(p.geometry_coat_tangent_angle), 0.0);
  f.t = glm::normalize(t - f.n * glm::dot(f.n, t));
  f.b = glm::cross(f.n, f.t);
  return f;
}
dvec3 liftedInCoat(const CoatFrame& f, const dvec3& w) {
  const dvec3 c = f.to(w);
  return {c.x, c.y, std::max(c.z, 1e-15)};
}

Alphas baseAlphas(const OpenpbrParams& p) { return alphasOf(baseRoughness(p), p.specular_roughness_anisotropy); }
Alphas coatAlphas(const OpenpbrParams& p) { return alphasOf(p.coat_roughness, p.coat_roughness_anisotropy); }

// sqrt(F0) of the base dielectric: the index relative to the coat's mix of media (its inverse below 1), its F0
// scaled by specular_weight and clamped to 1 (OpenPBR, "Dielectric base").
double specularEps(const OpenpbrParams& p) {
  double eta = (1.0 - p.coat_weight) * p.specular_ior + p.coat_weight * p.specular_ior / p.coat_ior;
  if (eta < 1.0) eta = 1.0 / eta;
  return std::sqrt(std::clamp(p.specular_weight * F0FromEta(eta), 0.0, 1.0));
}
double coatEps(const OpenpbrParams& p) { return (p.coat_ior - 1.0) / (p.coat_ior + 1.0); }

double fresnel(double cosI, double eps) {
  if (eps >= 0.9999) return 1.0;  // an index beyond float's reach in the kernels: a perfect mirror
  return F_DielectricFromOutside((1.0 + eps) / (1.0 - eps), cosI);
}

// The width along w's azimuth, sqrt(alpha_t^2 cos^2 phi + alpha_b^2 sin^2 phi) (Smith's masking of w sees it); the
// tables of isotropic albedos are read at it. At the normal sqrt(alpha_t alpha_b).
double projectedAlpha(const Alphas& a, const dvec3& w) {
  const double s2 = w.x * w.x + w.y * w.y;
  if (!(s2 > 0.0)) return std::sqrt(a.t * a.b);
  return std::sqrt((a.t * a.t * w.x * w.x + a.b * a.b * w.y * w.y) / s2);
}

double cosineToHalfVector(const dvec3& wo, const dvec3& h) { return std::clamp(glm::dot(wo, h) / glm::length(h), 0.0, 1.0); }

// D G1(wi) G1(wo) / (4 cos_i cos_o) of a GGX lobe.
double microfacet(const dvec3& wi, const dvec3& wo, const Alphas& a) {
  return D_GGX(wi + wo, a.t, a.b) * G1_GGX(wi, a.t, a.b) * G1_GGX(wo, a.t, a.b) / (4.0 * wi.z * wo.z);
}

// The F82-tint metal (Kutz et al. 2021): Schlick's curve less b mu (1 - mu)^6, which meets specular_color times
// Schlick's curve at mu = 1/7.
constexpr double kMuBar = 1.0 / 7.0;
dvec3 f82Coefficient(const dvec3& F0, const dvec3& tint) {
  return F_Schlick(F0, kMuBar) * (dvec3(1.0) - tint) / (kMuBar * std::pow(1.0 - kMuBar, 6));
}
dvec3 f82(const dvec3& F0, const dvec3& b, double mu) {
  return glm::clamp(F_Schlick(F0, mu) - b * (mu * std::pow(1.0 - mu, 6)), 0.0, 1.0);
}

// Kulla & Conty's compensation with the F82 curve's mean 2 integral F mu dmu = F0 + (1 - F0)/21 - b/126
// (the Beta integrals of mu (1 - mu)^5 and mu^2 (1 - mu)^6), over the F = 1 slice of the layering table (its finer
// axes keep a white metal's furnace within the table's accuracy at grazing angles).
dvec3 metalMultipleScattering(const dvec3& F0, const dvec3& b, double weight, const Alphas& a, const dvec3& wi,
                              const dvec3& wo) {
  const double alpha = std::sqrt(a.t * a.b);
  const double averageLoss = mirrorAverageLoss(alpha);
  if (!(averageLoss > 1e-6)) return dvec3(0.0);
  const double eAvg = 1.0 - averageLoss;
  const dvec3 fAvg = glm::clamp(weight * (F0 + (dvec3(1.0) - F0) / 21.0 - b / 126.0), 0.0, 1.0);
  const dvec3 fMs = fAvg * fAvg * eAvg / (dvec3(1.0) - fAvg * averageLoss);
  const double lossO = dielectricReflectionLoss(wo.z, projectedAlpha(a, wo), 1.0);
  const double lossI = dielectricReflectionLoss(wi.z, projectedAlpha(a, wi), 1.0);
  return fMs * std::max(lossO * lossI / (kPi * averageLoss), 0.0);
}

// The thin film (OpenPBR, "Thin film"): its reflectance over the dielectric base, whose index relative to the film's
// outside is (1 + eps) / (1 - eps), and over the metal, whose index comes from its F0 and edge tint by
// Gulbrandsen's map. The film's outside is taken as the ambient medium even under a coat (a film of index below
// the coat's would reflect totally at grazing angles: the false ring implementers report).
dvec3 filmOverDielectric(const OpenpbrParams& p, double eps, double cosTheta) {
  if (eps >= 0.9999) return dvec3(1.0);
  const std::complex<double> eta((1.0 + eps) / (1.0 - eps));
  const std::complex<double> base[3] = {eta, eta, eta};
  return thinFilmReflectance(cosTheta, p.thin_film_ior, 1000.0 * p.thin_film_thickness, base);
}
// Over the metal the film changes the light the metal absorbs: F = 1 - (1 - F82)(1 - R_film)/(1 - R_bare), R of
// Gulbrandsen's index with and without the film. It is R_film where the index reproduces F82 (at normal incidence,
// by construction), and 1 for a white metal: a film over a perfect mirror reflects everything.
dvec3 filmOverMetal(const OpenpbrParams& p, const dvec3& F0, const dvec3& f82Value, double cosTheta) {
  std::complex<double> base[3];
  for (int c = 0; c < 3; ++c) base[c] = metalIndexFromTint(F0[c], p.specular_color[c]);
  const dvec3 film = thinFilmReflectance(cosTheta, p.thin_film_ior, 1000.0 * p.thin_film_thickness, base);
  dvec3 F;
  for (int c = 0; c < 3; ++c) {
    const double absorbedBare = std::max(1.0 - bareReflectance(cosTheta, base[c]), 1e-9);
    F[c] = std::clamp(1.0 - (1.0 - f82Value[c]) * (1.0 - film[c]) / absorbedBare, 0.0, 1.0);
  }
  return F;
}

// The directional albedo of the film-coated dielectric's reflection, which the glossy-diffuse base passes the rest
// of: the table's E_spec(wo) of the bare interface plus what the film changes, E_film - E_bare, both by one
// quadrature of kFilmAlbedoPoints visible normals (the estimator F(wo.h) G1(wi), at fixed stratified points). The
// quadrature's own error mostly cancels in the difference, and a base that reflects almost nothing (eps near 0
// under a coat) needs no ratio to it.
constexpr int kFilmAlbedoSide = 3;
dvec3 filmAlbedo(const OpenpbrParams& p, double eps, const Alphas& alpha, const dvec3& wo, double eSpec) {
  dvec3 film(0.0);
  double bare = 0.0;
  for (int i = 0; i < kFilmAlbedoSide; ++i) {
    for (int j = 0; j < kFilmAlbedoSide; ++j) {
      const dvec2 u((i + 0.5) / kFilmAlbedoSide, (j + 0.5) / kFilmAlbedoSide);
      const dvec3 h = sampleGgxVisibleNormal(wo, alpha.t, alpha.b, u);
      const dvec3 wi = reflectAbout(wo, h);
      if (!(wi.z > 0.0)) continue;
      const double c = std::clamp(glm::dot(wo, h), 0.0, 1.0), g = G1_GGX(wi, alpha.t, alpha.b);
      film += g * filmOverDielectric(p, eps, c);
      bare += g * fresnel(c, eps);
    }
  }
  const double n = kFilmAlbedoSide * kFilmAlbedoSide;
  return glm::clamp(dvec3(eSpec) + (film - bare) / n, 0.0, 1.0);
}

// The fixed mixture: {specular lobes against the cosine lobe, the coat within the specular lobes, the fuzz within
// them}.
dvec3 lobeProbabilities(const OpenpbrParams& p) {
  const double eps = specularEps(p);
  const double diffuse = (1.0 - p.base_metalness) * p.base_weight * (p.base_color.x + p.base_color.y + p.base_color.z) / 3.0;
  const double base = p.base_metalness + (1.0 - p.base_metalness) * std::min(1.0, 4.0 * eps * eps);
  const double coat = 0.25 * p.coat_weight;
  const double fuzz = 0.5 * p.fuzz_weight * (p.fuzz_color.x + p.fuzz_color.y + p.fuzz_color.z) / 3.0;
  const double specular = base + coat + fuzz;
  return {diffuse + specular > 0.0 ? specular / (diffuse + specular) : 0.5, specular > 0.0 ? coat / specular : 0.0,
          specular > 0.0 ? fuzz / specular : 0.0};
}

// The fuzz over everything (OpenPBR, "Fuzz"): F fuzz_color f_fuzz + (1 - F E_fuzz(wo)) f_below. Its lobe is broad, so
// it joins the diffuse term, which the albedo quadrature integrates over the hemisphere's (cos, azimuth).
Lobes fuzzOver(const OpenpbrParams& p, const Lobes& below, const dvec3& wi, const dvec3& wo) {
  const double F = p.fuzz_weight;
  if (!(F > 0.0)) return below;
  const FuzzLobe lobe = fuzzLobe(wo.z, p.fuzz_roughness);
  const double passed = 1.0 - F * lobe.albedo;
  return {F * p.fuzz_color * (lobe.albedo * fuzzDensity(wi, wo, lobe) / wi.z) + passed * below.diffuse,
          passed * below.specular};
}

// The solid's GGX interface of index specular_ior (the translucent base, below), tinted by transmission_color on the
// way in when there is no volume.
GgxDielectricParams interfaceOf(const OpenpbrParams& p) {
  const Alphas a = baseAlphas(p);
  return {a.t, a.b, std::max(p.specular_ior, 1.001),
          p.transmission_depth > 0.0 ? dvec3(1.0) : p.transmission_color};
}
// Dispersion (openpbr.glsl says how): the index at the Fraunhofer lines C, d and F for red, green and blue, by
// KHR_materials_dispersion's Cauchy form with V = abbe_number / scale; the interface then refracts each channel by
// its own index, sampled by a channel drawn uniformly, and the dielectric's Fresnel term takes it too.
bool dispersive(const OpenpbrParams& p) { return p.transmission_dispersion_scale > 0.0; }
GgxDielectricParams channelInterface(const OpenpbrParams& p, int channel) {
  GgxDielectricParams q = interfaceOf(p);
  if (!dispersive(p)) return q;
  constexpr double kLambda[3] = {656.3, 587.6, 486.1};
  const double V = std::max(p.transmission_dispersion_abbe_number, 1.0) / p.transmission_dispersion_scale;
  q.eta = std::max(p.specular_ior + (p.specular_ior - 1.0) / V *
                                        (523655.0 / (kLambda[channel] * kLambda[channel]) - 1.5168),
                   1.001);
  return q;
}

// The reflection off the outside: every layer, the glossy-diffuse part of albedo diffuseAlbedo (diffuseAlbedoOf).
Lobes reflectionLobes(const OpenpbrParams& p, const dvec3& wi, const dvec3& wo, const dvec3& diffuseAlbedo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double C = p.coat_weight, M = p.base_metalness;
  const dvec3 h = wi + wo;
  const double cosH = cosineToHalfVector(wo, h);
  const Alphas alpha = baseAlphas(p);
  const double alphaTable = std::sqrt(alpha.t * alpha.b);
  const double eps = specularEps(p);
  const dvec3 rho = p.base_weight * p.base_color;

  // Glossy-diffuse dielectric: f_spec + (1 - E_spec(wo)) f_EON.
  const double W = p.thin_film_weight;
  const double loss = dielectricReflectionLoss(wo.z, projectedAlpha(alpha, wo), eps);  // 1 - E_spec(wo)
  dvec3 F = dvec3(fresnel(cosH, eps)), passed(loss);
  for (int c = 0; dispersive(p) && c < 3; ++c) {  // each channel's Fresnel term at its own index, as its refraction's
    OpenpbrParams channel = p;
    channel.specular_ior = channelInterface(p, c).eta;
    F[c] = fresnel(cosH, specularEps(channel));
  }
  if (W > 0.0 && M < 1.0) {  // the dielectric's film (a pure metal has none to show)
    F = (1.0 - W) * F + W * filmOverDielectric(p, eps, cosH);
    const dvec3 eFilm = filmAlbedo(p, eps, alpha, wo, 1.0 - loss);
    passed = glm::max(dvec3(1.0) - ((1.0 - W) * (1.0 - loss) + W * eFilm), 0.0);
  }
  const dvec3 specular = p.specular_color * F * microfacet(wi, wo, alpha);
  const dvec3 diffuse = passed * eonEval(EonParams{diffuseAlbedo, p.base_diffuse_roughness}, wi, wo).sum();
  // Metal.
  const dvec3 b = f82Coefficient(rho, p.specular_color);
  dvec3 metalF = f82(rho, b, cosH);
  if (W > 0.0 && M > 0.0) metalF = (1.0 - W) * metalF + W * filmOverMetal(p, rho, metalF, cosH);
  const dvec3 metal = glm::min(p.specular_weight * metalF, dvec3(1.0)) * microfacet(wi, wo, alpha) +
                      metalMultipleScattering(rho, b, p.specular_weight, alpha, wi, wo);

  Lobes substrate{(1.0 - M) * diffuse, (1.0 - M) * specular + M * metal};
  if (!(C > 0.0)) return fuzzOver(p, substrate, wi, wo);

  // The coat: its reflection, and what it passes to the base, in its own frame (nothing reflected where a
  // direction is below its horizon).
  const CoatFrame frame = coatFrameOf(p);
  const dvec3 wiCoat = liftedInCoat(frame, wi), woCoat = liftedInCoat(frame, wo);
  const bool above = frame.to(wi).z > 0.0 && frame.to(wo).z > 0.0;
  const Alphas alphaCoat = coatAlphas(p);
  const double epsCoat = coatEps(p);
  // f cos is the coat's own (times the cosine to its normal, divided by the base's the integrator applies): the coat
  // returns at most its albedo E_coat.
  const double coat = above ? fresnel(cosineToHalfVector(woCoat, wiCoat + woCoat), epsCoat) *
                                  microfacet(wiCoat, woCoat, alphaCoat) * (wiCoat.z / wi.z)
                            : 0.0;
  const double coatPassed = dielectricReflectionLoss(woCoat.z, projectedAlpha(alphaCoat, woCoat), epsCoat);  // 1 - E_coat(wo)
  const auto refractedCosine = [&p](double c) { return std::sqrt(1.0 - (1.0 - c * c) / (p.coat_ior * p.coat_ior)); };
  const double pathLength = 0.5 * (1.0 / refractedCosine(wiCoat.z) + 1.0 / refractedCosine(woCoat.z));
  const dvec3 T(std::pow(p.coat_color.x, pathLength), std::pow(p.coat_color.y, pathLength),
                std::pow(p.coat_color.z, pathLength));
  dvec3 darkening(1.0);
  if (p.coat_darkening > 0.0) {
    // E_b, the base's albedo at normal incidence; K, the share of the light leaving the base that the coat
    // reflects back (OpenPBR, "Darkening").
    const double eSpecNormal = 1.0 - dielectricReflectionLoss(1.0, alphaTable, eps);
    const dvec3 eBase = (1.0 - M) * (p.specular_color * eSpecNormal + (1.0 - eSpecNormal) * diffuseAlbedo) +
                        M * glm::min(p.specular_weight * rho, dvec3(1.0));
    const double kRough = 1.0 - (1.0 - averageFresnel(epsCoat)) / (p.coat_ior * p.coat_ior);  // the table's E_F
    const double kSmooth = fresnel(woCoat.z, epsCoat);
    const double roughnessEstimate = (1.0 - M) * ((1.0 - eps * eps) + eps * eps * p.specular_roughness) + M * p.specular_roughness;
    const double K = (1.0 - roughnessEstimate) * kSmooth + roughnessEstimate * kRough;
    for (int c = 0; c < 3; ++c) {
      // E_b, K <= 1 keep Delta <= 1; a white base under a coat that returns everything (0/0) is not darkened.
      const double denominator = 1.0 - eBase[c] * K;
      const double delta = denominator > 0.0 ? (1.0 - K) / denominator : 1.0;
      darkening[c] = 1.0 + C * p.coat_darkening * (delta - 1.0);
    }
  }
  const dvec3 below = ((1.0 - C) + C * T * coatPassed) * darkening;
  return fuzzOver(p, {below * substrate.diffuse, C * coat + below * substrate.specular}, wi, wo);
}

// The specular lobes: the coat's GGX with probability q, the fuzz's LTC with probability z, else the base's GGX
// (u.x stretched back to [0, 1) for the lobe's sampler).
dvec3 sampleReflectionSpecular(const OpenpbrParams& p, const dvec3& wo, const dvec2& u) {
  const dvec3 probabilities = lobeProbabilities(p);
  const double q = probabilities.y, z = probabilities.z;
  if (u.x >= q && u.x < q + z) {
    return sampleFuzz(wo, fuzzLobe(wo.z, p.fuzz_roughness), dvec2(std::min((u.x - q) / z, 1.0 - 1e-12), u.y));
  }
  if (u.x < q) {  // the coat's lobe, in its frame
    const CoatFrame frame = coatFrameOf(p);
    const dvec3 w = liftedInCoat(frame, wo);
    const Alphas a = coatAlphas(p);
    return frame.from(reflectAbout(w, sampleGgxVisibleNormal(w, a.t, a.b, dvec2(std::min(u.x / q, 1.0 - 1e-12), u.y))));
  }
  const Alphas a = baseAlphas(p);
  const double v = (u.x - q - z) / (1.0 - q - z);
  return reflectAbout(wo, sampleGgxVisibleNormal(wo, a.t, a.b, dvec2(std::min(v, 1.0 - 1e-12), u.y)));
}

double reflectionSpecularPdf(const OpenpbrParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 probabilities = lobeProbabilities(p);
  const double q = probabilities.y, z = probabilities.z;
  const Alphas base = baseAlphas(p), coat = coatAlphas(p);
  const CoatFrame frame = coatFrameOf(p);
  double density = (1.0 - q - z) * ggxReflectionPdf(wi + wo, wo, base.t, base.b) +
                   q * ggxReflectionPdf(frame.to(wi + wo), liftedInCoat(frame, wo), coat.t, coat.b);
  if (z > 0.0) density += z * fuzzDensity(wi, wo, fuzzLobe(wo.z, p.fuzz_roughness));
  return density;
}

// The reflection's mixture: the cosine lobe, or the specular lobes with probability lobeProbabilities(p).x.
dvec3 sampleReflection(const OpenpbrParams& p, const dvec3& wo, const dvec3& u) {
  if (!(wo.z > 0.0)) return dvec3(0.0);
  const dvec2 rest(u.y, u.z);
  return u.x < lobeProbabilities(p).x ? sampleReflectionSpecular(p, wo, rest) : sampleCosineHemisphere(rest);
}
double reflectionPdf(const OpenpbrParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return 0.0;
  const double specular = lobeProbabilities(p).x;
  return (1.0 - specular) * pdfCosineHemisphere(wi) + specular * reflectionSpecularPdf(p, wi, wo);
}

// The translucent base (OpenPBR, "Translucent base"; openpbr.glsl says how): T = transmission_weight of the
// dielectric refracts through the base's own GGX interface of index specular_ior, tinted by transmission_color on
// the way in when there is no volume (transmission_depth 0).
double transmissionShare(const OpenpbrParams& p) { return p.transmission_weight * (1.0 - p.base_metalness); }
dvec3 interfaceEval(const OpenpbrParams& p, const dvec3& wi, const dvec3& wo) {
  if (!dispersive(p)) return ggxDielectricEval(interfaceOf(p), wi, wo).sum();
  dvec3 f;
  for (int c = 0; c < 3; ++c) f[c] = ggxDielectricEval(channelInterface(p, c), wi, wo).sum()[c];
  return f;
}
double interfacePdf(const OpenpbrParams& p, const dvec3& wi, const dvec3& wo) {
  if (!dispersive(p)) return ggxDielectricPdf(interfaceOf(p), wi, wo);
  double pdf = 0.0;
  for (int c = 0; c < 3; ++c) pdf += ggxDielectricPdf(channelInterface(p, c), wi, wo);
  return pdf / 3.0;
}
dvec3 interfaceSample(const OpenpbrParams& p, const dvec3& wo, dvec3 u) {
  int channel = 1;
  if (dispersive(p)) {
    channel = std::min(static_cast<int>(3.0 * u.x), 2);
    u.x = std::min(3.0 * u.x - channel, 1.0 - 1e-12);
  }
  return ggxDielectricSample(channelInterface(p, channel), wo, u);
}
constexpr double kInterfaceShare = 0.75;  // of the sampler's choices when wo is outside (openpbr.glsl)

// A thin wall (geometry_thin_walled): the same material on both faces, the translucent base's light straight
// through, the subsurface a sheet that scatters the share (1 + g) / 2 through and the rest back, g its
// subsurface_scatter_anisotropy (openpbr.glsl).
bool thinWalled(const OpenpbrParams& p) { return p.geometry_thin_walled >= 0.5; }
double thinThrough(const OpenpbrParams& p) {
  return thinWalled(p) ? 0.5 * (1.0 + std::clamp(p.subsurface_scatter_anisotropy, -1.0, 1.0)) : 0.0;
}
dvec3 diffuseAlbedoOf(const OpenpbrParams& p, double T) {
  const double sheet = 1.0 - thinThrough(p), S = p.subsurface_weight;
  return (1.0 - T) * ((1.0 - S) * p.base_weight * p.base_color + S * sheet * p.subsurface_color);
}
// At most 0.9: the reflection keeps a share of the samples (openpbr.glsl).
double thinMirrorShare(const OpenpbrParams& p, double T) {
  return std::min(thinThrough(p) * p.subsurface_weight * (1.0 - T) * (1.0 - p.base_metalness), 0.9);
}

// What the coat and the fuzz pass of light crossing them along the outside direction w.
dvec3 layersPassed(const OpenpbrParams& p, const dvec3& wBase) {
  dvec3 passed(1.0);
  if (p.coat_weight > 0.0) {
    const dvec3 w = liftedInCoat(coatFrameOf(p), wBase);  // the coat's terms in its frame
    const double loss = dielectricReflectionLoss(w.z, projectedAlpha(coatAlphas(p), w), coatEps(p));
    const double cosT = std::sqrt(1.0 - (1.0 - w.z * w.z) / (p.coat_ior * p.coat_ior));
    for (int c = 0; c < 3; ++c) {
      const double crossing = std::pow(std::max(p.coat_color[c], 0.0), 0.5 / cosT) * loss;
      passed[c] *= 1.0 - p.coat_weight + p.coat_weight * crossing;
    }
  }
  if (p.fuzz_weight > 0.0) passed *= 1.0 - p.fuzz_weight * fuzzLobe(wBase.z, p.fuzz_roughness).albedo;
  return passed;
}

// Through a thin wall, wo above and wi below: the base's GGX lobe mirrored through the surface with 1 - F, and the
// thin subsurface's diffuse transmission, under what the layers pass along wo.
dvec3 thinTransmission(const OpenpbrParams& p, double T, const dvec3& wi, const dvec3& wo) {
  const dvec3 mirrored(wi.x, wi.y, -wi.z);
  const Alphas alpha = baseAlphas(p);
  const double eps = specularEps(p);
  const dvec3 straight = T * p.transmission_color * (1.0 - fresnel(cosineToHalfVector(wo, mirrored + wo), eps)) *
                         microfacet(mirrored, wo, alpha);
  const double passed = dielectricReflectionLoss(wo.z, projectedAlpha(alpha, wo), eps);  // 1 - E_spec(wo)
  const dvec3 diffuse = (1.0 - T) * (1.0 - p.base_metalness) * p.subsurface_weight * thinThrough(p) *
                        p.subsurface_color * passed * kInvPi;
  return (straight + diffuse) * layersPassed(p, wo);
}
double thinInterfacePdf(const OpenpbrParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 w(wi.x, wi.y, std::abs(wi.z));
  const Alphas alpha = baseAlphas(p);
  const double F = fresnel(cosineToHalfVector(wo, w + wo), specularEps(p));
  return (wi.z < 0.0 ? 1.0 - F : F) * ggxReflectionPdf(w + wo, wo, alpha.t, alpha.b);
}

}  // namespace

Lobes openpbrEval(const OpenpbrParams& p, const dvec3& wiIn, const dvec3& woIn) {
  dvec3 wi = wiIn, wo = woIn;
  const double T = transmissionShare(p);
  const bool thin = thinWalled(p);
  if (T > 0.0 && !thin && !(wi.z > 0.0 && wo.z > 0.0)) {
    if (!finiteAndOffTheSurface(wi) || !finiteAndOffTheSurface(wo)) return {};
    dvec3 f = T * interfaceEval(p, wi, wo);
    if (wi.z * wo.z < 0.0) f *= layersPassed(p, wi.z > 0.0 ? wi : wo);
    return {dvec3(0.0), f};
  }
  if ((thin || !(T > 0.0)) && wo.z < 0.0) {  // an opaque surface or a thin wall seen from behind
    wi.z = -wi.z;
    wo.z = -wo.z;
  }
  if (thin && wi.z < 0.0 && wo.z > 0.0) {
    if (!finiteAndOffTheSurface(wi) || !finiteAndOffTheSurface(wo)) return {};
    return {dvec3(0.0), thinTransmission(p, T, wi, wo)};
  }
  return reflectionLobes(p, wi, wo, diffuseAlbedoOf(p, T));
}

dvec3 openpbrSample(const OpenpbrParams& p, const dvec3& wo, const dvec3& u) {
  const double T = transmissionShare(p);
  const bool thin = thinWalled(p);
  const bool behind = (thin || !(T > 0.0)) && wo.z < 0.0;
  const dvec3 w = behind ? dvec3(wo.x, wo.y, -wo.z) : wo;
  const double share = T > 0.0 ? (w.z > 0.0 ? kInterfaceShare * T : 1.0) : 0.0;
  dvec3 wi;
  if (u.x < share) {
    const double v = std::min(u.x / share, 1.0 - 1e-12);
    if (thin) {
      const Alphas alpha = baseAlphas(p);
      const dvec3 m = sampleGgxVisibleNormal(w, alpha.t, alpha.b, dvec2(u.y, u.z));
      wi = reflectAbout(w, m);
      if (!(wi.z > 0.0)) return dvec3(0.0);
      if (!(v < fresnel(std::clamp(glm::dot(w, m), 0.0, 1.0), specularEps(p)))) wi.z = -wi.z;
    } else {
      wi = interfaceSample(p, w, dvec3(v, u.y, u.z));
    }
  } else {
    const double q = thinMirrorShare(p, T);
    double v = std::min((u.x - share) / (1.0 - share), 1.0 - 1e-12);
    const bool mirror = v < q;
    v = mirror ? v / q : (v - q) / (1.0 - q);
    wi = sampleReflection(p, w, dvec3(std::min(v, 1.0 - 1e-12), u.y, u.z));
    if (!(wi.z > 0.0)) return dvec3(0.0);
    if (mirror) wi.z = -wi.z;
  }
  if (behind) wi.z = -wi.z;
  return wi;
}

double openpbrPdf(const OpenpbrParams& p, const dvec3& wiIn, const dvec3& woIn) {
  dvec3 wi = wiIn, wo = woIn;
  const double T = transmissionShare(p);
  const bool thin = thinWalled(p);
  double interfaceDensity = 0.0, share = 0.0;
  if (T > 0.0 && !thin) {
    if (!finiteAndOffTheSurface(wi) || !finiteAndOffTheSurface(wo)) return 0.0;
    interfaceDensity = interfacePdf(p, wi, wo);
    share = wo.z > 0.0 ? kInterfaceShare * T : 1.0;
  } else if (wo.z < 0.0) {
    wi.z = -wi.z;
    wo.z = -wo.z;
  }
  if (thin && T > 0.0) {
    if (!finiteAndOffTheSurface(wi) || !(wo.z > 0.0)) return 0.0;
    interfaceDensity = thinInterfacePdf(p, wi, wo);
    share = kInterfaceShare * T;
  }
  if (!(share < 1.0)) return interfaceDensity;
  const double q = thinMirrorShare(p, T);
  const bool through = wi.z < 0.0;
  if (through && !(q > 0.0)) return share * interfaceDensity;
  const double mixture = reflectionPdf(p, dvec3(wi.x, wi.y, std::abs(wi.z)), wo);
  return share * interfaceDensity + (1.0 - share) * (through ? q : 1.0 - q) * mixture;
}

// Through a thin wall light keeps its medium: the ratio of indices across it is 1.
dvec3 openpbrTransmissionEtas(const OpenpbrParams& p) {
  if (thinWalled(p)) return dvec3(1.0);
  return {channelInterface(p, 0).eta, channelInterface(p, 1).eta, channelInterface(p, 2).eta};
}

dvec3 openpbrMediumAbsorption(const OpenpbrParams& p) {
  if (!(transmissionShare(p) > 0.0 && p.transmission_depth > 0.0) || thinWalled(p)) return dvec3(0.0);
  dvec3 sigma;
  for (int c = 0; c < 3; ++c) sigma[c] = std::min(-std::log(std::max(p.transmission_color[c], 1e-30)) / p.transmission_depth, 1e30);
  return sigma;
}

SpecularLobe openpbrSpecularLobe(const OpenpbrParams& p) {
  const Alphas a = baseAlphas(p);
  return {lobeProbabilities(p).x, dvec2(a.t, a.b), false};
}

}  // namespace raylab::reference
