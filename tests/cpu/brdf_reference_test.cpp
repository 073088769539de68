// The CPU reference on its own: values worked out by hand from the contract's formulas at configurations
// where every angle is known, the guards of the contract (exactly 0 below the horizon, never NaN, Inf or
// negative, including degenerate inputs and parameters at both ends of their ranges), accuracy in double at
// the hard cases (sharp lobes, cosines of 1e-7), the shading frame and the sampler's bookkeeping.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "reference/models.h"
#include "reference/terms.h"
#include "reference_materials.h"

// Terms of ashikhmin_shirley's reference file (engine/reference/models/ashikhmin_shirley.cpp), tested on their own.
namespace raylab::reference {
double AS_diffuseFalloff(double cosTheta);
double AS_exponent(const dvec3& h, double nu, double nv);
}  // namespace raylab::reference

namespace raylab::test {
namespace {

using reference::dvec2;
using reference::dvec3;
using reference::kPi;
using reference::Material;

constexpr double kDegree = kPi / 180.0;

dvec3 direction(double thetaDeg, double phiDeg) {
  const double t = thetaDeg * kDegree;
  const double p = phiDeg * kDegree;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// A direction at polar cosine c (which may be 1e-7) and azimuth phi, with sin computed without cancellation.
dvec3 directionFromCos(double c, double phiDeg) {
  const double s = std::sqrt((1.0 - c) * (1.0 + c));
  return {s * std::cos(phiDeg * kDegree), s * std::sin(phiDeg * kDegree), c};
}

// Every model with its parameters at both ends of their ranges and in between.
std::vector<Material> extremeMaterials() {
  std::vector<Material> materials;
  const std::vector<std::vector<ParamValue>> reflectances = {{{"rho_d", 0}, {"rho_s", 1}}, {{"rho_d", 1}, {"rho_s", 1}},
                                                             {{"rho_d", 0.3}, {"rho_s", 0}}};
  for (const auto& rho : reflectances) {
    auto with = [&rho](std::vector<ParamValue> more) {
      more.insert(more.end(), rho.begin(), rho.end());
      return more;
    };
    materials.push_back(makeMaterial("lambert", {rho[0]}));
    for (double s : {1.0, 1000.0, 10000.0}) {
      materials.push_back(makeMaterial("phong", with({{"s", s}})));
      materials.push_back(makeMaterial("blinnphong", with({{"s", s}})));
    }
    for (double m : {0.001, 0.2, 1.0}) {
      for (double eta : {1.0, 1.0001, 1.5, 10.0}) {
        materials.push_back(makeMaterial("cooktorrance", with({{"m", m}, {"eta", eta}})));
      }
    }
    for (const char* model : {"ward", "ward_duer", "ward_gmd"}) {
      for (auto [ax, ay] : {std::pair{0.001, 0.001}, {1.0, 1.0}, {0.001, 1.0}, {1.0, 0.001}, {0.2, 0.2}}) {
        materials.push_back(makeMaterial(model, with({{"alpha_x", ax}, {"alpha_y", ay}})));
      }
    }
    // Lafortune: Ngan's forward lobe, a retro-reflector, a lobe past |Cz| (off-specular peak) and a zero lobe, at the
    // exponents' ends, with and without the second lobe.
    for (auto [cx, cz] : {std::pair{-0.577, 0.577}, {0.577, 0.577}, {-0.707, 1.23e-10}, {0.0, 0.0}, {-1.0, 1.0}}) {
      for (double n : {1.0, 1000.0, 20000.0}) {
        for (double second : {0.0, 1.0}) {
          materials.push_back(makeMaterial("lafortune", with({{"cx", cx}, {"cy", cx}, {"cz", cz}, {"n", n},
                                                              {"rho_s2", second}, {"n2", 20000.0 / n}})));
        }
      }
    }
    const std::vector<ParamValue> asRho = {{"Rd", rho[0].value}, {"Rs", rho[1].value}};
    for (auto [nu, nv] : {std::pair{1.0, 1.0}, {10000.0, 10000.0}, {1.0, 10000.0}, {10000.0, 1.0}, {100.0, 100.0}}) {
      std::vector<ParamValue> params = {{"nu", nu}, {"nv", nv}};
      params.insert(params.end(), asRho.begin(), asRho.end());
      materials.push_back(makeMaterial("ashikhmin_shirley", params));
    }
  }
  return materials;
}

// Hard directions: the normal, exactly on the horizon, cosines from 1e-4 to 1e-7, grazing mirror pairs,
// and float-rounded (not quite unit) versions of them, as the GPU receives them.
std::vector<dvec3> hardDirections() {
  std::vector<dvec3> directions = {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}, {0.6, 0.8, 0}, {0, 0, -1}};
  for (double c : {1e-4, 1e-5, 1e-6, 1e-7, 0.5, 0.999999, 1.0 - 1e-12}) {
    for (double phi : {0.0, 90.0, 180.0, 270.0, 33.0, 213.0}) {
      const dvec3 w = directionFromCos(c, phi);
      directions.push_back(w);
      directions.push_back(dvec3(glm::vec3(w)));  // float-rounded: |w| differs from 1 by ~1e-7
      directions.push_back(dvec3(-w.x, -w.y, -w.z));
    }
  }
  return directions;
}

TEST(BrdfReference, ValuesAtTheNormalMatchTheFormulas) {
  // wi = wo = n: h = (0, 0, 2), N.H = V.H = 1, tan = 0, R.wo = 1, the Fresnel angle is 0.
  const dvec3 n(0, 0, 1);
  auto f = [&n](const Material& m) { return reference::eval(m, n, n).x; };
  EXPECT_DOUBLE_EQ(f(makeMaterial("lambert", {{"rho_d", 0.5}})), 0.5 / kPi);
  EXPECT_DOUBLE_EQ(f(makeMaterial("phong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 20}})), 22.0 / (2.0 * kPi));
  EXPECT_DOUBLE_EQ(f(makeMaterial("blinnphong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 20}})), 28.0 / (8.0 * kPi));
  const Material ct = makeMaterial("cooktorrance", {{"rho_d", 0}, {"rho_s", 1}, {"m", 0.25}, {"eta", 1.5}});
  EXPECT_DOUBLE_EQ(f(ct), 0.04 / (4.0 * kPi * 0.25 * 0.25));  // D = 1/(pi m^2), F = F0 = 0.04, G = 1
  for (const char* model : {"ward", "ward_duer", "ward_gmd"}) {
    // gmd: (h.h)/h_z^4 = 4/16 gives the same 1/(4 pi ax ay) as the other two.
    const Material ward = makeMaterial(model, {{"rho_d", 0}, {"rho_s", 1}, {"alpha_x", 0.25}, {"alpha_y", 0.5}});
    EXPECT_DOUBLE_EQ(f(ward), 1.0 / (4.0 * kPi * 0.25 * 0.5)) << model;
  }
  // Ashikhmin-Shirley with h_x = h_y = 0 and nu != nv: k = nu, the lobe factor is 1, F = Rs.
  const Material as = makeMaterial("ashikhmin_shirley", {{"Rd", 0.5}, {"Rs", 0.25}, {"nu", 1}, {"nv", 10000}});
  const double spec = std::sqrt(2.0 * 10001.0) / (8.0 * kPi) * 0.25;
  const double diff = 28.0 * 0.5 / (23.0 * kPi) * 0.75 * (31.0 / 32.0) * (31.0 / 32.0);
  EXPECT_NEAR(f(as), spec + diff, 1e-15 * (spec + diff));
}

// Lafortune's lobe with Cx = Cy = -Cz is Phong's lobe of the same exponent (C.(u * v) = |C| R.v), at any scale of
// C; with Cx = Cy = Cz it peaks back towards wi; and its value is the paper's sum written out by hand.
TEST(BrdfReference, LafortuneLobesAreTheirClosedForms) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(0.0, 89.0), azimuth(0.0, 360.0);
  for (int k = 0; k < 200; ++k) {
    const dvec3 wi = direction(angle(random), azimuth(random)), wo = direction(angle(random), azimuth(random));
    for (double scale : {0.577, 0.2, 1.0}) {
      const Material lafortune = makeMaterial(
          "lafortune", {{"rho_d", 0.3}, {"rho_s", 0.7}, {"cx", -scale}, {"cy", -scale}, {"cz", scale}, {"n", 37}});
      const Material phong = makeMaterial("phong", {{"rho_d", 0.3}, {"rho_s", 0.7}, {"s", 37}});
      EXPECT_NEAR(reference::eval(lafortune, wi, wo).x, reference::eval(phong, wi, wo).x,
                  1e-12 * reference::eval(phong, wi, wo).x + 1e-300);
    }
    // Two lobes at once: f = rho_d/pi + sum rho_s (n+2)/(2 pi) max(0, d)^n / max|C|^n, by hand.
    const Material two = makeMaterial("lafortune", {{"rho_d", 0.1}, {"rho_s", 0.5}, {"cx", -0.8}, {"cy", -0.3},
                                                    {"cz", 0.4}, {"n", 6}, {"rho_s2", 0.25}, {"cxy2", 0.5},
                                                    {"cz2", 0.25}, {"n2", 3}});
    const auto lobe = [&](double cx, double cy, double cz, double n) {
      const double d = cx * wi.x * wo.x + cy * wi.y * wo.y + cz * wi.z * wo.z;
      const double m = std::max({std::abs(cx), std::abs(cy), std::abs(cz)});
      return (n + 2.0) / (2.0 * kPi) * std::pow(std::max(0.0, d) / m, n);
    };
    // The material's parameters are floats: 1e-6 covers their rounding.
    const double expected = 0.1 / kPi + 0.5 * lobe(-0.8, -0.3, 0.4, 6) + 0.25 * lobe(0.5, 0.5, 0.25, 3);
    EXPECT_NEAR(reference::eval(two, wi, wo).x, expected, 1e-6 * expected);
  }
  // The retro-reflective lobe peaks at wo = wi: (n+2)/(2 pi) rho_s there.
  const Material retro = makeMaterial("lafortune", {{"rho_d", 0}, {"rho_s", 1}, {"cx", 0.5}, {"cy", 0.5},
                                                    {"cz", 0.5}, {"n", 50}});
  const dvec3 w = direction(50, 20);
  EXPECT_NEAR(reference::eval(retro, w, w).x, 52.0 / (2.0 * kPi), 1e-12);
  EXPECT_LT(reference::eval(retro, w, direction(50, 200)).x, 1e-6);
}

// Löw's ABC microfacet model written out in angles: wi at 60 deg and wo at 30 deg on the other side put H 15 deg from
// n and 45 deg from wo; F is the textbook Fresnel pair with Snell's cos theta_t; at the normal f = (rho_d + A F0)/pi.
TEST(BrdfReference, AbcMicrofacetIsItsFormulaInAngles) {
  const dvec3 wi = direction(60, 0);
  const dvec3 wo = direction(30, 180);
  const double cosI = 0.5, cosO = std::cos(30 * kDegree), cosH = std::cos(15 * kDegree), VoH = std::cos(45 * kDegree);
  for (const auto& [a, b, c, ior] : {std::array<double, 4>{100, 2000, 1.25, 1.5}, std::array<double, 4>{8, 30, 0.5, 20},
                                     std::array<double, 4>{1100, 262144, 1, 1.25}}) {
    const Material abc = makeMaterial("abc_microfacet", {{"rho_d", 0.25}, {"a", a}, {"b", b}, {"c", c}, {"ior", ior}});
    const double cosT = std::sqrt(1.0 - (1.0 - VoH * VoH) / (ior * ior));
    const double rs = (VoH - ior * cosT) / (VoH + ior * cosT);
    const double rp = (ior * VoH - cosT) / (ior * VoH + cosT);
    const double F = 0.5 * (rs * rs + rp * rp);
    const double G = std::min({1.0, 2.0 * cosH * cosO / VoH, 2.0 * cosH * cosI / VoH});
    const double D = a / std::pow(1.0 + b * (1.0 - cosH), c);
    const double expected = 0.25 / kPi + D * F * G / (kPi * cosI * cosO);
    EXPECT_NEAR(reference::eval(abc, wi, wo).x, expected, 1e-12 * expected) << a << " " << b << " " << c;
    const double f0 = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
    const dvec3 n(0.0, 0.0, 1.0);
    EXPECT_NEAR(reference::eval(abc, n, n).x, (0.25 + a * f0) / kPi, 1e-12 * (0.25 + a * f0) / kPi);
  }
}

// Löw's smooth-surface model written out: the projected distance from the mirror direction, the Fresnel factor at
// the cosine of the projected difference, no division by cosines; at the mirror direction f = rho_d/pi + A F(cos).
TEST(BrdfReference, AbcSmoothIsItsFormula) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> angle(0.0, 89.0), azimuth(0.0, 360.0);
  const Material smooth = makeMaterial("abc_smooth", {{"rho_d", 0.25}, {"a", 40}, {"b", 3000}, {"c", 0.75}, {"ior", 2}});
  for (int k = 0; k < 200; ++k) {
    const dvec3 wi = direction(angle(random), azimuth(random)), wo = direction(angle(random), azimuth(random));
    const double d2 = (wi.x + wo.x) * (wi.x + wo.x) + (wi.y + wo.y) * (wi.y + wo.y);
    const double cosD = std::sqrt(1.0 - 0.25 * ((wi.x - wo.x) * (wi.x - wo.x) + (wi.y - wo.y) * (wi.y - wo.y)));
    const double cosT = std::sqrt(1.0 - (1.0 - cosD * cosD) / 4.0);
    const double rs = (cosD - 2.0 * cosT) / (cosD + 2.0 * cosT), rp = (2.0 * cosD - cosT) / (2.0 * cosD + cosT);
    const double expected = 0.25 / kPi + 40.0 * std::pow(1.0 + 3000.0 * d2, -0.75) * 0.5 * (rs * rs + rp * rp);
    EXPECT_NEAR(reference::eval(smooth, wi, wo).x, expected, 1e-12 * expected);
  }
  const dvec3 wi = direction(50, 20), mirror(-wi.x, -wi.y, wi.z);
  const double cosI = std::cos(50 * kDegree), cosT = std::sqrt(1.0 - (1.0 - cosI * cosI) / 4.0);
  const double rs = (cosI - 2.0 * cosT) / (cosI + 2.0 * cosT), rp = (2.0 * cosI - cosT) / (2.0 * cosI + cosT);
  EXPECT_NEAR(reference::eval(smooth, wi, mirror).x, 0.25 / kPi + 40.0 * 0.5 * (rs * rs + rp * rp), 1e-12);
}

// ior = 1 is no interface: the ABC models' Fresnel factor is 0 at every angle, grazing included, where Snell's
// cos theta_t computed as sqrt(1 - sin^2) made it 1 (ABC, 3e34 /sr at the grazing mirror pair) or 0/0 (smooth).
TEST(BrdfReference, AbcModelsAtIorOneHaveNoSpecularEvenAtGrazing) {
  const dvec3 grazing(1.0, 0.0, 1e-15), opposite(-1.0, 0.0, 1e-15), retro = grazing;
  for (const char* model : {"abc_microfacet", "abc_smooth"}) {
    const Material material = makeMaterial(model, {{"rho_d", 0.5}, {"a", 100000}, {"b", 1}, {"c", 4}, {"ior", 1}});
    for (const dvec3& wo : {opposite, retro, dvec3(0.6, 0.0, 0.8)}) {
      const dvec3 f = reference::eval(material, grazing, wo);
      EXPECT_EQ(f.x, 0.5 / kPi) << model;
    }
  }
}

TEST(BrdfReference, ValuesOffThePeakMatchTheFormulasInAngles) {
  // wi at 60 deg, wo at 30 deg on the other side (phi 0 and 180): H lies 15 deg from n towards wi, the angle
  // between wo and H is 45 deg, and R_i is 30 deg from wo. Each model written with these angles by hand.
  const dvec3 wi = direction(60, 0);
  const dvec3 wo = direction(30, 180);
  const double cosI = 0.5;
  const double cosO = std::cos(30 * kDegree);
  const double tanH = std::tan(15 * kDegree);
  const double cosH = std::cos(15 * kDegree);
  const double VoH = std::cos(45 * kDegree);
  auto f = [&](const Material& m) { return reference::eval(m, wi, wo).x; };
  auto near = [](double a, double b) { EXPECT_NEAR(a, b, 1e-13 * std::abs(b)); };

  near(f(makeMaterial("phong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 7}})), 9.0 / (2.0 * kPi) * std::pow(cosO, 7.0));
  near(f(makeMaterial("blinnphong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 7}})), 15.0 / (8.0 * kPi) * std::pow(cosH, 7.0));
  {
    const double m = 0.25;
    const double D = std::exp(-tanH * tanH / (m * m)) / (kPi * m * m * std::pow(cosH, 4.0));
    const double F0 = std::pow(0.5 / 2.5, 2.0);
    const double F = F0 + (1.0 - F0) * std::pow(1.0 - VoH, 5.0);
    const double G = std::min({1.0, 2.0 * cosH * cosO / VoH, 2.0 * cosH * cosI / VoH});
    near(f(makeMaterial("cooktorrance", {{"rho_d", 0}, {"rho_s", 1}, {"m", m}, {"eta", 1.5}})),
         D * F * G / (4.0 * cosI * cosO));
  }
  {
    const double ax = 0.25;
    const double ay = 0.5;  // H has phi_h = 0: only ax enters the exponent
    const double lobe = std::exp(-tanH * tanH / (ax * ax));
    const std::vector<ParamValue> params = {{"rho_d", 0}, {"rho_s", 1}, {"alpha_x", ax}, {"alpha_y", ay}};
    near(f(makeMaterial("ward", params)), lobe / (4.0 * kPi * ax * ay * std::sqrt(cosI * cosO)));
    near(f(makeMaterial("ward_duer", params)), lobe / (4.0 * kPi * ax * ay * cosI * cosO));
    // (h.h)/h_z^4 = 1/(|h|^2 cos^4 theta_h) with |h| = 2 V.H.
    near(f(makeMaterial("ward_gmd", params)), lobe / (kPi * ax * ay * 4.0 * VoH * VoH * std::pow(cosH, 4.0)));
  }
  {
    const double nu = 30;  // phi_h = 0: k = nu
    const double nv = 3;
    const double Rs = 0.25;
    const double Rd = 0.5;
    const double F = Rs + (1.0 - Rs) * std::pow(1.0 - VoH, 5.0);
    const double spec = std::sqrt((nu + 1) * (nv + 1)) / (8.0 * kPi) * std::pow(cosH, nu) / (VoH * cosO) * F;
    const double diff = 28.0 * Rd / (23.0 * kPi) * (1.0 - Rs) * (1.0 - std::pow(1.0 - cosI / 2.0, 5.0)) *
                        (1.0 - std::pow(1.0 - cosO / 2.0, 5.0));
    near(f(makeMaterial("ashikhmin_shirley", {{"Rd", Rd}, {"Rs", Rs}, {"nu", nu}, {"nv", nv}})), spec + diff);
  }
}

TEST(BrdfReference, ExactlyZeroBelowTheHorizonAndForNonFiniteInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<dvec3> below = {{1, 0, 0}, {0, 1, -0.0}, directionFromCos(-1e-7, 10), {0, 0, -1},
                                    {nan, 0, 1}, {0, 0, nan}, {inf, 0, 1}};
  const dvec3 above = direction(30, 45);
  for (const Material& material : extremeMaterials()) {
    for (const dvec3& w : below) {
      EXPECT_EQ(reference::eval(material, w, above), dvec3(0.0)) << modelName(material);
      EXPECT_EQ(reference::eval(material, above, w), dvec3(0.0)) << modelName(material);
      EXPECT_EQ(reference::pdf(material, w, above), 0.0) << modelName(material);
      EXPECT_EQ(reference::pdf(material, above, w), 0.0) << modelName(material);
      EXPECT_EQ(reference::sample(material, w, dvec3(0.3, 0.6, 0.9)).pdf, 0.0) << modelName(material);
    }
  }
}

TEST(BrdfReference, NeverNaNInfOrNegativeOnHardInputs) {
  const std::vector<dvec3> directions = hardDirections();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  long long checked = 0;
  for (const Material& material : extremeMaterials()) {
    for (const dvec3& wi : directions) {
      for (const dvec3& wo : directions) {
        const dvec3 f = reference::eval(material, wi, wo);
        const double p = reference::pdf(material, wi, wo);
        ASSERT_TRUE(std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z) && f.x >= 0 && f.y >= 0 && f.z >= 0)
            << modelName(material) << " wi " << wi.x << " " << wi.y << " " << wi.z << " wo " << wo.x << " " << wo.y
            << " " << wo.z;
        ASSERT_TRUE(std::isfinite(p) && p >= 0.0) << modelName(material);
        ++checked;
      }
      // The sampler at every hard wo, including u at 0 and just below 1.
      for (const dvec3& u : {dvec3(0.0), dvec3(std::nextafter(1.0, 0.0)), dvec3(uniform(rng), 0.0, 0.999999),
                             dvec3(uniform(rng), uniform(rng), uniform(rng))}) {
        const reference::Sample s = reference::sample(material, wi, u);
        ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf >= 0.0 && std::isfinite(s.f.x) && s.f.x >= 0.0)
            << modelName(material);
        if (s.pdf == 0.0) continue;
        ASSERT_GT(s.wi.z, 0.0);
        ASSERT_NEAR(glm::length(s.wi), 1.0, 1e-6) << modelName(material);
      }
    }
  }
  std::printf("checked %lld (material, wi, wo) triples on hard inputs\n", checked);
}

TEST(BrdfReference, GrazingMirrorPairsOfNonUnitInputsStayFinite) {
  // wi ~ -wo in x and y with tiny z: h is tiny and, for float-rounded inputs, wo.h can round to <= 0.
  for (const Material& material : extremeMaterials()) {
    for (double z : {1e-7, 1e-6, 1e-4}) {
      for (double scale : {1.0 + 1e-7, 1.0 - 1e-7}) {
        const dvec3 wo = dvec3(glm::vec3(directionFromCos(z, 0.0)));
        const dvec3 wi = dvec3(glm::vec3(directionFromCos(z, 180.0) * scale));
        const dvec3 f = reference::eval(material, wi, wo);
        EXPECT_TRUE(std::isfinite(f.x) && f.x >= 0.0) << modelName(material);
        const double p = reference::pdf(material, wi, wo);
        EXPECT_TRUE(std::isfinite(p) && p >= 0.0) << modelName(material);
      }
    }
  }
}

TEST(BrdfReference, HardCasesAreAccurateInDouble) {
  // Sharp lobes: (N.H)^s at s = 1e4 a small tilt d off the peak, against cos(d)^s = exp(s log1p(-2 sin^2(d/2))).
  const Material bp = makeMaterial("blinnphong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 10000}});
  for (double tilt : {1e-6, 1e-4, 1e-3, 1e-2, 3e-2}) {
    // wi and wo mirror-symmetric about a half vector tilted by `tilt` from n in the x-z plane.
    const dvec3 H(std::sin(tilt), 0.0, std::cos(tilt));
    const dvec3 wo = direction(40, 180);
    const dvec3 wi = 2.0 * glm::dot(wo, H) * H - wo;
    const double half = std::sin(0.5 * tilt);
    const double exact = 10008.0 / (8.0 * kPi) * std::exp(10000.0 * std::log1p(-2.0 * half * half));
    EXPECT_NEAR(reference::eval(bp, wi, wo).x, exact, 1e-11 * exact) << tilt;
  }
  // Beckmann at m = 0.001: tan^2 from the components of h keeps its relative accuracy at tilts of 1e-6.
  for (double tilt : {1e-6, 1e-4, 1e-3, 2e-3}) {
    const double m = 0.001;
    const double tan2 = std::tan(tilt) * std::tan(tilt);
    const dvec3 h(std::sin(tilt), 0.0, std::cos(tilt));
    EXPECT_NEAR(reference::tan2ThetaH(h), tan2, 1e-14 * tan2);
    const double exact = std::exp(-tan2 / (m * m)) / (kPi * m * m * std::pow(std::cos(tilt), 4.0));
    EXPECT_NEAR(reference::D_Beckmann(reference::tan2ThetaH(h), m), exact, 1e-12 * exact);
  }
  // Ashikhmin-Shirley's 1 - (1 - c/2)^5 at c = 1e-7: 5x - 10x^2 + ... with x = c/2, where the naive form in
  // double keeps only about 8 digits.
  for (double c : {1e-7, 1e-5, 1e-3, 0.5, 1.0}) {
    const double x = 0.5 * c;
    const double exact = 5 * x - 10 * x * x + 10 * x * x * x - 5 * x * x * x * x + x * x * x * x * x;
    EXPECT_NEAR(reference::AS_diffuseFalloff(c), exact, 1e-15 * exact) << c;
  }
  // Ashikhmin-Shirley's k is a weighted mean of nu and nv even when h_x^2 + h_y^2 underflows.
  EXPECT_DOUBLE_EQ(reference::AS_exponent(dvec3(1e-200, 1e-200, 1.0), 10.0, 30.0), 20.0);
  EXPECT_DOUBLE_EQ(reference::AS_exponent(dvec3(0.0, 0.0, 1.0), 10.0, 30.0), 10.0);
}

TEST(BrdfReference, ShadingFrameIsOrthonormalAndFallsBackForDegenerateTangents) {
  struct Case {
    dvec3 n, t;
  };
  const std::vector<Case> cases = {{{0, 0, 1}, {1, 0, 0}},      {{0, 0, 1}, {0, 0, 0}},   {{0, 0, -1}, {0, 0, 0}},
                                   {{0, 0, 2}, {0, 0, 5}},      {{1, 2, 3}, {1, 0, 0}},   {{0, 0, -1}, {1, 1e-9, 0}},
                                   {{1, 0, 0}, {1, 1e-7, 0}},   {{0.3, -0.4, 0.1}, {0, 1, 1}}};
  for (const Case& c : cases) {
    const reference::Frame frame = reference::makeFrame(c.n, c.t);
    EXPECT_NEAR(glm::length(frame.n), 1.0, 1e-15);
    EXPECT_NEAR(glm::length(frame.t), 1.0, 1e-15);
    EXPECT_NEAR(glm::dot(frame.t, frame.n), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(frame.b - glm::cross(frame.n, frame.t)), 0.0, 1e-15);
    const dvec3 local = reference::toLocal(frame, c.n);
    EXPECT_NEAR(local.z, glm::length(c.n), 1e-14);
  }
  // A usable hint is kept (Gram-Schmidt), a parallel one is replaced.
  EXPECT_NEAR(reference::makeFrame({0, 0, 1}, {2, 0, 1}).t.x, 1.0, 1e-15);
  EXPECT_THROW(reference::makeFrame(dvec3(0.0), {1, 0, 0}), Error);
}

TEST(BrdfReference, MaterialRecordConvertsExactly) {
  gpu::MaterialRecord record = defaultRecord(modelId("ashikhmin_shirley"));
  setParam(record, "Rd", glm::vec3(0.1f, 0.2f, 0.3f), "test");
  setParam(record, "nu", glm::vec3(7.0f), "test");
  const Material material = reference::fromRecord(record);
  EXPECT_EQ(material.model, modelId("ashikhmin_shirley"));
  EXPECT_EQ(rgbParam(material, "Rd"), dvec3(glm::vec3(0.1f, 0.2f, 0.3f)));
  EXPECT_EQ(scalarParam(material, "nu"), 7.0);
  EXPECT_EQ(scalarParam(material, "nv"), static_cast<double>(getParam(record, "nv").x));
}

TEST(BrdfReference, SpecularProbabilityFollowsTheContract) {
  EXPECT_EQ(reference::specularProbability(makeMaterial("lambert", {{"rho_d", 0.5}})), 0.0);
  EXPECT_EQ(reference::specularProbability(makeMaterial("glass", {})), 0.0);
  EXPECT_EQ(reference::specularProbability(makeMaterial("phong", {{"rho_d", 0}, {"rho_s", 0}})), 0.5);
  Material material = makeMaterial("cooktorrance", {});
  setParamExactly(material, "rho_d", dvec3(0.1, 0.2, 0.3));
  setParamExactly(material, "rho_s", dvec3(0.4, 0.0, 0.2));
  EXPECT_DOUBLE_EQ(reference::specularProbability(material), 0.6 / 1.2);
}

TEST(BrdfReference, SampleCarriesEvalAndPdfOrFailsCleanly) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const Material& material : extremeMaterials()) {
    int failed = 0;
    for (int k = 0; k < 2000; ++k) {
      const dvec3 wo = directionFromCos(std::max(1e-6, uniform(rng)), 360.0 * uniform(rng));
      const reference::Sample s = reference::sample(material, wo, dvec3(uniform(rng), uniform(rng), uniform(rng)));
      if (s.pdf == 0.0) {
        EXPECT_EQ(s.wi, dvec3(0.0));
        EXPECT_EQ(s.f, dvec3(0.0));
        ++failed;
        continue;
      }
      EXPECT_EQ(s.f, reference::eval(material, s.wi, wo));
      EXPECT_EQ(s.pdf, reference::pdf(material, s.wi, wo));
    }
    EXPECT_LT(failed, 2000) << modelName(material);
  }
  // Glass is a delta BSDF: no sample, no density.
  const Material glass = makeMaterial("glass", {});
  EXPECT_EQ(reference::sample(glass, direction(30, 0), dvec3(0.5)).pdf, 0.0);
  EXPECT_EQ(reference::pdf(glass, direction(30, 0), direction(30, 180)), 0.0);
  EXPECT_EQ(reference::eval(glass, direction(30, 0), direction(30, 180)), dvec3(0.0));
}

}  // namespace
}  // namespace raylab::test
