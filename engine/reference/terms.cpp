#include "reference/terms.h"

#include <algorithm>
#include <cmath>

namespace raylab::reference {

double tan2ThetaH(const dvec3& h) { return (h.x * h.x + h.y * h.y) / (h.z * h.z); }

double powCosThetaH(double tan2Theta, double k) { return std::exp(-0.5 * k * std::log1p(tan2Theta)); }

double D_Beckmann(double tan2Alpha, double m) {
  const double m2 = m * m;
  const double lobe = std::exp(-tan2Alpha / m2);
  // exp underflows to 0 long before (1 + tan^2)^2 could overflow; returning early keeps 0 * inf out.
  if (lobe == 0.0) return 0.0;
  const double secant2 = 1.0 + tan2Alpha;
  return lobe * secant2 * secant2 / (kPi * m2);
}

double F_Schlick(double f0, double cosTheta) {
  // V.H of unit vectors is <= 1, but rounding can put it a few ulps above 1, and an odd power of a negative
  // 1 - cos would make F, and f with it, negative when F0 = 0 (eta = 1, Rs = 0).
  const double c = std::max(0.0, 1.0 - cosTheta);
  const double c2 = c * c;
  return f0 + (1.0 - f0) * c2 * c2 * c;
}

dvec3 F_Schlick(const dvec3& f0, double cosTheta) {
  return {F_Schlick(f0.x, cosTheta), F_Schlick(f0.y, cosTheta), F_Schlick(f0.z, cosTheta)};
}

double F0FromEta(double eta) {
  const double r = (eta - 1.0) / (eta + 1.0);
  return r * r;
}

double F_DielectricExact(double etaI, double etaT, double cosI, double cosT) {
  const double rs = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
  const double rp = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

double F_DielectricFromOutside(double eta, double cosI) {
  // Equal indices are no interface, at every angle (at cos_i = 0 the amplitudes would be 0/0).
  if (eta == 1.0) return 0.0;
  // cos^2 theta_t = (eta^2 - 1 + cos_i^2) / eta^2: 1 - (1 - cos_i^2) / eta^2 loses cos_i^2 at grazing incidence.
  const double cosT = std::sqrt(std::max(0.0, (eta - 1.0) * (eta + 1.0) + cosI * cosI)) / eta;
  return F_DielectricExact(1.0, eta, cosI, cosT);
}

double expm1OverX(double x) { return x == 0.0 ? 1.0 : std::expm1(x) / x; }

double G_TorranceSparrow(double NoH, double NoV, double NoL, double VoH) {
  return std::min({1.0, 2.0 * NoH * NoV / VoH, 2.0 * NoH * NoL / VoH});
}

}  // namespace raylab::reference
