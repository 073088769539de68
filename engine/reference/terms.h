// The shared terms of the BRDF models of docs/brdf_contract.md, in double precision, each a small function
// that cites its source. Half-vector quantities take the unnormalised h = wi + wo of the contract and are
// computed from its components, which is exact for any length of h and keeps full relative accuracy where
// 1 - cos^2 would cancel (the peak of a sharp lobe).
#pragma once

#include <glm/glm.hpp>

namespace raylab::reference {

using glm::dvec3;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInvPi = 1.0 / kPi;

// tan^2 of the angle between n (= z) and h: (h_x^2 + h_y^2) / h_z^2. Needs h_z > 0, which holds whenever
// wi and wo are both above the horizon.
double tan2ThetaH(const dvec3& h);

// (N.H)^k written as (1 + tan^2)^(-k/2) = exp(-k/2 log1p(tan^2)): the same number for any h, without the
// cancellation of 1 - N.H that costs k * 1e-16 relative accuracy near the peak of a k = 1e4 lobe.
double powCosThetaH(double tan2Theta, double k);

// Beckmann microfacet distribution (Beckmann & Spizzichino 1963, as used by Cook & Torrance, "A Reflectance
// Model for Computer Graphics", ACM TOG 1(1), 1982): exp(-tan^2 a / m^2) / (pi m^2 cos^4 a), with
// 1 / cos^4 a = (1 + tan^2 a)^2 so that only tan^2 a enters.
double D_Beckmann(double tan2Alpha, double m);

// Schlick's approximation of the Fresnel factor (Schlick, "An Inexpensive BRDF Model for Physically-based
// Rendering", Computer Graphics Forum 13(3), 1994): F0 + (1 - F0)(1 - cos)^5, with 1 - cos clamped at 0.
double F_Schlick(double f0, double cosTheta);
dvec3 F_Schlick(const dvec3& f0, double cosTheta);
// Reflectance at normal incidence of a dielectric interface of relative index eta: ((eta-1)/(eta+1))^2.
double F0FromEta(double eta);

// Exact unpolarised Fresnel reflectance of a dielectric interface (Born & Wolf, "Principles of Optics", 1.5.2):
// (r_s^2 + r_p^2) / 2 from the cosines on the incident (etaI) and transmitted (etaT) sides. The caller
// handles total internal reflection; etaI cosI + etaT cosT must be > 0.
double F_DielectricExact(double etaI, double etaT, double cosI, double cosT);
// The same for light arriving from outside (index 1) at cosI onto a dielectric of index eta >= 1 (no total internal
// reflection), cos theta_t from Snell's law; 0 for eta = 1.
double F_DielectricFromOutside(double eta, double cosI);

// Torrance-Sparrow V-cavity shadowing and masking (Torrance & Sparrow, JOSA 57(9), 1967, in the form of
// Blinn 1977 and Cook & Torrance 1982): min(1, 2 NoH NoV / VoH, 2 NoH NoL / VoH). Needs VoH > 0.
double G_TorranceSparrow(double NoH, double NoV, double NoL, double VoH);

// expm1(x) / x, 1 at x = 0 (its limit).
double expm1OverX(double x);

}  // namespace raylab::reference
