// Thin-film interference (thin_film.h). Per polarisation, with r12 the film's top amplitude reflection (real: the
// film does not absorb) and z = r23 exp(i delta) the bottom one after a round trip of phase delta = 2 pi OPD /
// lambda, OPD = 2 eta_film d cos(theta_film), Stokes' relations (r21 = -r12, t12 t21 = 1 - r12^2) sum the
// reflections to
//   r = (r12 + z) / (1 + r12 z),
// and with x = r12 |r23|, psi = delta + arg r23, R = |r|^2 has the Fourier series
//   R(psi) = 1 - T [1 + 2 sum_{m >= 1} (-x)^m cos(m psi)],  T = (1 - R12)(1 - R23) / (1 - R12 R23),
// from 1 / (C + B cos psi) = (1 + 2 sum (-q)^m cos m psi) / sqrt(C^2 - B^2), here with q = x and
// sqrt(C^2 - B^2) = 1 - x^2. Its m = 0 term is the incoherent sum of the two interfaces; integrated over channel c's
// sensitivity, cos(m psi) becomes Re(exp(i m arg r23) G_c(m OPD)), G_c the sensitivity's Fourier transform in
// 1/lambda (Belcour & Barla 2017 fit G with Gaussians; it is tabulated here instead, from the observer).
#include "reference/thin_film.h"

#include <algorithm>
#include <cmath>

#include "shared/brdf_tables.h"

namespace raylab::reference {
namespace {

using complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

// Wyman, Sloan & Shirley's piecewise Gaussian, of widths s1 below the mean and s2 above it.
double lobe(double lambda, double mean, double s1, double s2) {
  const double t = (lambda - mean) / (lambda < mean ? s1 : s2);
  return std::exp(-0.5 * t * t);
}

// The CIE 1931 2-degree colour matching functions, their multi-lobe fit (JCGT 2(2), 2013, section 2.2).
dvec3 observer(double lambda) {
  return {1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7) -
              0.065 * lobe(lambda, 501.1, 20.4, 26.2),
          0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1),
          1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8)};
}

// Linear sRGB (Rec. 709 primaries, D65) from XYZ, each channel then scaled so that a flat spectrum is white.
dvec3 rgbSensitivity(double lambda) {
  const dvec3 xyz = observer(lambda);
  return {3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
          -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
          0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z};
}

constexpr double kFirstNm = 360.0, kLastNm = 830.0;

// The channels' sensitivities at every nanometre, each normalised to integrate to 1.
const std::vector<dvec3>& sensitivities() {
  static const std::vector<dvec3> table = [] {
    std::vector<dvec3> s;
    dvec3 sum(0.0);
    for (double lambda = kFirstNm; lambda <= kLastNm; lambda += 1.0) {
      s.push_back(rgbSensitivity(lambda));
      sum += s.back();
    }
    for (dvec3& v : s) v /= sum;
    return s;
  }();
  return table;
}

// Amplitude reflection coefficients (s, p) at an interface from index a to index b, given the cosine in a and
// w = b cos_b = sqrt(b^2 - a^2 sin^2), all complex: r_s = (a c - w) / (a c + w), r_p = (b^2 c - a w) / (b^2 c + a w).
struct Amplitudes {
  complex s, p;
};
Amplitudes amplitudes(complex a, complex cosA, complex b, complex w) {
  return {(a * cosA - w) / (a * cosA + w), (b * b * cosA - a * w) / (b * b * cosA + a * w)};
}

// The film's two interfaces for one channel's base: r12 (real), r23, and the optical path difference (nm).
struct Film {
  Amplitudes top, bottom;
  double opd = 0.0;
  bool totalReflection = false;
};
Film filmOf(double cosTheta, double etaFilm, double thicknessNm, complex eta3) {
  Film film;
  const double sin2 = std::max(0.0, 1.0 - cosTheta * cosTheta);
  const double cos2Film = 1.0 - sin2 / (etaFilm * etaFilm);
  if (!(cos2Film > 0.0)) {
    film.totalReflection = true;  // a film of index below 1 reflects everything past its critical angle
    return film;
  }
  const double cosFilm = std::sqrt(cos2Film);
  film.top = amplitudes(1.0, cosTheta, etaFilm, etaFilm * cosFilm);
  const complex w = std::sqrt(eta3 * eta3 - sin2);  // Snell: eta_film sin(theta_film) = sin(theta)
  film.bottom = amplitudes(etaFilm, cosFilm, eta3, w);
  film.opd = 2.0 * etaFilm * thicknessNm * cosFilm;
  return film;
}

}  // namespace

const std::vector<double>& thinFilmSpectrum() {
  static const std::vector<double> table = [] {
    std::vector<double> g(6 * std::size_t(gpu::kThinFilmSamples));
    const std::vector<dvec3>& s = sensitivities();
    for (std::uint32_t k = 0; k < gpu::kThinFilmSamples; ++k) {
      const double t = k * double(gpu::kThinFilmStepNm);
      dvec3 re(0.0), im(0.0);
      for (std::size_t i = 0; i < s.size(); ++i) {
        const double phase = 2.0 * kPi * t / (kFirstNm + double(i));
        re += s[i] * std::cos(phase);
        im += s[i] * std::sin(phase);
      }
      for (int c = 0; c < 3; ++c) {
        g[6 * k + 2 * c] = re[c];
        g[6 * k + 2 * c + 1] = im[c];
      }
    }
    return g;
  }();
  return table;
}

dvec3 thinFilmReflectance(double cosTheta, double etaFilm, double thicknessNm, const complex eta3[3]) {
  const std::vector<double>& g = thinFilmSpectrum();
  // G_c(t), linear in the table, 0 beyond its end (where the sensitivities' transforms have decayed).
  const auto spectrum = [&](double t, int c) {
    const double x = t / double(gpu::kThinFilmStepNm);
    const std::size_t k = std::size_t(x);
    if (k + 1 >= gpu::kThinFilmSamples) return complex(0.0);
    const double f = x - double(k);
    return complex((1.0 - f) * g[6 * k + 2 * c] + f * g[6 * (k + 1) + 2 * c],
                   (1.0 - f) * g[6 * k + 2 * c + 1] + f * g[6 * (k + 1) + 2 * c + 1]);
  };
  dvec3 reflectance;
  for (int c = 0; c < 3; ++c) {
    const Film film = filmOf(cosTheta, etaFilm, thicknessNm, eta3[c]);
    if (film.totalReflection) {
      reflectance[c] = 1.0;
      continue;
    }
    double sum = 0.0;
    for (const auto& [r12, r23] : {std::pair{film.top.s, film.bottom.s}, std::pair{film.top.p, film.bottom.p}}) {
      const double R12 = std::norm(r12), R23 = std::norm(r23);
      const double denominator = 1.0 - R12 * R23;
      if (!(denominator > 0.0)) {
        sum += 1.0;  // both interfaces mirrors
        continue;
      }
      const double T = (1.0 - R12) * (1.0 - R23) / denominator;
      // The terms a_m = (-x exp(i arg r23))^m G_c(m OPD); past kThinFilmTerms, a geometric tail of ratio
      // rho = -x exp(i arg r23) G_c(OPD): where it matters (a thin film, |x| near 1 at grazing angles) G_c is
      // nearly a pure phase that turns by G_c(OPD) each bounce, and where G_c decays the terms are gone already.
      const complex step = -r12.real() * std::abs(r23) * std::polar(1.0, std::arg(r23));
      complex power(1.0), term(0.0), terms(0.0);
      for (std::uint32_t m = 1; m <= gpu::kThinFilmTerms; ++m) {
        power *= step;
        term = power * spectrum(m * film.opd, c);
        terms += term;
        if (std::norm(power) < 1e-10) break;  // as thin_film.glsl: |x|^m below 1e-5, the tail smaller still
      }
      const complex ratio = step * spectrum(film.opd, c);
      terms += term * ratio / (1.0 - ratio);
      sum += 1.0 - T * (1.0 + 2.0 * terms.real());
    }
    reflectance[c] = std::clamp(0.5 * sum, 0.0, 1.0);
  }
  return reflectance;
}

dvec3 thinFilmReflectanceSpectral(double cosTheta, double etaFilm, double thicknessNm, const complex eta3[3]) {
  const std::vector<dvec3>& s = sensitivities();
  dvec3 reflectance(0.0);
  for (int c = 0; c < 3; ++c) {
    const Film film = filmOf(cosTheta, etaFilm, thicknessNm, eta3[c]);
    if (film.totalReflection) {
      reflectance[c] = 1.0;
      continue;
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
      const complex turn = std::polar(1.0, 2.0 * kPi * film.opd / (kFirstNm + double(i)));
      double R = 0.0;
      for (const auto& [r12, r23] : {std::pair{film.top.s, film.bottom.s}, std::pair{film.top.p, film.bottom.p}}) {
        const complex z = r23 * turn;
        R += 0.5 * std::norm((r12 + z) / (1.0 + r12 * z));
      }
      reflectance[c] += s[i][c] * R;
    }
  }
  // Out-of-gamut spectra (a channel's sensitivity has negative lobes) clipped as the series clips them.
  return glm::clamp(reflectance, 0.0, 1.0);
}

double bareReflectance(double cosTheta, std::complex<double> eta) {
  const double sin2 = std::max(0.0, 1.0 - cosTheta * cosTheta);
  const Amplitudes r = amplitudes(1.0, cosTheta, eta, std::sqrt(eta * eta - sin2));
  return 0.5 * (std::norm(r.s) + std::norm(r.p));
}

complex metalIndexFromTint(double r, double g) {
  r = std::clamp(r, 0.0, 0.99);
  const double root = std::sqrt(r);
  const double n = g * (1.0 - r) / (1.0 + r) + (1.0 - g) * (1.0 + root) / (1.0 - root);
  const double k2 = (r * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - r);
  return {n, std::sqrt(std::max(k2, 0.0))};
}

}  // namespace raylab::reference
