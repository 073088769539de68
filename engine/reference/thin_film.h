// Thin-film interference in RGB (OpenPBR's thin film, after Belcour & Barla, "A Practical Extension to Microfacet
// Theory for the Modeling of Varying Iridescence", SIGGRAPH 2017): the Airy reflectance of a film over a base, its
// interference terms integrated over each RGB channel's spectral sensitivity in closed form through the
// sensitivity's Fourier transform, tabulated here (docs/brdfs.md, "Thin film").
#pragma once

#include <complex>
#include <vector>

#include "reference/brdf_reference.h"

namespace raylab::reference {

// G_c(t) = integral S_c(lambda) exp(i 2 pi t / lambda) dlambda, S_c linear sRGB channel c's sensitivity to a
// spectrum under an equal-energy light, normalised so that a flat spectrum of 1 is (1, 1, 1); at
// t = k kThinFilmStepNm for k < kThinFilmSamples (0 beyond), as (Re, Im) per channel: 6 values per k.
// Computed on first use from the CIE 1931 observer in Wyman, Sloan & Shirley's multi-lobe fit (JCGT 2(2), 2013).
const std::vector<double>& thinFilmSpectrum();

// The unpolarised RGB reflectance, from a medium of index 1, of a film of index etaFilm and thickness
// thicknessNm over a base of complex index eta3 (per channel: n + i k, k >= 0 absorbing), at cosine cosTheta.
// Interference terms up to kThinFilmTerms bounces; at thickness 0 it tends to the bare base's Fresnel term.
dvec3 thinFilmReflectance(double cosTheta, double etaFilm, double thicknessNm, const std::complex<double> eta3[3]);

// The same reflectance by brute force: the exact Airy sum at every nanometre from 360 to 830, weighted by the
// channels' sensitivities. The test's independent answer (thin_film_test), not for rendering.
dvec3 thinFilmReflectanceSpectral(double cosTheta, double etaFilm, double thicknessNm,
                                  const std::complex<double> eta3[3]);

// The unpolarised Fresnel reflectance of the bare base (no film), from a medium of index 1.
double bareReflectance(double cosTheta, std::complex<double> eta);

// Gulbrandsen's map ("Artist Friendly Metallic Fresnel", JCGT 3(4), 2014) from a reflectivity r (F0) and edge tint
// g to the complex index n + i k whose exact Fresnel term has them: how a metal described by F0 and a tint gets the
// index a film on it needs.
std::complex<double> metalIndexFromTint(double r, double g);

}  // namespace raylab::reference
