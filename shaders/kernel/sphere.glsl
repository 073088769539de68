// Ray-sphere intersection that stays accurate at grazing incidence, for tiny and distant spheres, and from
// inside. Haines, Günther & Akenine-Möller, "Precision Improvements for Ray/Sphere Intersection",
// Ray Tracing Gems, ch. 7, 2019.
#ifndef RAYLAB_KERNEL_SPHERE_GLSL
#define RAYLAB_KERNEL_SPHERE_GLSL

// The two ray parameters where origin + t * direction meets the sphere, nearest first; false on a miss.
// `direction` need not be unit length (object-space rays of scaled instances are not).
bool intersectSphere(vec3 origin, vec3 direction, vec3 center, float radius, out float tNear, out float tFar) {
  const vec3 f = origin - center;
  const float a = dot(direction, direction);
  const float b = dot(f, direction);  // half the textbook b
  // |f|^2 - b^2/a computed as the squared distance from the centre to the ray's line: the textbook
  // b^2 - a c cancels catastrophically when the ray passes far from the centre relative to |f|.
  const vec3 perpendicular = f - (b / a) * direction;
  const float discriminant = a * (radius * radius - dot(perpendicular, perpendicular));
  if (discriminant < 0.0) return false;
  const float c = dot(f, f) - radius * radius;
  // Of the two roots, compute the one without cancellation directly and the other from Vieta's formula.
  const float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant);
  if (q == 0.0) {  // the origin is on the sphere and the ray is tangent: a single touching point
    tNear = tFar = 0.0;
    return true;
  }
  const float t0 = c / q;
  const float t1 = q / a;
  tNear = min(t0, t1);
  tFar = max(t0, t1);
  return true;
}

// The intersection in [tMin, tMax] nearest to the origin, if any.
bool nearestSphereHit(vec3 origin, vec3 direction, vec3 center, float radius, float tMin, float tMax, out float t) {
  float tNear, tFar;
  if (!intersectSphere(origin, direction, center, radius, tNear, tFar)) return false;
  if (tNear >= tMin && tNear <= tMax) {
    t = tNear;
    return true;
  }
  if (tFar >= tMin && tFar <= tMax) {
    t = tFar;
    return true;
  }
  return false;
}

#endif
