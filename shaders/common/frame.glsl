// The local shading frame of docs/brdf_contract.md: n the shading normal, t the tangent made orthogonal to n
// (Gram-Schmidt), b = n x t. Local coordinates of w are (w.t, w.b, w.n).
#ifndef RAYLAB_COMMON_FRAME_GLSL
#define RAYLAB_COMMON_FRAME_GLSL

struct ShadingFrame {
  vec3 t;
  vec3 b;
  vec3 n;
};

// Any unit vector orthogonal to unit n, without a singularity: Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017.
vec3 anyTangent(vec3 n) {
  const float sign = n.z >= 0.0 ? 1.0 : -1.0;
  const float a = -1.0 / (sign + n.z);
  const float b = n.x * n.y * a;
  return vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

// `tangentHint` may be zero or parallel to n; then any tangent is used.
ShadingFrame makeShadingFrame(vec3 n, vec3 tangentHint) {
  vec3 t = tangentHint - dot(tangentHint, n) * n;
  const float length2 = dot(t, t);
  // Below ~1e-12 the hint is numerically parallel to n and its direction is noise.
  if (!(length2 > 1e-12)) {
    t = anyTangent(n);
  } else {
    // One Gram-Schmidt step leaves t off orthogonal by about ulp(1) / |t| when the hint leans towards n; a
    // second step removes what the first left ("twice is enough", Giraud et al. 2005). A tilted t and a b
    // shorter than 1 move the local h components that sharp anisotropic lobes (alpha_x = 0.006) amplify.
    t *= inversesqrt(length2);
    t = normalize(t - dot(t, n) * n);
  }
  return ShadingFrame(t, normalize(cross(n, t)), n);
}

vec3 toLocal(ShadingFrame frame, vec3 w) { return vec3(dot(w, frame.t), dot(w, frame.b), dot(w, frame.n)); }
vec3 toWorld(ShadingFrame frame, vec3 v) { return v.x * frame.t + v.y * frame.b + v.z * frame.n; }

#endif
