#include "reference/albedo.h"

#include <cmath>
#include <limits>
#include <random>

#include "reference/cubature.h"
#include "reference/models.h"
#include "reference/terms.h"
#include "shared/brdf_lobes.h"

namespace raylab::reference {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The largest radius rho >= 0 along the ray (p, q) = rho (a, b) of the gnomonic coordinates for which wi
// stays above the horizon; infinity when it never meets it.
double mirrorHorizonRadius(const Frame& around, double a, double b) {
  // wi ~ R + p t + q b: wi.z = R.z + rho (a t.z + b b.z), linear in rho.
  const double slope = a * around.t.z + b * around.b.z;
  return slope >= 0.0 ? kInfinity : around.n.z / -slope;
}

double halfVectorHorizonRadius(const dvec3& wo, double a, double b) {
  // H ~ (p, q, 1), wi = 2 (wo.H) H - wo: wi.z > 0 iff wo.z + 2 rho K - wo.z rho^2 L > 0 with
  // K = wo.x a + wo.y b, L = a^2 + b^2: one positive root, written without cancellation for either sign of K.
  const double K = wo.x * a + wo.y * b;
  const double L = a * a + b * b;
  const double root = std::sqrt(K * K + wo.z * wo.z * L);
  return K >= 0.0 ? (K + root) / (wo.z * L) : wo.z / (root - K);
}

// The integrand of the specular term in (v, psi): the radius is rho = tan(v tau*(psi)), with tau* = atan of
// the horizon radius, so that v in [0, 1] spans exactly the directions above the horizon.
dvec3 specularIntegrand(const Material& material, const SpecularLobe& lobe, const dvec3& wo, const Frame& mirrorFrame,
                        double v, double psi) {
  const dvec2 width = lobe.widths;
  const double a = width.x * std::cos(psi);
  const double b = width.y * std::sin(psi);
  const bool aroundMirror = lobe.aroundMirror;
  const double horizon = aroundMirror ? mirrorHorizonRadius(mirrorFrame, a, b) : halfVectorHorizonRadius(wo, a, b);
  const double tauMax = std::atan(horizon);  // pi/2 for an infinite radius
  const double rho = std::tan(v * tauMax);
  const double p = rho * a;
  const double q = rho * b;
  const double secant2 = 1.0 + p * p + q * q;
  // dp dq = wx wy rho drho dpsi, drho = (1 + rho^2) tau* dv; gnomonic: dw = dp dq / secant^3.
  const double jacobian = width.x * width.y * rho * (1.0 + rho * rho) * tauMax / (secant2 * std::sqrt(secant2));
  dvec3 wi;
  double extra = 1.0;
  if (aroundMirror) {
    wi = glm::normalize(mirrorFrame.n + p * mirrorFrame.t + q * mirrorFrame.b);
  } else {
    const dvec3 H = dvec3(p, q, 1.0) / std::sqrt(secant2);
    const double VoH = glm::dot(wo, H);
    wi = 2.0 * VoH * H - wo;
    extra = 4.0 * VoH;  // dwi = 4 (wo.H) dH
  }
  if (!(wi.z > 0.0)) return dvec3(0.0);  // rounding at the horizon edge
  return evalLobes(material, wi, wo).specular * (wi.z * extra * jacobian);
}

// The transmission term of a two-sided model (rough glass) for wo outside, in the same polar gnomonic coordinates of
// the transmission half vector H (the whole plane: every H with H_z > 0 refracts wo to some wi inside, unless that
// wi comes out on the outside, where the integrand is 0). wi = refract(wo, H) and dwi = (eta wi.H + wo.H)^2 /
// (eta^2 |wi.H|) dH (Walter et al. 2007, eq. 17). The integrand is weighted by eta_i^2 / eta_o^2 = eta^2, which by
// generalised reciprocity turns the viewer's integral over wi into the fraction of light arriving from wo that
// is transmitted.
dvec3 transmissionIntegrand(const Material& material, const SpecularLobe& lobe, double eta, const dvec3& wo, double v,
                            double psi) {
  const double a = lobe.widths.x * std::cos(psi);
  const double b = lobe.widths.y * std::sin(psi);
  const double tauMax = 0.5 * kPi;
  const double rho = std::tan(v * tauMax);
  const double secant2 = 1.0 + rho * rho * (a * a + b * b);
  const double jacobian = lobe.widths.x * lobe.widths.y * rho * (1.0 + rho * rho) * tauMax / (secant2 * std::sqrt(secant2));
  const dvec3 H = dvec3(rho * a, rho * b, 1.0) / std::sqrt(secant2);
  const double c = glm::dot(wo, H);
  if (!(c > 0.0)) return dvec3(0.0);
  const double ratio = 1.0 / eta;
  const double sin2T = ratio * ratio * (1.0 - c * c);
  const dvec3 wi = -ratio * wo + (ratio * c - std::sqrt(1.0 - sin2T)) * H;  // sin2T < 1 from outside
  if (!(wi.z < 0.0)) return dvec3(0.0);
  const double wiH = glm::dot(wi, H);
  const double denominator = eta * wiH + c;
  const double dwi = denominator * denominator / (eta * eta * std::abs(wiH));
  return evalLobes(material, wi, wo).specular * (-wi.z * dwi * jacobian * eta * eta);
}

}  // namespace

dvec3 directionFromAngles(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

namespace {

// A tabulated f is a step function, on which adaptive cubature refines every step without end: its albedo is the
// mean of f |cos_i| / pdf over kTabulatedSamples draws of the model's own sampler, stratified in u.x, with a fixed
// seed; errorEstimate is three standard errors of the largest channel. A material sampled for another reason (a
// thin wall) takes kSampledSamples: its weights are smooth.
constexpr int kTabulatedSamples = 1 << 20;
constexpr int kSampledSamples = 1 << 16;

Albedo sampledAlbedo(const Material& material, const dvec3& wo, int samples) {
  std::mt19937_64 random(20241204);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  dvec3 sum(0.0), sumSquares(0.0);
  for (int i = 0; i < samples; ++i) {
    const dvec3 u((i + uniform(random)) / samples, uniform(random), uniform(random));
    const Sample s = sample(material, wo, u);
    const dvec3 weight = s.pdf > 0.0 ? s.f * std::abs(s.wi.z) / s.pdf : dvec3(0.0);
    sum += weight;
    sumSquares += weight * weight;
  }
  Albedo albedo;
  const double n = samples;
  albedo.value = albedo.specular = sum / n;
  for (int c = 0; c < 3; ++c) {
    const double variance = std::max(0.0, sumSquares[c] / n - albedo.value[c] * albedo.value[c]) / (n - 1.0);
    albedo.errorEstimate = std::max(albedo.errorEstimate, 3.0 * std::sqrt(variance));
  }
  albedo.evaluations = samples;
  albedo.converged = true;
  return albedo;
}

}  // namespace

Albedo directionalAlbedo(const Material& material, const dvec3& wo, const AlbedoOptions& options) {
  Albedo albedo;
  if (!aboveHorizon(wo, wo) || (lobeFlags(material) & (gpu::kLobeDiffuse | gpu::kLobeGlossy)) == 0) return albedo;
  if (isTabulated(material)) return sampledAlbedo(material, wo, kTabulatedSamples);
  if (albedoBySampling(material)) return sampledAlbedo(material, wo, kSampledSamples);
  CubatureOptions cubature;
  cubature.relTolerance = options.relTolerance;
  cubature.maxRegions = options.maxRegions;
  // A floor on the error target: below 1e-13 the diffuse or specular term is negligible next to 1.
  cubature.absTolerance = 1e-13;

  // Diffuse: over (cos theta_i, phi_i), dw cos_i = cos_i dcos dphi.
  const CubatureResult diffuse = integrate2d(
      [&](double c, double phi) {
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        const dvec3 wi(s * std::cos(phi), s * std::sin(phi), c);
        return evalLobes(material, wi, wo).diffuse * c;
      },
      dvec2(0.0, 0.0), dvec2(1.0, 2.0 * kPi), cubature);

  CubatureResult specular;
  specular.converged = true;
  if (const std::optional<SpecularLobe> lobe = specularLobe(material)) {
    const Frame mirrorFrame = makeFrame(dvec3(-wo.x, -wo.y, wo.z), dvec3(0.0));
    specular = integrate2d(
        [&](double v, double psi) { return specularIntegrand(material, *lobe, wo, mirrorFrame, v, psi); },
        dvec2(0.0, 0.0), dvec2(1.0, 2.0 * kPi), cubature);
  }
  CubatureResult transmission;
  transmission.converged = true;
  const std::optional<dvec3> etas = transmissionEtas(material);
  if (const std::optional<SpecularLobe> lobe = specularLobe(material); lobe && etas) {
    // A dispersive material refracts each channel by its own index: each channel integrated about its own.
    const bool dispersive = etas->x != etas->y || etas->y != etas->z;
    for (int c = 0; c < (dispersive ? 3 : 1); ++c) {
      const CubatureResult channel = integrate2d(
          [&](double v, double psi) {
            const dvec3 value = transmissionIntegrand(material, *lobe, (*etas)[c], wo, v, psi);
            return dispersive ? dvec3(c == 0 ? value.x : 0.0, c == 1 ? value.y : 0.0, c == 2 ? value.z : 0.0) : value;
          },
          dvec2(0.0, 0.0), dvec2(1.0, 2.0 * kPi), cubature);
      if (!dispersive) {
        transmission = channel;
        break;
      }
      transmission.value[c] = channel.value[c];
      transmission.errorEstimate = std::max(transmission.errorEstimate, channel.errorEstimate);
      transmission.evaluations += channel.evaluations;
      transmission.converged = transmission.converged && channel.converged;
    }
  }
  albedo.diffuse = diffuse.value;
  albedo.specular = specular.value;
  albedo.transmission = transmission.value;
  albedo.value = diffuse.value + specular.value + transmission.value;
  albedo.errorEstimate = diffuse.errorEstimate + specular.errorEstimate + transmission.errorEstimate;
  albedo.evaluations = diffuse.evaluations + specular.evaluations + transmission.evaluations;
  albedo.converged = diffuse.converged && specular.converged && transmission.converged;
  return albedo;
}

}  // namespace raylab::reference
