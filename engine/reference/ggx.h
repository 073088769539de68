// GGX (Trowbridge-Reitz) microfacet terms in double precision (docs/brdfs.md, "GGX terms"), for the models of the
// second library. The sampler of visible normals maps u to m exactly as the GLSL does (Heitz 2018), so that
// brdf_device_sampling_test can require the same directions; the χ² tests check it against the density.
#pragma once

#include <glm/glm.hpp>

namespace raylab::reference {

using glm::dvec2;
using glm::dvec3;

// D(m) = 1 / (pi ax ay B^2), B = (h_x^2/ax^2 + h_y^2/ay^2 + h_z^2) / |h|^2, for any length of h; 0 for h_z <= 0.
double D_GGX(const dvec3& h, double ax, double ay);
// Smith's Lambda(w) = (-1 + sqrt(1 + (ax^2 w_x^2 + ay^2 w_y^2) / w_z^2)) / 2 (Heitz 2014).
double Lambda_GGX(const dvec3& w, double ax, double ay);
// G1(w) = 1 / (1 + Lambda(w)), and the separable G = G1(wi) G1(wo) and height-correlated G2 = 1 / (1 + Lambda(wi)
// + Lambda(wo)) (Heitz 2014).
double G1_GGX(const dvec3& w, double ax, double ay);
double G2_GGX(const dvec3& wi, const dvec3& wo, double ax, double ay);

// A unit microfacet normal with density G1(wo) max(0, wo.m) D(m) / wo_z (Heitz, "Sampling the GGX Distribution
// of Visible Normals", JCGT 7(4), 2018: a point of the projected disk in the stretched configuration).
dvec3 sampleGgxVisibleNormal(const dvec3& wo, double ax, double ay, const dvec2& u);
// The density of wi = reflect(wo, m) for that m: G1(wo) D(m) / (4 wo_z), with h = wi + wo.
double ggxReflectionPdf(const dvec3& h, const dvec3& wo, double ax, double ay);

}  // namespace raylab::reference
