// Lafortune, Foo, Torrance & Greenberg, "Non-Linear Approximation of Reflectance Functions", SIGGRAPH 1997, eq. 4,
// with Ngan, Durand & Matusik's normalisation of each lobe (EGSR 2005; docs/brdfs.md, "lafortune"):
//   f = rho_d / pi + sum_k rho_s,k (n_k + 2)/(2 pi) max(0, Cx ux vx + Cy uy vy + Cz uz vz)^n_k / max|C|^n_k.
// The second lobe has Cx = Cy = cxy2.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

namespace {

struct Lobe {
  dvec3 c;
  double n;
};

Lobe firstLobe(const LafortuneParams& p) { return {dvec3(p.cx, p.cy, p.cz), p.n}; }
Lobe secondLobe(const LafortuneParams& p) { return {dvec3(p.cxy2, p.cxy2, p.cz2), p.n2}; }

double largest(const dvec3& c) { return std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}); }

// max(0, C.(wi * wo))^n / max|C|^n: 1 at the lobe's peak.
double lobeShape(const Lobe& lobe, const dvec3& wi, const dvec3& wo) {
  const double m = largest(lobe.c);
  if (m == 0.0) return 0.0;
  const double d = lobe.c.x * wi.x * wo.x + lobe.c.y * wi.y * wo.y + lobe.c.z * wi.z * wo.z;
  return d > 0.0 ? std::pow(d / m, lobe.n) : 0.0;
}

// Seen from wo, the lobe is (|C * wo| / max|C|)^n times a cosine power about the axis C * wo / |C * wo|.
double reach(const Lobe& lobe, const dvec3& wo) {
  const double m = largest(lobe.c);
  return m == 0.0 ? 0.0 : std::pow(glm::length(lobe.c * wo) / m, lobe.n);
}

dvec3 axis(const Lobe& lobe, const dvec3& wo) {
  const dvec3 cw = lobe.c * wo;
  const double length = glm::length(cw);
  return length > 0.0 ? cw / length : dvec3(0.0, 0.0, 1.0);
}

// The share of the glossy samples that go to the first lobe from wo: each lobe's weight times its reach.
double firstLobeProbability(const LafortuneParams& p, const dvec3& wo) {
  const double w1 = (p.rho_s.x + p.rho_s.y + p.rho_s.z) * reach(firstLobe(p), wo);
  const double w2 = (p.rho_s2.x + p.rho_s2.y + p.rho_s2.z) * reach(secondLobe(p), wo);
  return w1 + w2 > 0.0 ? w1 / (w1 + w2) : 0.5;
}

double lobePdf(const Lobe& lobe, const dvec3& wi, const dvec3& wo) {
  return (lobe.n + 1.0) / (2.0 * kPi) * std::pow(std::max(0.0, glm::dot(axis(lobe, wo), wi)), lobe.n);
}

}  // namespace

Lobes lafortuneEval(const LafortuneParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const auto term = [&](const dvec3& weight, const Lobe& lobe) {
    return weight * ((lobe.n + 2.0) / (2.0 * kPi) * lobeShape(lobe, wi, wo));
  };
  return {p.rho_d * kInvPi, term(p.rho_s, firstLobe(p)) + term(p.rho_s2, secondLobe(p))};
}

// u.x picks the lobe and, rescaled to [0, 1), draws the cosine about its axis; u.y the azimuth. The frame around the
// axis is that of shaders/common/frame.glsl for a zero tangent hint, so the GPU draws the very same directions.
dvec3 lafortuneSampleSpecular(const LafortuneParams& p, const dvec3& wo, const dvec2& u) {
  const double q = firstLobeProbability(p, wo);
  const bool first = u.x < q;
  const Lobe lobe = first ? firstLobe(p) : secondLobe(p);
  const double v = std::min(first ? u.x / q : (u.x - q) / (1.0 - q), 1.0);
  const Frame frame = makeFrame(axis(lobe, wo), dvec3(0.0));
  const PowerCosine alpha = samplePowerCosine(v, lobe.n);
  const double phi = 2.0 * kPi * u.y;
  return alpha.sinTheta * std::cos(phi) * frame.t + alpha.sinTheta * std::sin(phi) * frame.b +
         alpha.cosTheta * frame.n;
}

double lafortunePdfSpecular(const LafortuneParams& p, const dvec3& wi, const dvec3& wo) {
  const double q = firstLobeProbability(p, wo);
  return q * lobePdf(firstLobe(p), wi, wo) + (1.0 - q) * lobePdf(secondLobe(p), wi, wo);
}

// The albedo quadrature's coordinates: those of the half vector about the normal, which reach every wi (a retro lobe
// peaks at wi = wo, beyond the tangent plane of the mirror direction's coordinates at oblique wo); the peak of Ngan's
// Cx = Cy = -Cz lobe is H = n there. As wide as the wider lobe: c^n ~ exp(-n beta^2 / 2) in wi is about
// exp(-2 n beta_H^2) in H.
SpecularLobe lafortuneSpecularLobe(const LafortuneParams& p) {
  const double n = std::min(p.n, p.rho_s2 == dvec3(0.0) ? p.n : p.n2);
  return {mixtureProbability(p.rho_d, p.rho_s + p.rho_s2), dvec2(std::sqrt(0.5 / n)), false};
}

}  // namespace raylab::reference
