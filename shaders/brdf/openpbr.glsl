// OpenPBR Surface 1.1.1: a metal and a glossy-diffuse (or subsurface, or translucent) dielectric mixed by metalness,
// under a thin film, a coat and a fuzz; solid or a thin wall; emitting.
// lobes: reflection transmission diffuse glossy
// feature: coat coat_weight
// feature: thin_film thin_film_weight
// feature: fuzz fuzz_weight
// feature: transmission transmission_weight
// feature: thin_walled geometry_thin_walled
// feature: dispersion transmission_dispersion_scale
// feature: coat_frame geometry_coat_normal_x
// feature: coat_frame geometry_coat_normal_y
// feature: coat_frame geometry_coat_tangent_angle
// medium: transmission_weight base_metalness transmission_color transmission_depth geometry_thin_walled
// albedo sampled when: geometry_thin_walled
// fit: free base_color base_metalness base_diffuse_roughness specular_roughness specular_ior coat_weight coat_roughness
// fit: free fuzz_weight fuzz_roughness, the layers an opaque isotropic reflection shows: metal or dielectric, coat, fuzz
// fit: by name, its fit costs several of the others' (7-9 s of CPU a slice): named, or in the study (fitting.md)
// reciprocal: no, albedo scaling by 1 - E(wo) conserves energy but weighs wo and wi differently (OpenPBR)
// look: base_color=0.8/0.25/0.1, specular_roughness=0.35, coat_weight=1, coat_roughness=0.05
// figure: base_color=0.8/0.25/0.1, specular_roughness=0.4, coat_weight=1, coat_roughness=0.1
// figure metal: base_color=0.95/0.64/0.54, base_metalness=1, specular_color=0.95/0.8/0.75, specular_roughness=0.3
// | parameter                     | range    | default | kind              | meaning                                  |
// |-------------------------------|----------|---------|-------------------|------------------------------------------|
// | base_weight                   | [0, 1]   | 1       |                   | scales the base's diffuse albedo and metal F0 |
// | base_color                    | [0, 1]   | 0.8     | rgb diffuse       | diffuse albedo, or the metal's F0         |
// | base_metalness                | [0, 1]   | 0       | metallic          | 0 dielectric, 1 metal, a mix between      |
// | base_diffuse_roughness        | [0, 1]   | 0       |                   | EON's roughness of the diffuse lobe       |
// | specular_weight               | [0, 5]   | 1       | specular_weight   | scales the dielectric's F0 (by its index), and the metal's F |
// | specular_color                | [0, 1]   | 1       | rgb specular_tint | tints the dielectric's reflection; the metal's F82 edge tint |
// | specular_roughness            | [0, 1]   | 0.3     | roughness         | roughness r of the base; alpha = r^2      |
// | specular_roughness_anisotropy | [0, 1]   | 0       |                   | stretches the base's GGX along the tangent |
// | specular_ior                  | [1, 5]   | 1.5     | eta               | index of refraction of the dielectric     |
// | coat_weight                   | [0, 1]   | 0       |                   | coverage of the coat                      |
// | coat_color                    | [0, 1]   | 1       | rgb               | the coat's transmittance squared at normal incidence |
// | coat_roughness                | [0, 1]   | 0       |                   | roughness of the coat's GGX               |
// | coat_roughness_anisotropy     | [0, 1]   | 0       |                   | stretches the coat's GGX along the tangent |
// | coat_ior                      | [1, 3]   | 1.6     |                   | index of refraction of the coat           |
// | coat_darkening                | [0, 1]   | 1       |                   | 1: the coat darkens the base as physics does; 0: compensated |
// | thin_film_weight              | [0, 1]   | 0       |                   | coverage of the thin film on the base     |
// | thin_film_thickness           | [0, 5]   | 0.5     |                   | the film's thickness in micrometres       |
// | thin_film_ior                 | [1, 3]   | 1.4     |                   | the film's index of refraction            |
// | fuzz_weight                   | [0, 1]   | 0       |                   | coverage of the fuzz over everything      |
// | fuzz_color                    | [0, 1]   | 1       | rgb               | tints the light the fuzz reflects         |
// | fuzz_roughness                | [0, 1]   | 0.5     |                   | 0: fibres along the normal; 1: round flakes |
// | transmission_weight           | [0, 1]   | 0       |                   | the dielectric's share that lets light through |
// | transmission_color            | [0, 1]   | 1       | rgb               | the colour the volume reaches at transmission_depth |
// | transmission_depth            | [0, 1000] | 0      |                   | that depth in scene units; 0: no volume, tinted at the surface |
// | transmission_dispersion_scale | [0, 1]   | 0       |                   | the dispersion's strength: 0 none, 1 the Abbe number's |
// | transmission_dispersion_abbe_number | [1, 1000] | 20 |                 | the Abbe number V_d at scale 1 (glass 60, polycarbonate 32) |
// | subsurface_weight             | [0, 1]   | 0       |                   | the dielectric's share that scatters below the surface |
// | subsurface_color              | [0, 1]   | 0.8     | rgb               | the albedo of that scattering             |
// | subsurface_scatter_anisotropy | [-1, 1]  | 0       |                   | on a thin wall, the share through: (1 + g) / 2 |
// | geometry_thin_walled          | [0, 1]   | 0       |                   | 1: a thin shell (leaf, paper, bubble); 0: a solid |
// | geometry_coat_normal_x        | [-1, 1]  | 0       |                   | the coat's own normal: its x in the base's shading frame (a coat normal map sets it) |
// | geometry_coat_normal_y        | [-1, 1]  | 0       |                   | its y; z = sqrt(1 - x^2 - y^2)            |
// | geometry_coat_tangent_angle   | [-3.1416, 3.1416] | 0 |                | turns the coat's tangent (its anisotropy's direction) from the base's, radians |
// | emission_luminance            | [0, 1000000] | 0   | emission_luminance | emitted luminance in nits (raylab's radiance unit) |
// | emission_color                | [0, 1]   | 1       | rgb emission_color | the emission's colour                    |
// | geometry_opacity              | [0, 1]   | 1       | opacity           | coverage: 0 a hole, 1 solid; between, the chance a ray meets the surface |
// Portsmouth, Hoffman, Pharr, Kutz, Leidl et al., "OpenPBR Surface", Academy Software Foundation, v1.1.1, 2026,
// section "Reduction to a mixture of lobes", with non-reciprocal albedo scaling (docs/brdfs.md, "openpbr"):
//   f = C f_coat + lerp(1, T (1 - E_coat(wo)), C) lerp(1, Delta, C delta) lerp(f_dielectric, f_metal, M),
//   f_dielectric = specular_color f_spec + (1 - E_spec(wo)) f_EON(base_weight base_color, base_diffuse_roughness),
//   f_metal = F_82(wo.H) D G / (4 cos_i cos_o) + Kulla & Conty's multiple scattering,
// C = coat_weight, M = base_metalness, delta = coat_darkening. f_spec and f_coat are GGX dielectric reflections
// (separable Smith G, exact Fresnel F(wo.H)); E_spec and E_coat their directional albedos, read from a build-time
// table (shared/brdf_tables.h) at the width the lobe has along wo's azimuth. The specular index is
// eta_s = lerp(specular_ior, specular_ior / coat_ior, C), taken as 1 / eta_s below 1 (no total internal reflection
// under the coat: a ray inside the coat never reaches the base beyond the critical angle); specular_weight scales
// its F0: eps = sqrt(min(1, specular_weight F0)),
// eta' = (1 + eps) / (1 - eps). Metal (F82-tint, Kutz et al. 2021): F0 = base_weight base_color, F_s = Schlick,
// b = F_s(1/7) (1 - specular_color) / ((1/7)(6/7)^6),
// F_82 = min(1, specular_weight clamp(F_s(mu) - b mu (1 - mu)^6, 0, 1)).
// Anisotropy: alpha_t = r^2 sqrt(2 / (1 + (1 - a)^2)), alpha_b = (1 - a) alpha_t, each at least 0.001. Coat:
// view-dependent absorption T = coat_color^((1/mu_i^t + 1/mu_o^t) / 2) with the cosines refracted into the coat,
// roughening of the base r' = lerp(r, min(1, r^4 + 2 r_c^4)^(1/4), C), and darkening
// Delta = (1 - K) / (1 - E_b K), K = lerp(F_coat(cos_o), 1 - (1 - E_F) / coat_ior^2, r_b).
// Emission (emission_luminance x emission_color) is not part of f: the host keeps the material's emission equal to
// it (brdf_params, setParam), which the integrators and the light list read as every emitter's.
// Opacity (geometry_opacity) is not part of f either: it is coverage, the chance a ray meets the surface at all,
// decided in the traversal (kernel/alpha.glsl) so that shadow rays see it too.
// Fuzz (OpenPBR, "Fuzz", after Zeltner et al. 2022; fuzz.glsl): F fuzz_color f_fuzz + (1 - F E_fuzz(wo)) f_below,
// F = fuzz_weight: the fuzz reflects E_fuzz of the light and passes the rest, untinted, to the coated base.
// Sampled as a mixture fixed per material: the cosine lobe, or GGX visible normals of the coat or of the base, or
// the fuzz's LTC.
#ifndef RAYLAB_BRDF_OPENPBR_GLSL
#define RAYLAB_BRDF_OPENPBR_GLSL

#extension GL_EXT_control_flow_attributes : require

#include "brdf/brdf_tables.glsl"
#include "brdf/eon.glsl"
#include "brdf/fresnel.glsl"
#include "brdf/fuzz.glsl"
#include "brdf/ggx_dielectric.glsl"
#include "brdf/ggx.glsl"
#include "brdf/sampling.glsl"
#include "brdf/thin_film.glsl"

// The coat's own shading frame (OpenPBR's geometry_coat_normal and geometry_coat_tangent; glTF's coat normal map and
// coat anisotropy rotation) in the base's: its normal (x, y, sqrt(1 - x^2 - y^2)), at most 88 degrees from the base's,
// and its tangent, the base's turned by the angle and made orthogonal to that normal. The coat's lobe, its albedo and
// its path lengths are taken in it, the base below in the base's frame; an orthonormal change of frame leaves the
// densities as they are. The defaults are the base's frame itself.
struct OpenpbrCoatFrame {
  vec3 t;
  vec3 b;
  vec3 n;
};
OpenpbrCoatFrame openpbrCoatFrame(float normalX, float normalY, float tangentAngle) {
  OpenpbrCoatFrame f = OpenpbrCoatFrame(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
  // A scene without a coat of its own frame compiles none (kernels are compiled per scene: vk/spirv_specialization.h).
  if (!featureEnabled(kOpenpbrFeatureCoatFrame) || (normalX == 0.0 && normalY == 0.0 && tangentAngle == 0.0)) {
    return f;
  }
  vec2 slope = vec2(normalX, normalY);
  const float sine2 = dot(slope, slope), kMaxSine2 = 0.9988;  // sin^2 of 88 degrees
  if (sine2 > kMaxSine2) slope *= sqrt(kMaxSine2 / sine2);
  f.n = vec3(slope, sqrt(1.0 - dot(slope, slope)));
  const vec3 t = vec3(cos(tangentAngle), sin(tangentAngle), 0.0);
  f.t = normalize(t - f.n * dot(f.n, t));  // t is horizontal and n at least 2 degrees above: never parallel
  f.b = cross(f.n, f.t);
  return f;
}
vec3 openpbrToCoat(OpenpbrCoatFrame f, vec3 w) { return vec3(dot(w, f.t), dot(w, f.b), dot(w, f.n)); }
vec3 openpbrFromCoat(OpenpbrCoatFrame f, vec3 w) { return w.x * f.t + w.y * f.b + w.z * f.n; }

// The GGX widths (alpha_t, alpha_b) of a roughness and an anisotropy (OpenPBR, "Microfacet model").
vec2 openpbrAlphas(float roughness, float anisotropy) {
  const float alphaT = roughness * roughness * sqrt(2.0 / (1.0 + (1.0 - anisotropy) * (1.0 - anisotropy)));
  return max(vec2(alphaT, (1.0 - anisotropy) * alphaT), vec2(1e-3));
}

// The base's roughness roughened by the coat (OpenPBR, "Roughening").
float openpbrBaseRoughness(float specularRoughness, float coatWeight, float coatRoughness) {
  const float r2 = specularRoughness * specularRoughness, c2 = coatRoughness * coatRoughness;
  return mix(specularRoughness, sqrt(sqrt(min(1.0, r2 * r2 + 2.0 * c2 * c2))), coatWeight);
}

// The coat's weight where a scene compiles a coat, else the constant 0: the coat's code then folds away.
float openpbrCoat(float coatWeight) { return featureEnabled(kOpenpbrFeatureCoat) ? coatWeight : 0.0; }

// The base's GGX widths, its roughness roughened by a coat of weight C.
vec2 openpbrBaseAlphas(float specularRoughness, float specularAnisotropy, float C, float coatRoughness) {
  return openpbrAlphas(openpbrBaseRoughness(specularRoughness, C, coatRoughness), specularAnisotropy);
}

// eps = (eta' - 1) / (eta' + 1) = sqrt(F0) of the base dielectric seen from the coat's mix of media, specular_weight
// applied (OpenPBR, "Dielectric base"); an index below 1 is taken as its inverse, which has the same F0.
float openpbrSpecularEps(float specularWeight, float specularIor, float coatWeight, float coatIor) {
  float eta = mix(specularIor, specularIor / coatIor, coatWeight);
  eta = eta < 1.0 ? 1.0 / eta : eta;
  const float F0 = (eta - 1.0) * (eta - 1.0) / ((eta + 1.0) * (eta + 1.0));
  return sqrt(clamp(specularWeight * F0, 0.0, 1.0));
}

// ggx_dielectric's index floor: an index of 1 has no refraction half vector.
float openpbrTransmissionEta(float specularIor) { return max(specularIor, 1.001); }

// Dispersion (transmission_dispersion_scale, compiled only where a scene has one): the index at the three Fraunhofer
// lines that define the Abbe number, C (656.3 nm) for red, d (587.6 nm) for green and F (486.1 nm) for blue, from
// Cauchy's two terms as KHR_materials_dispersion writes them, n = max(n_d + (n_d - 1) / V (523655 / lambda^2 -
// 1.5168), 1) with V = abbe_number / scale: green keeps specular_ior (to 2e-4 of the spread) and blue less red is
// (n_d - 1) / V, the Abbe number's own definition. The dielectric's Fresnel term and the solid's refraction take each
// channel's index, so each channel keeps the furnace; the albedo tables of the layering keep specular_ior (a part in
// 10^3 of the spread).
bool openpbrDispersive(float dispersionScale) {
  return featureEnabled(kOpenpbrFeatureDispersion) && dispersionScale > 0.0;
}
vec3 openpbrDispersedEtas(float specularIor, float dispersionScale, float abbeNumber) {
  if (!openpbrDispersive(dispersionScale)) return vec3(openpbrTransmissionEta(specularIor));
  const vec3 lambda = vec3(656.3, 587.6, 486.1);
  const vec3 n = specularIor + (specularIor - 1.0) * dispersionScale / max(abbeNumber, 1.0) *
                 (523655.0 / (lambda * lambda) - 1.5168);
  return max(n, vec3(1.001));  // the floor of openpbrTransmissionEta
}

// The exact Fresnel reflectance from outside at cosine c of the index (1 + eps)/(1 - eps); eps near 1 is a
// perfect mirror (an index beyond float's reach), eps = 0 no interface.
float openpbrFresnel(float c, float eps) {
  if (eps >= 0.9999) return 1.0;
  return F_DielectricExact(c, 1.0, (1.0 + eps) / (1.0 - eps));
}

// 1 - E_r in slice z of the build-time table (shared/brdf_tables.h), bilinear at (x, y) in entries. Written out
// rather than looped: lavapipe compiles every copy of this (five per evaluation), and the straight-line form
// compiles in a fraction of the time.
float openpbrLossInSlice(uint z, float x, float y) {
  const uint x0 = min(uint(x), kGgxAlbedoSize - 2u), y0 = min(uint(y), kGgxAlbedoSize - 2u);
  const uint i = kDielectricAlbedoOffset + (z * kGgxAlbedoSize + y0) * kGgxAlbedoSize + x0;
  const float tx = x - float(x0);
  return mix(mix(brdfTables[i], brdfTables[i + 1u], tx),
             mix(brdfTables[i + kGgxAlbedoSize], brdfTables[i + kGgxAlbedoSize + 1u], tx), y - float(y0));
}

// 1 - E_r(mu, alpha, eps), trilinear in (sqrt(mu), sqrt(alpha), eps).
float openpbrDielectricLoss(float mu, float alpha, float eps) {
  const float last = float(kGgxAlbedoSize - 1u);
  const float x = sqrt(clamp(mu, 0.0, 1.0)) * last, y = sqrt(clamp(alpha, 0.0, 1.0)) * last;
  const float z = clamp(eps, 0.0, 1.0) * float(kDielectricAlbedoEpsSize - 1u);
  const uint z0 = min(uint(z), kDielectricAlbedoEpsSize - 2u);
  return mix(openpbrLossInSlice(z0, x, y), openpbrLossInSlice(z0 + 1u, x, y), z - float(z0));
}

// 1 - E of GGX with F = 1: the table's last slice, bilinear.
float openpbrMirrorLoss(float mu, float alpha) {
  const float last = float(kGgxAlbedoSize - 1u);
  return openpbrLossInSlice(kDielectricAlbedoEpsSize - 1u, sqrt(clamp(mu, 0.0, 1.0)) * last,
                            sqrt(clamp(alpha, 0.0, 1.0)) * last);
}

// 2 integral F(mu) mu dmu of the Fresnel term at eps, linear in the table.
float openpbrAverageFresnel(float eps) {
  const float z = clamp(eps, 0.0, 1.0) * float(kDielectricAlbedoEpsSize - 1u);
  const uint z0 = min(uint(z), kDielectricAlbedoEpsSize - 2u);
  return mix(brdfTables[kAverageFresnelOffset + z0], brdfTables[kAverageFresnelOffset + z0 + 1u], z - float(z0));
}

// The GGX width seen along w's azimuth, sqrt(alpha_t^2 cos^2 phi + alpha_b^2 sin^2 phi): the width Smith's masking
// of w sees, at which the isotropic albedo tables stand in for an anisotropic lobe's (at the normal, where phi is
// undefined, sqrt(alpha_t alpha_b)).
float openpbrProjectedAlpha(vec2 alpha, vec3 w) {
  const float s2 = w.x * w.x + w.y * w.y;
  if (!(s2 > 0.0)) return sqrt(alpha.x * alpha.y);
  return sqrt((alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y) / s2);
}

// A GGX dielectric reflection without its colour: F(wo.H) D G1(wi) G1(wo) / (4 cos_i cos_o).
// wo.H, clamped to [0, 1]: the cosine every Fresnel term of the model takes.
float openpbrCosineToHalfVector(vec3 wo, vec3 h) { return clamp(dot(wo, h) * inversesqrt(dot(h, h)), 0.0, 1.0); }

// D G1(wi) G1(wo) / (4 cos_i cos_o) of a GGX lobe: the dielectric reflections' and the metal's.
float openpbrMicrofacet(vec3 wi, vec3 wo, vec3 h, vec2 alpha) {
  return D_GGX(h, alpha.x, alpha.y) * G1_GGX(wi, alpha.x, alpha.y) * G1_GGX(wo, alpha.x, alpha.y) / (4.0 * wi.z * wo.z);
}

float openpbrGgxReflection(vec3 wi, vec3 wo, vec3 h, vec2 alpha, float eps) {
  return openpbrFresnel(openpbrCosineToHalfVector(wo, h), eps) * openpbrMicrofacet(wi, wo, h, alpha);
}

// F-82 tint (Kutz, Hasan & Edmondson, "Novel aspects of the Adobe Standard Material", 2021) at cosine mu.
const float kOpenpbrMuBar = 1.0 / 7.0;
vec3 openpbrF82B(vec3 F0, vec3 specularColor) {
  const vec3 atBar = F_Schlick(F0, 1.0 - kOpenpbrMuBar);
  return atBar * (1.0 - specularColor) / (kOpenpbrMuBar * pow(1.0 - kOpenpbrMuBar, 6.0));
}
vec3 openpbrF82(vec3 F0, vec3 b, float mu) {
  const float m = 1.0 - mu;
  return clamp(F_Schlick(F0, m) - b * (mu * m * m * m * m * m * m), 0.0, 1.0);
}

// The metal's multiple scattering (Kulla & Conty 2017, as ggx_conductor), with F_avg of the F82 curve in closed
// form: 2 integral mu F mu dmu = F0 + (1 - F0)/21 - b/126; E and E_avg from the F = 1 slice of the layering table,
// whose finer axes keep a white metal's furnace within the table's accuracy at grazing angles.
vec3 openpbrMetalMultipleScattering(vec3 F0, vec3 b, float weight, vec2 alpha, vec3 wi, vec3 wo) {
  const float a = sqrt(alpha.x * alpha.y);
  const float y = sqrt(clamp(a, 0.0, 1.0)) * float(kGgxAlbedoSize - 1u);
  const uint y0 = min(uint(y), kGgxAlbedoSize - 2u);
  const float averageLoss = mix(brdfTables[kMirrorAverageLossOffset + y0], brdfTables[kMirrorAverageLossOffset + y0 + 1u],
                                y - float(y0));
  if (!(averageLoss > 1e-6)) return vec3(0.0);
  const float eAvg = 1.0 - averageLoss;
  const vec3 fAvg = clamp(weight * (F0 + (1.0 - F0) / 21.0 - b / 126.0), 0.0, 1.0);
  const vec3 fMs = fAvg * fAvg * eAvg / (vec3(1.0) - fAvg * averageLoss);
  const float lossO = openpbrMirrorLoss(wo.z, openpbrProjectedAlpha(alpha, wo));
  const float lossI = openpbrMirrorLoss(wi.z, openpbrProjectedAlpha(alpha, wi));
  return fMs * max(lossO * lossI / (kPi * averageLoss), 0.0);
}

// The probabilities of the mixture: (the specular lobes against the cosine lobe, the coat within the specular
// lobes, the fuzz within them). Fixed per material: a glossy share for the metal, four times the dielectric's F0
// (its reflectance rises towards grazing), a quarter for the coat, half the fuzz's mean colour, against the diffuse
// albedo.
vec3 openpbrLobeProbabilities(float baseWeight, vec3 baseColor, float metalness, float specularWeight,
                              float specularIor, float coatWeight, float coatIor, float fuzzWeight, vec3 fuzzColor) {
  const float eps = openpbrSpecularEps(specularWeight, specularIor, coatWeight, coatIor);
  const float diffuse = (1.0 - metalness) * baseWeight * sum3(baseColor) / 3.0;
  const float base = metalness + (1.0 - metalness) * min(1.0, 4.0 * eps * eps);
  const float coat = 0.25 * coatWeight;
  const float fuzz = 0.5 * fuzzWeight * sum3(fuzzColor) / 3.0;
  const float specular = base + coat + fuzz;
  return vec3(diffuse + specular > 0.0 ? specular / (diffuse + specular) : 0.5,
              specular > 0.0 ? coat / specular : 0.0, specular > 0.0 ? fuzz / specular : 0.0);
}

// The coat over the substrate: its reflection, the absorption along the two refracted paths through it, and the
// darkening by the light it reflects back onto the base, all in the coat's frame (a direction below the coat's
// horizon and above the base's meets the coat at grazing: it reflects nothing there). wiBase and woBase are above
// the base's horizon (lifted).
vec3 openpbrCoatOver(vec3 substrate, vec3 wiBase, vec3 woBase, float C, vec3 coatColor, float coatRoughness,
                     float coatAnisotropy, float coatIor, float coatDarkening, OpenpbrCoatFrame frame,
                     float alphaTable, float eps, vec3 rho, vec3 diffuseAlbedo, vec3 specularColor,
                     float specularWeight, float specularRoughness, float M) {
  const vec3 wiCoat = openpbrToCoat(frame, wiBase), woCoat = openpbrToCoat(frame, woBase);
  const bool above = wiCoat.z > 0.0 && woCoat.z > 0.0;
  const vec3 wi = liftOffHorizon(wiCoat), wo = liftOffHorizon(woCoat);
  precise const vec3 h = wi + wo;
  const vec2 alphaCoat = openpbrAlphas(coatRoughness, coatAnisotropy);
  const float epsCoat = (coatIor - 1.0) / (coatIor + 1.0);
  // f cos is the coat's own (its f times the cosine to its normal, as a surface of that normal reflects), so that
  // the coat never returns more than its albedo E_coat: the integrator multiplies f by the base's cosine.
  const vec3 coat = above ? vec3(openpbrGgxReflection(wi, wo, h, alphaCoat, epsCoat) * (wi.z / wiBase.z))
                          : vec3(0.0);
  const float coatPassed = openpbrDielectricLoss(wo.z, openpbrProjectedAlpha(alphaCoat, wo), epsCoat);  // 1 - E_coat
  // Absorption along the two paths through the coat, refracted: cos_t^2 = 1 - (1 - cos^2) / coat_ior^2.
  const float inv2 = 1.0 / (coatIor * coatIor);
  const float pathLength = 0.5 * (inversesqrt(1.0 - (1.0 - wi.z * wi.z) * inv2) +
                                  inversesqrt(1.0 - (1.0 - wo.z * wo.z) * inv2));
  const vec3 T = pow(max(coatColor, vec3(0.0)), vec3(pathLength));
  // Darkening by the light the coat reflects back onto the base (OpenPBR, "Darkening").
  vec3 darkening = vec3(1.0);
  if (coatDarkening > 0.0) {
    const float eSpecNormal = 1.0 - openpbrDielectricLoss(1.0, alphaTable, eps);
    const vec3 eBase = mix(specularColor * eSpecNormal + (1.0 - eSpecNormal) * diffuseAlbedo,
                           min(specularWeight * rho, vec3(1.0)), M);
    const float kRough = 1.0 - (1.0 - openpbrAverageFresnel(epsCoat)) * inv2;
    const float kSmooth = openpbrFresnel(wo.z, epsCoat);
    const float rDielectric = mix(1.0, specularRoughness, eps * eps);
    const float K = mix(kSmooth, kRough, mix(rDielectric, specularRoughness, M));
    // E_b, K <= 1: Delta <= 1, and 0/0 (a white base under a coat that returns everything) is no darkening.
    const vec3 denominator = vec3(1.0) - eBase * K;
    const vec3 delta = mix(vec3(1.0), (1.0 - K) / max(denominator, vec3(1e-30)), greaterThan(denominator, vec3(0.0)));
    darkening = mix(vec3(1.0), delta, C * coatDarkening);
  }
  return C * coat + mix(vec3(1.0), T * coatPassed, C) * darkening * substrate;
}

// The fuzz over everything (fuzz.glsl), compiled only where a scene has one.
vec3 openpbrFuzzOver(vec3 below, vec3 wi, vec3 wo, float fuzzWeight, vec3 fuzzColor, float fuzzRoughness) {
  const float F = featureEnabled(kOpenpbrFeatureFuzz) ? fuzzWeight : 0.0;
  if (!(F > 0.0)) return below;
  const vec3 lobe = fuzzLobe(wo.z, fuzzRoughness);
  return F * fuzzColor * (lobe.x * fuzzDensity(wi, wo, lobe) / wi.z) + (1.0 - F * lobe.x) * below;
}

vec3 openpbrReflection(float baseWeight, vec3 baseColor, float metalness, float diffuseRoughness, float specularWeight,
                 vec3 specularColor, float specularRoughness, float specularAnisotropy, float specularIor,
                 float coatWeight, vec3 coatColor, float coatRoughness, float coatAnisotropy, float coatIor,
                 float coatDarkening, float thinFilmWeight, float thinFilmThickness, float thinFilmIor,
                 float fuzzWeight, vec3 fuzzColor, float fuzzRoughness, float dispersionScale, float abbeNumber,
                 OpenpbrCoatFrame coatFrame, vec3 diffuseAlbedo, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  precise const vec3 h = wi + wo;
  // A scene without a coat compiles none: C is then the constant 0, and the coat's code folds away.
  const float C = openpbrCoat(coatWeight), M = metalness;

  // The base substrate: the glossy-diffuse dielectric and the metal.
  const float r = openpbrBaseRoughness(specularRoughness, C, coatRoughness);
  const vec2 alpha = openpbrAlphas(r, specularAnisotropy);
  const float alphaTable = sqrt(alpha.x * alpha.y);
  const float eps = openpbrSpecularEps(specularWeight, specularIor, C, coatIor);
  const vec3 rho = baseWeight * baseColor;
  const float loss = openpbrDielectricLoss(wo.z, openpbrProjectedAlpha(alpha, wo), eps);  // 1 - E_spec(wo)
  const float cosH = openpbrCosineToHalfVector(wo, h);
  vec3 F = vec3(openpbrFresnel(cosH, eps)), passed = vec3(loss);
  if (openpbrDispersive(dispersionScale)) {  // each channel's Fresnel term at its own index, as its refraction's
    const vec3 etas = openpbrDispersedEtas(specularIor, dispersionScale, abbeNumber);
    [[dont_unroll]] for (int c = 0; c < 3; ++c) F[c] = openpbrFresnel(cosH, openpbrSpecularEps(specularWeight, etas[c], C, coatIor));
  }
  const vec3 b = openpbrF82B(rho, specularColor);
  vec3 metalF = openpbrF82(rho, b, cosH);
  // The thin film (reference: openpbr.cpp), compiled only where a scene has one: over the dielectric at wo.H and at
  // its albedo's 3 x 3 quadrature points, then over the metal at wo.H, a channel at a time (its index differs per
  // channel), in one loop with one call of the film (thin_film.glsl says why).
  const float W = featureEnabled(kOpenpbrFeatureThinFilm) ? thinFilmWeight : 0.0;
  if (W > 0.0) {
    const float thicknessNm = 1000.0 * thinFilmThickness, eta = (1.0 + eps) / (1.0 - eps);
    const bool dielectricFilm = M < 1.0 && eps < 0.9999;
    vec3 filmF = F, filmAlbedo = vec3(0.0), metalFilm = metalF;
    float bareAlbedo = 0.0;
    [[dont_unroll]] for (uint point = 0u; point < 13u; ++point) {  // 0: wo.H; 1-9: the quadrature; 10-12: the metal
      if ((point < 10u && !dielectricFilm) || (point >= 10u && !(M > 0.0))) continue;
      float cosTheta = cosH, g = 1.0;
      vec2 index = vec2(eta, 0.0);
      const uint c = point >= 10u ? point - 10u : 0u;
      if (point >= 1u && point <= 9u) {
        const vec2 u = (vec2(float((point - 1u) / 3u), float((point - 1u) % 3u)) + 0.5) / 3.0;
        const vec3 m = sampleGgxVisibleNormal(wo, alpha.x, alpha.y, u);
        const vec3 reflected = reflectAbout(wo, m);
        if (!(reflected.z > 0.0)) continue;
        cosTheta = clamp(dot(wo, m), 0.0, 1.0);
        g = G1_GGX(reflected, alpha.x, alpha.y);
        bareAlbedo += g * openpbrFresnel(cosTheta, eps);
      } else if (point >= 10u) {
        index = metalIndexFromTint(rho[c], specularColor[c]);
      }
      const vec3 film = thinFilmReflectance(cosTheta, thinFilmIor, thicknessNm, index);
      if (point == 0u) {
        filmF = film;
      } else if (point <= 9u) {
        filmAlbedo += g * film;
      } else {
        metalFilm[c] = thinFilmOverMetal(metalF[c], film[c], index, cosH);
      }
    }
    if (dielectricFilm) {
      F = mix(F, filmF, W);
      // E_film = E_spec(wo) + (quadrature with the film - without it) / 9.
      const vec3 eFilm = clamp(vec3(1.0 - loss) + (filmAlbedo - bareAlbedo) / 9.0, 0.0, 1.0);
      passed = max(vec3(1.0) - mix(vec3(1.0 - loss), eFilm, W), vec3(0.0));
    }
    metalF = mix(metalF, metalFilm, W);
  }
  const vec3 dielectric = specularColor * F * openpbrMicrofacet(wi, wo, h, alpha) +
                          passed * eonEval(diffuseAlbedo, diffuseRoughness, wi, wo);
  const vec3 metal = min(specularWeight * metalF, vec3(1.0)) * openpbrMicrofacet(wi, wo, h, alpha) +
                     openpbrMetalMultipleScattering(rho, b, specularWeight, alpha, wi, wo);
  const vec3 substrate = mix(dielectric, metal, M);
  return openpbrFuzzOver(C > 0.0 ? openpbrCoatOver(substrate, wi, wo, C, coatColor, coatRoughness, coatAnisotropy,
                                                   coatIor, coatDarkening, coatFrame, alphaTable, eps, rho,
                                                   diffuseAlbedo, specularColor, specularWeight, specularRoughness, M)
                                 : substrate,
                         wi, wo, fuzzWeight, fuzzColor, fuzzRoughness);
}


float openpbrReflectionPdf(float baseWeight, vec3 baseColor, float metalness, float diffuseRoughness, float specularWeight,
                 vec3 specularColor, float specularRoughness, float specularAnisotropy, float specularIor,
                 float coatWeight, vec3 coatColor, float coatRoughness, float coatAnisotropy, float coatIor,
                 float coatDarkening, float thinFilmWeight, float thinFilmThickness, float thinFilmIor,
                 float fuzzWeight, vec3 fuzzColor, float fuzzRoughness, OpenpbrCoatFrame coatFrame, vec3 wi,
                 vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  coatWeight = openpbrCoat(coatWeight);  // as in openpbrReflection
  fuzzWeight = featureEnabled(kOpenpbrFeatureFuzz) ? fuzzWeight : 0.0;
  const vec3 p = openpbrLobeProbabilities(baseWeight, baseColor, metalness, specularWeight, specularIor, coatWeight,
                                          coatIor, fuzzWeight, fuzzColor);
  precise const vec3 h = wi + wo;
  const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, coatWeight, coatRoughness);
  float specular = (1.0 - p.y - p.z) * ggxReflectionPdf(h, wo, alpha.x, alpha.y);
  if (p.y > 0.0) {
    const vec2 alphaCoat = openpbrAlphas(coatRoughness, coatAnisotropy);
    // In the coat's frame, from wo lifted off the coat's horizon as its sampler does.
    specular += p.y * ggxReflectionPdf(openpbrToCoat(coatFrame, h), liftOffHorizon(openpbrToCoat(coatFrame, wo)),
                                       alphaCoat.x, alphaCoat.y);
  }
  if (p.z > 0.0) specular += p.z * fuzzDensity(wi, wo, fuzzLobe(wo.z, fuzzRoughness));
  return (1.0 - p.x) * cosineHemispherePdf(wi) + p.x * specular;
}

// A direction from the reflection's mixture (zero when it fails); the caller evaluates f and the density.
vec3 openpbrReflectionDirection(float baseWeight, vec3 baseColor, float metalness, float specularWeight,
                                float specularRoughness, float specularAnisotropy, float specularIor, float coatWeight,
                                float coatRoughness, float coatAnisotropy, float coatIor, float fuzzWeight,
                                vec3 fuzzColor, float fuzzRoughness, OpenpbrCoatFrame coatFrame, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return vec3(0.0);
  coatWeight = openpbrCoat(coatWeight);  // as in openpbrReflection
  fuzzWeight = featureEnabled(kOpenpbrFeatureFuzz) ? fuzzWeight : 0.0;
  const vec3 p = openpbrLobeProbabilities(baseWeight, baseColor, metalness, specularWeight, specularIor, coatWeight,
                                          coatIor, fuzzWeight, fuzzColor);
  if (u.x < p.x && u.y >= p.y && u.y < p.y + p.z) {
    // u.y picks the coat, the fuzz or the base, and is stretched back to [0, 1) for the lobe's sampler.
    const vec3 w = liftOffHorizon(wo);  // as openpbrReflectionPdf reads the lobe
    return sampleFuzz(w, fuzzLobe(w.z, fuzzRoughness), vec2(min((u.y - p.y) / p.z, 0.99999994), u.z));
  }
  if (u.x < p.x && u.y < p.y) {  // the coat's lobe, in its frame (openpbrReflectionPdf reads it there)
    const vec2 alpha = openpbrAlphas(coatRoughness, coatAnisotropy);
    const vec3 w = liftOffHorizon(openpbrToCoat(coatFrame, liftOffHorizon(wo)));
    return openpbrFromCoat(coatFrame,
                           reflectAbout(w, sampleGgxVisibleNormal(w, alpha.x, alpha.y, vec2(min(u.y / p.y, 0.99999994), u.z))));
  }
  if (u.x < p.x) {
    const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, coatWeight, coatRoughness);
    const float v = (u.y - p.y - p.z) / (1.0 - p.y - p.z);
    return reflectAbout(wo, sampleGgxVisibleNormal(liftOffHorizon(wo), alpha.x, alpha.y, vec2(min(v, 0.99999994), u.z)));
  }
  return sampleCosineHemisphere(u.yz);
}

// The translucent base (OpenPBR, "Translucent base"), compiled only where a scene has one: T = transmission_weight
// of the dielectric (the metal is opaque) refracts through the dielectric's own GGX interface, index specular_ior
// (parallel layers above bend the light back: only the base's index decides where it goes) and the base's
// roughness, into the object. transmission_depth > 0: a volume whose absorption the path integrator applies
// (openpbrMediumAbsorption); 0: no volume, transmission_color tints the light at the interface on its way in. The
// reflection off the outside keeps its specular term and scales the glossy-diffuse part by 1 - T. What crosses the
// surface also crosses the coat and the fuzz: scaled by what they pass along the outside direction.
// An opaque material (T = 0) is shaded on either side, as every opaque surface: the model is two-sided only for
// its transmission.
float openpbrTransmissionShare(float transmissionWeight, float metalness) {
  return featureEnabled(kOpenpbrFeatureTransmission) ? transmissionWeight * (1.0 - metalness) : 0.0;
}
// The solid's interface with an index per channel: each channel of f is that channel of ggx_dielectric at its own
// index; the sampler picks a channel uniformly and refracts by its index, so the density is the three channels'
// mean (where the lobes part, a sample carries one channel's light, three times over).
vec3 openpbrInterfaceEval(vec2 alpha, vec3 etas, bool dispersive, vec3 tint, vec3 wi, vec3 wo) {
  if (!dispersive) return ggxDielectricEval(alpha.x, alpha.y, etas.g, tint, wi, wo);
  vec3 f;
  [[dont_unroll]] for (int c = 0; c < 3; ++c) f[c] = ggxDielectricEval(alpha.x, alpha.y, etas[c], tint, wi, wo)[c];
  return f;
}
float openpbrInterfacePdf(vec2 alpha, vec3 etas, bool dispersive, vec3 wi, vec3 wo) {
  if (!dispersive) return ggxDielectricPdf(alpha.x, alpha.y, etas.g, vec3(1.0), wi, wo);
  float pdf = 0.0;
  [[dont_unroll]] for (int c = 0; c < 3; ++c) pdf += ggxDielectricPdf(alpha.x, alpha.y, etas[c], vec3(1.0), wi, wo);
  return pdf / 3.0;
}
vec3 openpbrInterfaceDirection(vec2 alpha, vec3 etas, bool dispersive, vec3 wo, vec3 u) {
  float eta = etas.g;
  if (dispersive) {
    const float channel = min(floor(3.0 * u.x), 2.0);
    eta = etas[int(channel)];
    u.x = min(3.0 * u.x - channel, 0.99999994);
  }
  return ggxDielectricSample(alpha.x, alpha.y, eta, vec3(1.0), wo, u).wi;
}

// The share of the sampler's choices that go to the interface's own sampler (reflect or refract by F) when wo is
// outside, against the reflection's mixture (the coat's and fuzz's lobes, the diffuse the rest keeps).
const float kOpenpbrInterfaceShare = 0.75;

// A thin-walled surface (geometry_thin_walled, compiled only where a scene has one) is a shell with the same
// material on both faces and no inside: what the translucent base passes goes straight through, the base's GGX
// lobe mirrored through the surface with (1 - F), and the subsurface becomes a thin translucent sheet that
// scatters the share (1 + g) / 2 of its light through and the rest back (g = subsurface_scatter_anisotropy), both
// diffusely, tinted by subsurface_color.
bool openpbrThinWalled(float thinWalled) { return featureEnabled(kOpenpbrFeatureThinWalled) && thinWalled >= 0.5; }
float openpbrThinThrough(float subsurfaceAnisotropy) { return 0.5 * (1.0 + clamp(subsurfaceAnisotropy, -1.0, 1.0)); }

// The glossy-diffuse base's albedo: base_weight base_color, mixed with the subsurface in its short-radius limit (a
// diffuse lobe of subsurface_color, less the share `through` a thin wall passes), of the share 1 - T that does not
// transmit.
vec3 openpbrDiffuseAlbedo(float baseWeight, vec3 baseColor, float subsurfaceWeight, vec3 subsurfaceColor, float T,
                          float through) {
  return (1.0 - T) * mix(baseWeight * baseColor, (1.0 - through) * subsurfaceColor, subsurfaceWeight);
}

// The probability that the reflection's mixture sends its sample through a thin wall (mirrored): the share of the
// diffuse light that the thin subsurface passes, at most 0.9 so that the reflection keeps a share of the samples (its
// specular lobes are sampled only there when nothing transmits).
float openpbrThinMirrorShare(float metalness, float subsurfaceWeight, float T, float through) {
  return min(through * subsurfaceWeight * (1.0 - T) * (1.0 - metalness), 0.9);
}

// What the coat and the fuzz pass of light crossing them along w (outside): the coat's 1 - E_coat and its absorption
// along one refracted crossing (coat_color is the transmittance there and back at normal incidence), the fuzz's
// 1 - F E_fuzz.
vec3 openpbrLayersPassed(vec3 wBase, float coatWeight, vec3 coatColor, float coatRoughness, float coatAnisotropy,
                         float coatIor, OpenpbrCoatFrame coatFrame, float fuzzWeight, float fuzzRoughness) {
  vec3 passed = vec3(1.0);
  const float C = openpbrCoat(coatWeight);
  if (C > 0.0) {
    const vec3 w = liftOffHorizon(openpbrToCoat(coatFrame, wBase));  // the coat's terms in its frame
    const float epsCoat = (coatIor - 1.0) / (coatIor + 1.0);
    const float loss = openpbrDielectricLoss(w.z, openpbrProjectedAlpha(openpbrAlphas(coatRoughness, coatAnisotropy), w),
                                             epsCoat);
    const float cosT = sqrt(1.0 - (1.0 - w.z * w.z) / (coatIor * coatIor));
    passed *= mix(vec3(1.0), pow(max(coatColor, vec3(0.0)), vec3(0.5 / cosT)) * loss, C);
  }
  const float F = featureEnabled(kOpenpbrFeatureFuzz) ? fuzzWeight : 0.0;
  if (F > 0.0) passed *= 1.0 - F * fuzzLobe(wBase.z, fuzzRoughness).x;
  return passed;
}

// The interior's absorption coefficient per unit length, -ln(transmission_color) / transmission_depth, for the path
// integrator's Beer-Lambert attenuation inside (Beer's law with the colour reached at that depth); 0 without a volume
// (depth 0, or a thin wall). A channel of colour 0 absorbs everything: 1e30 per unit length.
vec3 openpbrMediumAbsorption(float transmissionWeight, float metalness, vec3 transmissionColor,
                             float transmissionDepth, float thinWalled) {
  if (!(openpbrTransmissionShare(transmissionWeight, metalness) > 0.0 && transmissionDepth > 0.0) ||
      openpbrThinWalled(thinWalled)) {
    return vec3(0.0);
  }
  return min(-log(max(transmissionColor, vec3(1e-30))) / transmissionDepth, vec3(1e30));
}

// f through a thin wall, wo above and wi below: the straight-through GGX lobe and the thin subsurface's diffuse
// transmission, under what the coat and the fuzz pass along wo.
vec3 openpbrThinTransmission(float metalness, float specularWeight, float specularRoughness, float specularAnisotropy,
                             float specularIor, float coatWeight, vec3 coatColor, float coatRoughness,
                             float coatAnisotropy, float coatIor, float fuzzWeight, float fuzzRoughness, float T,
                             vec3 transmissionColor, float subsurfaceWeight, vec3 subsurfaceColor, float through,
                             OpenpbrCoatFrame coatFrame, vec3 wi, vec3 wo) {
  const float C = openpbrCoat(coatWeight);
  wo = liftOffHorizon(wo);
  const vec3 mirrored = liftOffHorizon(vec3(wi.xy, -wi.z));
  precise const vec3 h = mirrored + wo;
  const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, C, coatRoughness);
  const float eps = openpbrSpecularEps(specularWeight, specularIor, C, coatIor);
  const vec3 straight = T * transmissionColor * (1.0 - openpbrFresnel(openpbrCosineToHalfVector(wo, h), eps)) *
                        openpbrMicrofacet(mirrored, wo, h, alpha);
  const float passed = openpbrDielectricLoss(wo.z, openpbrProjectedAlpha(alpha, wo), eps);  // 1 - E_spec(wo)
  const vec3 diffuse = (1.0 - T) * (1.0 - metalness) * subsurfaceWeight * through * subsurfaceColor * passed * kInvPi;
  return (straight + diffuse) * openpbrLayersPassed(wo, coatWeight, coatColor, coatRoughness, coatAnisotropy, coatIor,
                                                    coatFrame, fuzzWeight, fuzzRoughness);
}

// The density of the thin wall's interface sampler: a visible normal of the base's GGX, reflecting with probability
// F(wo.m) and going straight through (the reflection mirrored) otherwise. wo above.
float openpbrThinInterfacePdf(float specularWeight, float specularRoughness, float specularAnisotropy,
                              float specularIor, float coatWeight, float coatRoughness, float coatIor, vec3 wi,
                              vec3 wo) {
  const float C = openpbrCoat(coatWeight);
  wo = liftOffHorizon(wo);
  const bool through = wi.z < 0.0;
  const vec3 w = liftOffHorizon(vec3(wi.xy, abs(wi.z)));
  precise const vec3 h = w + wo;
  const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, C, coatRoughness);
  const float F = openpbrFresnel(openpbrCosineToHalfVector(wo, h), openpbrSpecularEps(specularWeight, specularIor, C, coatIor));
  return (through ? 1.0 - F : F) * ggxReflectionPdf(h, wo, alpha.x, alpha.y);
}

vec3 openpbrEval(float baseWeight, vec3 baseColor, float metalness, float diffuseRoughness, float specularWeight,
                 vec3 specularColor, float specularRoughness, float specularAnisotropy, float specularIor,
                 float coatWeight, vec3 coatColor, float coatRoughness, float coatAnisotropy, float coatIor,
                 float coatDarkening, float thinFilmWeight, float thinFilmThickness, float thinFilmIor,
                 float fuzzWeight, vec3 fuzzColor, float fuzzRoughness, float transmissionWeight,
                 vec3 transmissionColor, float transmissionDepth, float dispersionScale, float abbeNumber,
                 float subsurfaceWeight, vec3 subsurfaceColor,
                 float subsurfaceAnisotropy, float thinWalled, float coatNormalX, float coatNormalY,
                 float coatTangentAngle, float emissionLuminance, vec3 emissionColor,
                 float geometryOpacity, vec3 wi, vec3 wo) {
  const float T = openpbrTransmissionShare(transmissionWeight, metalness);
  const bool thin = openpbrThinWalled(thinWalled);
  const OpenpbrCoatFrame coatFrame = openpbrCoatFrame(coatNormalX, coatNormalY, coatTangentAngle);
  if (T > 0.0 && !thin && !(wi.z > 0.0 && wo.z > 0.0)) {
    if (!(abs(wi.z) > 0.0 && abs(wo.z) > 0.0)) return vec3(0.0);  // on the surface, or NaN
    const float C = openpbrCoat(coatWeight);
    const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, C, coatRoughness);
    const vec3 tint = transmissionDepth > 0.0 ? vec3(1.0) : transmissionColor;
    vec3 f = T * openpbrInterfaceEval(alpha, openpbrDispersedEtas(specularIor, dispersionScale, abbeNumber),
                                      openpbrDispersive(dispersionScale), tint, wi, wo);
    if (wi.z * wo.z < 0.0) {
      f *= openpbrLayersPassed(liftOffHorizon(wi.z > 0.0 ? wi : wo), coatWeight, coatColor, coatRoughness,
                               coatAnisotropy, coatIor, coatFrame, fuzzWeight, fuzzRoughness);
    }
    return f;
  }
  if ((thin || !(T > 0.0)) && wo.z < 0.0) {  // an opaque surface or a thin wall seen from behind
    wi.z = -wi.z;
    wo.z = -wo.z;
  }
  if (thin && wi.z < 0.0 && wo.z > 0.0) {
    return openpbrThinTransmission(metalness, specularWeight, specularRoughness, specularAnisotropy, specularIor,
                                   coatWeight, coatColor, coatRoughness, coatAnisotropy, coatIor, fuzzWeight,
                                   fuzzRoughness, T, transmissionColor, subsurfaceWeight, subsurfaceColor,
                                   openpbrThinThrough(subsurfaceAnisotropy), coatFrame, wi, wo);
  }
  return openpbrReflection(baseWeight, baseColor, metalness, diffuseRoughness, specularWeight, specularColor,
                           specularRoughness, specularAnisotropy, specularIor, coatWeight, coatColor, coatRoughness,
                           coatAnisotropy, coatIor, coatDarkening, thinFilmWeight, thinFilmThickness, thinFilmIor,
                           fuzzWeight, fuzzColor, fuzzRoughness, dispersionScale, abbeNumber, coatFrame,
                           openpbrDiffuseAlbedo(baseWeight, baseColor, subsurfaceWeight, subsurfaceColor, T,
                                                thin ? openpbrThinThrough(subsurfaceAnisotropy) : 0.0),
                           wi, wo);
}

float openpbrPdf(float baseWeight, vec3 baseColor, float metalness, float diffuseRoughness, float specularWeight,
                 vec3 specularColor, float specularRoughness, float specularAnisotropy, float specularIor,
                 float coatWeight, vec3 coatColor, float coatRoughness, float coatAnisotropy, float coatIor,
                 float coatDarkening, float thinFilmWeight, float thinFilmThickness, float thinFilmIor,
                 float fuzzWeight, vec3 fuzzColor, float fuzzRoughness, float transmissionWeight,
                 vec3 transmissionColor, float transmissionDepth, float dispersionScale, float abbeNumber,
                 float subsurfaceWeight, vec3 subsurfaceColor,
                 float subsurfaceAnisotropy, float thinWalled, float coatNormalX, float coatNormalY,
                 float coatTangentAngle, float emissionLuminance, vec3 emissionColor,
                 float geometryOpacity, vec3 wi, vec3 wo) {
  const float T = openpbrTransmissionShare(transmissionWeight, metalness);
  const bool thin = openpbrThinWalled(thinWalled);
  float interfaceDensity = 0.0, share = 0.0;
  if (T > 0.0 && !thin) {
    if (!(abs(wi.z) > 0.0 && abs(wo.z) > 0.0)) return 0.0;
    const float C = openpbrCoat(coatWeight);
    const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, C, coatRoughness);
    interfaceDensity = openpbrInterfacePdf(alpha, openpbrDispersedEtas(specularIor, dispersionScale, abbeNumber),
                                           openpbrDispersive(dispersionScale), wi, wo);
    share = wo.z > 0.0 ? kOpenpbrInterfaceShare * T : 1.0;
  } else if (wo.z < 0.0) {
    wi.z = -wi.z;
    wo.z = -wo.z;
  }
  if (thin && T > 0.0) {
    if (!(abs(wi.z) > 0.0 && wo.z > 0.0)) return 0.0;
    interfaceDensity = openpbrThinInterfacePdf(specularWeight, specularRoughness, specularAnisotropy, specularIor,
                                               coatWeight, coatRoughness, coatIor, wi, wo);
    share = kOpenpbrInterfaceShare * T;
  }
  if (!(share < 1.0)) return interfaceDensity;
  // The reflection's mixture, a share q of it mirrored through a thin wall.
  const float q =
      openpbrThinMirrorShare(metalness, subsurfaceWeight, T, thin ? openpbrThinThrough(subsurfaceAnisotropy) : 0.0);
  const bool through = wi.z < 0.0;
  if (through && !(q > 0.0)) return share * interfaceDensity;
  const float mixture = openpbrReflectionPdf(baseWeight, baseColor, metalness, diffuseRoughness, specularWeight,
                                             specularColor, specularRoughness, specularAnisotropy, specularIor,
                                             coatWeight, coatColor, coatRoughness, coatAnisotropy, coatIor,
                                             coatDarkening, thinFilmWeight, thinFilmThickness, thinFilmIor,
                                             fuzzWeight, fuzzColor, fuzzRoughness,
                                             openpbrCoatFrame(coatNormalX, coatNormalY, coatTangentAngle),
                                             vec3(wi.xy, abs(wi.z)), wo);
  return share * interfaceDensity + (1.0 - share) * (through ? q : 1.0 - q) * mixture;
}

BsdfSample openpbrSample(float baseWeight, vec3 baseColor, float metalness, float diffuseRoughness,
                         float specularWeight, vec3 specularColor, float specularRoughness, float specularAnisotropy,
                         float specularIor, float coatWeight, vec3 coatColor, float coatRoughness,
                         float coatAnisotropy, float coatIor, float coatDarkening, float thinFilmWeight,
                         float thinFilmThickness, float thinFilmIor, float fuzzWeight, vec3 fuzzColor,
                         float fuzzRoughness, float transmissionWeight, vec3 transmissionColor,
                         float transmissionDepth, float dispersionScale, float abbeNumber,
                         float subsurfaceWeight, vec3 subsurfaceColor,
                         float subsurfaceAnisotropy, float thinWalled, float coatNormalX, float coatNormalY,
                         float coatTangentAngle,
                         float emissionLuminance, vec3 emissionColor, float geometryOpacity,
                         vec3 wo, vec3 u) {
  const float T = openpbrTransmissionShare(transmissionWeight, metalness);
  const bool thin = openpbrThinWalled(thinWalled);
  // An opaque surface or a thin wall seen from behind is sampled mirrored to the front, and mirrored back.
  const bool behind = (thin || !(T > 0.0)) && wo.z < 0.0;
  const vec3 w = behind ? vec3(wo.xy, -wo.z) : wo;
  const float share = T > 0.0 ? (w.z > 0.0 ? kOpenpbrInterfaceShare * T : 1.0) : 0.0;
  vec3 wi;
  if (u.x < share) {
    const float C = openpbrCoat(coatWeight);
    const vec2 alpha = openpbrBaseAlphas(specularRoughness, specularAnisotropy, C, coatRoughness);
    const float v = min(u.x / share, 0.99999994);
    if (thin) {
      const vec3 m = sampleGgxVisibleNormal(liftOffHorizon(w), alpha.x, alpha.y, u.yz);
      wi = reflectAbout(w, m);
      if (!(wi.z > 0.0)) return noSample();
      const float F = openpbrFresnel(clamp(dot(w, m), 0.0, 1.0), openpbrSpecularEps(specularWeight, specularIor, C, coatIor));
      if (!(v < F)) wi.z = -wi.z;  // straight through
    } else {
      wi = openpbrInterfaceDirection(alpha, openpbrDispersedEtas(specularIor, dispersionScale, abbeNumber),
                                     openpbrDispersive(dispersionScale), w, vec3(v, u.yz));
    }
  } else {
    const float q =
      openpbrThinMirrorShare(metalness, subsurfaceWeight, T, thin ? openpbrThinThrough(subsurfaceAnisotropy) : 0.0);
    float v = min((u.x - share) / (1.0 - share), 0.99999994);
    const bool mirror = v < q;
    v = mirror ? v / q : (v - q) / (1.0 - q);
    wi = openpbrReflectionDirection(baseWeight, baseColor, metalness, specularWeight, specularRoughness,
                                    specularAnisotropy, specularIor, coatWeight, coatRoughness, coatAnisotropy, coatIor,
                                    fuzzWeight, fuzzColor, fuzzRoughness,
                                    openpbrCoatFrame(coatNormalX, coatNormalY, coatTangentAngle), w,
                                    vec3(min(v, 0.99999994), u.yz));
    if (!(wi.z > 0.0)) return noSample();
    if (mirror) wi.z = -wi.z;
  }
  if (behind) wi.z = -wi.z;
  if (!(abs(wi.z) > 0.0)) return noSample();
  const float pdf = openpbrPdf(baseWeight, baseColor, metalness, diffuseRoughness, specularWeight, specularColor,
                               specularRoughness, specularAnisotropy, specularIor, coatWeight, coatColor, coatRoughness,
                               coatAnisotropy, coatIor, coatDarkening, thinFilmWeight, thinFilmThickness, thinFilmIor,
                               fuzzWeight, fuzzColor, fuzzRoughness, transmissionWeight, transmissionColor,
                               transmissionDepth, dispersionScale, abbeNumber, subsurfaceWeight, subsurfaceColor,
                               subsurfaceAnisotropy, thinWalled, coatNormalX, coatNormalY, coatTangentAngle,
                               emissionLuminance, emissionColor, geometryOpacity, wi, wo);
  if (!(pdf > 0.0)) return noSample();
  return BsdfSample(wi,
                    openpbrEval(baseWeight, baseColor, metalness, diffuseRoughness, specularWeight, specularColor,
                                specularRoughness, specularAnisotropy, specularIor, coatWeight, coatColor,
                                coatRoughness, coatAnisotropy, coatIor, coatDarkening, thinFilmWeight,
                                thinFilmThickness, thinFilmIor, fuzzWeight, fuzzColor, fuzzRoughness,
                                transmissionWeight, transmissionColor, transmissionDepth, dispersionScale,
                                abbeNumber, subsurfaceWeight,
                                subsurfaceColor, subsurfaceAnisotropy, thinWalled, coatNormalX, coatNormalY,
                                coatTangentAngle, emissionLuminance, emissionColor,
                                geometryOpacity, wi, wo),
                    pdf);
}

#endif
