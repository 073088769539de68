// The surface at a committed hit, reconstructed from the primitive rather than from origin + t * direction,
// so that the robust ray offset (common/ray_offset.glsl) starts from an accurate point.
#ifndef RAYLAB_KERNEL_SURFACE_GLSL
#define RAYLAB_KERNEL_SURFACE_GLSL

#include "common/frame.glsl"
#include "kernel/payload.glsl"

struct Surface {
  vec3 position;         // world space
  vec3 geometricNormal;  // world space, unit, outward (counter-clockwise winding; outside of a sphere)
  vec3 shadingNormal;    // world space, unit, on the same side as geometricNormal
  vec3 tangent;          // world space; a hint for the shading frame (may be zero)
  vec4 normalTangent;    // a normal map's tangent (world space; xyz zero: none) and the bitangent's sign (w; without
                         // a mesh's tangents, the UV parameterisation's)
  vec2 uv;               // TEXCOORD_0
  vec2 uv1;              // TEXCOORD_1
  bool normalMapped;     // shadingNormal comes from a normal map (hit_common.glsl, applyNormalMap)
  vec3 coatNormal;       // world space, unit: the coat's own normal map's (applyTextures); zero: none
  uint material;
  bool frontFace;        // the ray arrived from the side geometricNormal points to
};

vec3 transformPoint(mat4x3 m, vec3 p) { return m * vec4(p, 1.0); }
vec3 transformVector(mat4x3 m, vec3 v) { return mat3(m) * v; }
// Normals transform with the inverse transpose of the object-to-world matrix.
vec3 transformNormal(mat4x3 worldToObject, vec3 n) { return normalize(n * mat3(worldToObject)); }

// A sphere's UVs at its unit normal (object space): longitude around y from +z, and colatitude from +y.
vec2 sphereUv(vec3 normal) {
  return vec2(atan(normal.x, normal.z) * (0.5 / 3.14159265358979) + 0.5, acos(clamp(normal.y, -1.0, 1.0)) / 3.14159265358979);
}

Surface sphereSurface(Hit hit, InstanceRecord instance) {
  const SphereRecord sphere = spheres[instance.firstSphere + hit.primitive];
  // Project the hit back onto the sphere: o + t d carries the error of t, the projection does not.
  const vec3 fromCenter = hit.objectOrigin + hit.t * hit.objectDirection - sphere.center;
  const vec3 normal = normalize(fromCenter);
  const vec3 onSphere = sphere.center + sphere.radius * normal;

  Surface s;
  s.position = transformPoint(hit.objectToWorld, onSphere);
  s.geometricNormal = transformNormal(hit.worldToObject, normal);
  s.shadingNormal = s.geometricNormal;
  // Azimuthal direction around the sphere's y axis, so anisotropic lobes run along "latitudes".
  s.tangent = transformVector(hit.objectToWorld, vec3(normal.z, 0.0, -normal.x));
  s.uv = sphereUv(normal);
  s.uv1 = s.uv;
  s.normalTangent = vec4(0.0);  // normal maps need a mesh's tangents
  s.normalMapped = false;
  s.coatNormal = vec3(0.0);
  s.material = sphere.material;
  s.frontFace = dot(hit.objectDirection, normal) < 0.0;
  return s;
}

Surface triangleSurface(Hit hit, InstanceRecord instance) {
  const uint base = instance.firstIndex + 3u * hit.primitive;
  const uint i0 = instance.firstVertex + indices[base];
  const uint i1 = instance.firstVertex + indices[base + 1u];
  const uint i2 = instance.firstVertex + indices[base + 2u];
  const vec3 p0 = positions[i0];
  const vec3 e1 = positions[i1] - p0;
  const vec3 e2 = positions[i2] - p0;
  const vec3 weights = vec3(1.0 - hit.barycentrics.x - hit.barycentrics.y, hit.barycentrics);

  Surface s;
  s.position = transformPoint(hit.objectToWorld, p0 + hit.barycentrics.x * e1 + hit.barycentrics.y * e2);
  const vec3 objectNormal = cross(e1, e2);
  s.geometricNormal = transformNormal(hit.worldToObject, objectNormal);
  s.frontFace = dot(hit.objectDirection, objectNormal) < 0.0;

  s.shadingNormal = s.geometricNormal;
  if ((instance.vertexFlags & kVertexHasNormals) != 0u) {
    const vec3 interpolated = weights.x * normals[i0] + weights.y * normals[i1] + weights.z * normals[i2];
    // Zero-length or reversed vertex normals (broken files) fall back to the geometric normal.
    if (dot(interpolated, interpolated) > 0.0) {
      const vec3 n = transformNormal(hit.worldToObject, interpolated);
      if (dot(n, s.geometricNormal) > 0.0) s.shadingNormal = n;
    }
  }

  s.uv = vec2(0.0);
  s.uv1 = vec2(0.0);
  s.tangent = vec3(0.0);
  s.normalTangent = vec4(0.0);
  s.normalMapped = false;
  s.coatNormal = vec3(0.0);
  if ((instance.vertexFlags & kVertexHasUvs) != 0u) {
    const vec2 uv0 = uvs[i0];
    const vec2 duv1 = uvs[i1] - uv0;
    const vec2 duv2 = uvs[i2] - uv0;
    s.uv = uv0 + hit.barycentrics.x * duv1 + hit.barycentrics.y * duv2;
    // dp/du from the UV parameterisation (pbrt-v4 Triangle::InteractionFromIntersection).
    const float determinant = duv1.x * duv2.y - duv1.y * duv2.x;
    if (abs(determinant) > 1e-20) {
      s.tangent = transformVector(hit.objectToWorld, (duv2.y * e1 - duv1.y * e2) / determinant);
      // Without a mesh's tangents, the bitangent's sign is the parameterisation's: +1 where cross(n, dp/du) runs
      // along dp/dv (what a generated tangent's w would say; the anisotropy's direction turns towards it).
      const vec3 dpdv = transformVector(hit.objectToWorld, (duv1.x * e2 - duv2.x * e1) / determinant);
      s.normalTangent.w = dot(cross(s.shadingNormal, s.tangent), dpdv) < 0.0 ? -1.0 : 1.0;
    }
  }
  if ((instance.vertexFlags & kVertexHasUvs1) != 0u) {
    s.uv1 = weights.x * uvs1[i0] + weights.y * uvs1[i1] + weights.z * uvs1[i2];
  }
  if ((instance.vertexFlags & kVertexHasTangents) != 0u) {
    // glTF 3.7.2.1: the bitangent is cross(normal, tangent.xyz) * tangent.w, w the same at every vertex of a
    // triangle. A mirroring transform (negative determinant) flips the handedness in world space.
    const vec3 t = weights.x * tangents[i0].xyz + weights.y * tangents[i1].xyz + weights.z * tangents[i2].xyz;
    const float mirror = determinant(mat3(hit.objectToWorld)) < 0.0 ? -1.0 : 1.0;
    s.normalTangent = vec4(transformVector(hit.objectToWorld, t), tangents[i0].w * mirror);
  }
  s.material = instance.material;
  return s;
}

// TEXCOORD_0 and TEXCOORD_1 of triangle `primitive` of a mesh instance at barycentrics b (of its second and third
// vertex); zero where the mesh has none.
void triangleUvsAt(InstanceRecord instance, uint primitive, vec2 b, out vec2 uv0, out vec2 uv1) {
  const uint base = instance.firstIndex + 3u * primitive;
  const uint i0 = instance.firstVertex + indices[base];
  const uint i1 = instance.firstVertex + indices[base + 1u];
  const uint i2 = instance.firstVertex + indices[base + 2u];
  const vec3 weights = vec3(1.0 - b.x - b.y, b);
  uv0 = vec2(0.0);
  uv1 = vec2(0.0);
  if ((instance.vertexFlags & kVertexHasUvs) != 0u) uv0 = weights.x * uvs[i0] + weights.y * uvs[i1] + weights.z * uvs[i2];
  if ((instance.vertexFlags & kVertexHasUvs1) != 0u) {
    uv1 = weights.x * uvs1[i0] + weights.y * uvs1[i1] + weights.z * uvs1[i2];
  }
}

Surface surfaceAt(Hit hit) {
  const InstanceRecord instance = instances[hit.instance];
  return instance.geometryKind == kGeometrySpheres ? sphereSurface(hit, instance) : triangleSurface(hit, instance);
}

#endif
