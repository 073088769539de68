// Closed-form geometry for image tests, in double precision: camera rays as render.comp makes them,
// ray-sphere and ray-plane distances, and the radiance of a Lambert surface under a point light.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "render/renderer.h"
#include "scene/scene.h"
#include "shared/frame.h"

namespace raylab::test {

inline constexpr double kPi = 3.14159265358979323846;

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  // unit
};

// Render settings sampling pixel centres only (no jitter), so each pixel's ray is pixelCenterRay's.
RenderSettings pixelCentres(std::uint32_t width, std::uint32_t height);

// The camera of `scene` for a width x height image, exactly as the renderer sets it up.
gpu::FrameParams frameFor(const Scene& scene, std::uint32_t width, std::uint32_t height);

// The primary ray through the centre of pixel (x, y), computed as render.comp does.
Ray pixelCenterRay(const gpu::FrameParams& params, std::uint32_t x, std::uint32_t y);

// Nearest t >= 0 where the ray meets the sphere; `lineDistance` gets the distance of the ray's line from the
// centre (to skip pixels whose ray grazes the silhouette).
std::optional<double> hitSphere(const Ray& ray, glm::dvec3 center, double radius, double* lineDistance = nullptr);

// rho/pi * I cos(theta) / r^2 at p with normal n; 0 when the light is below the surface. No shadowing.
glm::dvec3 lambertRadiance(glm::dvec3 rho, glm::dvec3 p, glm::dvec3 n, glm::dvec3 lightPosition,
                           glm::dvec3 intensity);

}  // namespace raylab::test
