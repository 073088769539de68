// The build-time albedo tables (generated/ggx_albedo.h, laid out as shared/brdf_tables.h says) as the reference
// reads them: interpolated as the kernels interpolate them, in double.
#pragma once

namespace raylab::reference {

// 1 - E(mu, alpha) of single-scattering GGX with F = 1, bilinear; and 1 - E_avg(alpha), linear.
double ggxAlbedoLoss(double mu, double alpha);
double ggxAverageLoss(double alpha);

// 1 - E_r(mu, alpha, eps), E_r the albedo of a GGX dielectric interface's reflection, index (1 + eps) / (1 - eps),
// trilinear in (sqrt(mu), sqrt(alpha), eps); eps = 1 is GGX with F = 1.
double dielectricReflectionLoss(double mu, double alpha, double eps);
// 1 - E_avg(alpha) of the eps = 1 slice, linear in sqrt(alpha).
double mirrorAverageLoss(double alpha);
// 2 integral F(mu) mu dmu of the Fresnel term of index (1 + eps) / (1 - eps), linear in eps.
double averageFresnel(double eps);

}  // namespace raylab::reference
