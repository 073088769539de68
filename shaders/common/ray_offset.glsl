// Where a secondary ray starts: the hit point pushed off the surface by an amount that scales with the
// floating-point spacing of the point itself, never a fixed epsilon.
// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6, 2019.
#ifndef RAYLAB_COMMON_RAY_OFFSET_GLSL
#define RAYLAB_COMMON_RAY_OFFSET_GLSL

// p: the hit point as reconstructed from the primitive (not origin + t * direction);
// n: the geometric normal on the side the new ray leaves from.
vec3 offsetRayOrigin(vec3 p, vec3 n) {
  // Near the origin the float spacing vanishes, so a small fixed offset takes over there.
  const float kOrigin = 1.0 / 32.0;
  const float kFloatScale = 1.0 / 65536.0;
  const float kIntScale = 256.0;

  const ivec3 offsetUlps = ivec3(kIntScale * n);
  const vec3 pUlps = intBitsToFloat(floatBitsToInt(p) + mix(offsetUlps, -offsetUlps, lessThan(p, vec3(0.0))));
  return mix(pUlps, p + kFloatScale * n, lessThan(abs(p), vec3(kOrigin)));
}

#endif
