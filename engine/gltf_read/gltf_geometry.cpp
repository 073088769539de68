#include "gltf_read/gltf_geometry.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace raylab::gltf {

namespace {

constexpr int kModeTriangles = TINYGLTF_MODE_TRIANGLES;
constexpr int kModeStrip = TINYGLTF_MODE_TRIANGLE_STRIP;
constexpr int kModeFan = TINYGLTF_MODE_TRIANGLE_FAN;
// glTF requires unit normals; writers round, so only a larger error counts as a repair.
constexpr float kUnitTolerance = 1e-3f;
constexpr std::size_t kMaxZeroElements = std::size_t(1) << 24;

std::string componentName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_INT: return "int";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "double";
  }
  return "component type " + std::to_string(componentType);
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
  }
  return "type " + std::to_string(type);
}

// What an attribute accepts (glTF 2.0 § 3.7.2.1) and how messages name it.
struct AccessorUse {
  std::string role;  // "POSITION of mesh 0 'box' primitive 0"
  int type;
  std::vector<int> componentTypes;
  bool integersNormalized;  // integer components must be normalized (TEXCOORD_0)
};

// One component at `p`, normalised integers mapped to [0, 1] as glTF defines.
double readComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double v = *p;
      return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
  }
  return 0.0;  // other types are rejected before reading
}

class AccessorReader {
 public:
  explicit AccessorReader(Document& document) : document_(document), model_(document.model) {}

  // Every element of accessor `index` as `components` doubles each, sparse substitution applied.
  std::vector<double> read(int index, const AccessorUse& use) {
    if (index < 0 || std::size_t(index) >= model_.accessors.size()) {
      document_.fail(use.role + ": accessor " + std::to_string(index) + " does not exist (the file has " +
                     std::to_string(model_.accessors.size()) + ")");
    }
    const tinygltf::Accessor& accessor = model_.accessors[std::size_t(index)];
    const std::string where = describe("accessor", index, accessor.name) + " (" + use.role + ")";
    bool componentOk = false;
    for (int allowed : use.componentTypes) componentOk = componentOk || accessor.componentType == allowed;
    if (accessor.type != use.type || !componentOk) {
      std::string allowed;
      for (int type : use.componentTypes) allowed += (allowed.empty() ? "" : " or ") + componentName(type);
      document_.fail(where + ": is " + typeName(accessor.type) + " of " + componentName(accessor.componentType) +
                     "; expected " + typeName(use.type) + " of " + allowed);
    }
    const bool isInteger = accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (use.integersNormalized && isInteger && !accessor.normalized) {
      document_.fail(where + ": integer components must be normalized (\"normalized\": true)");
    }
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    const std::size_t count = accessor.count;
    std::vector<double> values;
    if (accessor.bufferView >= 0) {
      values = readElements(accessor.bufferView, accessor.byteOffset, count, accessor.componentType, components,
                            componentSize, accessor.normalized, where);
    } else if (accessor.sparse.isSparse) {
      // Without a buffer view the elements are zeros, to be replaced by sparse values (glTF 2.0 § 3.6.2.3);
      // no buffer bounds the count then, so a sane limit does.
      if (count > kMaxZeroElements) {
        document_.fail(where + ": " + std::to_string(count) + " elements without a buffer view is more than " +
                       std::to_string(kMaxZeroElements));
      }
      values.assign(count * std::size_t(components), 0.0);
    } else {
      document_.fail(where + ": has neither a buffer view nor sparse values");
    }
    if (accessor.sparse.isSparse) applySparse(accessor, components, componentSize, where, values);
    return values;
  }

 private:
  // Reads `count` elements starting `byteOffset` bytes into buffer view `viewIndex`, after checking that they
  // lie inside the view and the view inside its buffer (before allocating: the count comes from the file).
  std::vector<double> readElements(int viewIndex, std::size_t byteOffset, std::size_t count, int componentType,
                                   int components, int componentSize, bool normalized, const std::string& where) {
    if (count == 0) return {};
    const tinygltf::BufferView& view = bufferView(viewIndex, where);
    const std::string viewName = describe("buffer view", viewIndex, view.name);
    const std::uint64_t elementSize = std::uint64_t(components) * std::uint64_t(componentSize);
    const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize) {
      document_.fail(where + ": " + viewName + " has byteStride " + std::to_string(view.byteStride) +
                     ", less than the " + std::to_string(elementSize) + "-byte element");
    }
    const std::uint64_t needed = std::uint64_t(byteOffset) + stride * (count - 1) + elementSize;
    if (needed > view.byteLength) {
      document_.fail(where + ": " + std::to_string(count) + " elements of " + std::to_string(elementSize) +
                     " bytes (stride " + std::to_string(stride) + ", offset " + std::to_string(byteOffset) +
                     ") need " + std::to_string(needed) + " bytes, but " + viewName + " has " +
                     std::to_string(view.byteLength));
    }
    const unsigned char* base = viewData(view, viewIndex, where) + byteOffset;
    std::vector<double> out(count * std::size_t(components));
    for (std::size_t e = 0; e < count; ++e) {
      const unsigned char* element = base + e * stride;
      for (int c = 0; c < components; ++c) {
        out[e * std::size_t(components) + std::size_t(c)] =
            readComponent(element + c * componentSize, componentType, normalized);
      }
    }
    return out;
  }

  const tinygltf::BufferView& bufferView(int viewIndex, const std::string& where) {
    if (viewIndex < 0 || std::size_t(viewIndex) >= model_.bufferViews.size()) {
      document_.fail(where + ": buffer view " + std::to_string(viewIndex) + " does not exist (the file has " +
                     std::to_string(model_.bufferViews.size()) + ")");
    }
    return model_.bufferViews[std::size_t(viewIndex)];
  }

  const unsigned char* viewData(const tinygltf::BufferView& view, int viewIndex, const std::string& where) {
    const std::string viewName = describe("buffer view", viewIndex, view.name);
    if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size()) {
      document_.fail(where + ": " + viewName + " refers to buffer " + std::to_string(view.buffer) +
                     ", which does not exist");
    }
    const tinygltf::Buffer& buffer = model_.buffers[std::size_t(view.buffer)];
    if (std::uint64_t(view.byteOffset) + view.byteLength > buffer.data.size()) {
      document_.fail(where + ": " + viewName + " (bytes " + std::to_string(view.byteOffset) + " to " +
                     std::to_string(view.byteOffset + view.byteLength) + ") runs past the end of " +
                     describe("buffer", view.buffer, buffer.name) + " (" + std::to_string(buffer.data.size()) +
                     " bytes)");
    }
    return buffer.data.data() + view.byteOffset;
  }

  void applySparse(const tinygltf::Accessor& accessor, int components, int componentSize, const std::string& where,
                   std::vector<double>& values) {
    const auto& sparse = accessor.sparse;
    const std::string sparseWhere = where + " sparse";
    if (sparse.count < 0 || std::size_t(sparse.count) > accessor.count) {
      document_.fail(sparseWhere + ": count " + std::to_string(sparse.count) + " exceeds the accessor's " +
                     std::to_string(accessor.count) + " elements");
    }
    const int indexType = sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      document_.fail(sparseWhere + " indices: are " + componentName(indexType) +
                     "; expected unsigned byte, unsigned short or unsigned int");
    }
    const std::size_t count = std::size_t(sparse.count);
    const std::vector<double> indices =
        readElements(sparse.indices.bufferView, std::size_t(sparse.indices.byteOffset), count, indexType, 1,
                     tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(indexType)), false,
                     sparseWhere + " indices");
    const std::vector<double> replacements =
        readElements(sparse.values.bufferView, std::size_t(sparse.values.byteOffset), count, accessor.componentType,
                     components, componentSize, accessor.normalized, sparseWhere + " values");
    for (std::size_t i = 0; i < count; ++i) {
      const double target = indices[i];
      if (target >= double(accessor.count)) {
        document_.fail(sparseWhere + " indices: index " + std::to_string(std::uint64_t(target)) +
                       " is out of range (" + std::to_string(accessor.count) + " elements)");
      }
      for (int c = 0; c < components; ++c) {
        values[std::size_t(target) * std::size_t(components) + std::size_t(c)] =
            replacements[i * std::size_t(components) + std::size_t(c)];
      }
    }
  }

  Document& document_;
  const tinygltf::Model& model_;
};

bool isFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string format(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", v.x, v.y, v.z);
  return text;
}

std::vector<glm::vec3> toVec3(const std::vector<double>& values) {
  std::vector<glm::vec3> out(values.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = glm::vec3(float(values[3 * i]), float(values[3 * i + 1]), float(values[3 * i + 2]));
  }
  return out;
}

// Triangle lists from lists, strips and fans (glTF 2.0 § 3.7.2.1), keeping strips' alternating winding
// consistent. Strips and fans join their parts with degenerate triangles, which are dropped here; a list's
// degenerate triangles are a defect, dropped (and reported) by dropZeroArea.
std::vector<std::uint32_t> triangulate(const std::vector<std::uint32_t>& vertices, int mode, Document& document,
                                       const std::string& where) {
  const std::size_t n = vertices.size();
  if (mode == kModeTriangles) {
    if (n % 3 != 0) {
      document.fail(where + ": a triangle list of " + std::to_string(n) + " vertices (not a multiple of 3)");
    }
    return vertices;
  }
  std::vector<std::uint32_t> triangles;
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c) return;
    triangles.insert(triangles.end(), {a, b, c});
  };
  if (mode == kModeStrip) {
    for (std::size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0) add(vertices[i], vertices[i + 1], vertices[i + 2]);
      else add(vertices[i + 1], vertices[i], vertices[i + 2]);
    }
  } else {
    for (std::size_t i = 1; i + 1 < n; ++i) add(vertices[0], vertices[i], vertices[i + 1]);
  }
  return triangles;
}

// Drops triangles of zero area: the kernel's geometric normal would be normalize(0), a NaN.
std::size_t dropZeroArea(Mesh& mesh) {
  std::vector<std::uint32_t> kept;
  kept.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const glm::vec3 cross = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    if (glm::dot(cross, cross) > 0.0f) kept.insert(kept.end(), {a, b, c});
  }
  const std::size_t dropped = (mesh.indices.size() - kept.size()) / 3;
  mesh.indices = std::move(kept);
  return dropped;
}

// Normalises normals and replaces zero or non-finite ones by the area-weighted mean of the normals of the
// triangles around them. A vertex no triangle uses gets any unit normal (it is never interpolated); if the
// faces around a used vertex cancel out, the mesh falls back to geometric (flat) normals.
void repairNormals(Mesh& mesh, Document& document, const std::string& where) {
  std::vector<bool> bad(mesh.normals.size(), false);
  std::size_t badCount = 0;
  std::size_t rescaled = 0;
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    glm::vec3& n = mesh.normals[i];
    const float length = isFinite(n) ? glm::length(n) : 0.0f;
    if (!(length > 0.0f) || !std::isfinite(length)) {
      bad[i] = true;
      ++badCount;
      continue;
    }
    if (std::abs(length - 1.0f) > kUnitTolerance) ++rescaled;
    n /= length;
  }
  if (badCount == 0 && rescaled == 0) return;

  bool dropped = false;
  if (badCount > 0) {
    std::vector<glm::vec3> faceSum(mesh.normals.size(), glm::vec3(0.0f));
    std::vector<bool> used(mesh.normals.size(), false);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
      const glm::vec3 area = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
      for (std::uint32_t v : {a, b, c}) {
        faceSum[v] += area;
        used[v] = true;
      }
    }
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
      if (!bad[i]) continue;
      const float length = glm::length(faceSum[i]);
      if (!used[i]) {
        mesh.normals[i] = glm::vec3(0.0f, 0.0f, 1.0f);
      } else if (length > 0.0f && std::isfinite(length)) {
        mesh.normals[i] = faceSum[i] / length;
      } else {
        dropped = true;
      }
    }
    if (dropped) mesh.normals.clear();
  }
  std::string what;
  if (badCount > 0) {
    what = std::to_string(badCount) + (dropped ? " zero or non-finite normals (their faces cancel out: the mesh "
                                                 "uses flat geometric normals)"
                                               : " zero or non-finite normals (replaced by their faces' mean normal)");
  }
  if (rescaled > 0) what += (what.empty() ? "" : " and ") + std::to_string(rescaled) + " non-unit normals (normalised)";
  document.warnOnce("normals", where + ": repaired " + what + "; later repairs in this file are not reported");
}

}  // namespace

std::vector<PrimitiveMesh> convertMesh(Document& document, int meshIndex) {
  const tinygltf::Mesh& gltfMesh = document.model.meshes[std::size_t(meshIndex)];
  const std::string meshName = describe("mesh", meshIndex, gltfMesh.name);
  AccessorReader reader(document);
  std::vector<PrimitiveMesh> out;
  if (!gltfMesh.weights.empty()) document.ignore("morph targets");

  for (std::size_t p = 0; p < gltfMesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = gltfMesh.primitives[p];
    const std::string where = meshName + " primitive " + std::to_string(p);
    if (!primitive.targets.empty()) document.ignore("morph targets");
    if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP) {
      document.ignore("points and lines (primitive modes 0 to 3)");
      continue;
    }
    if (primitive.mode != kModeTriangles && primitive.mode != kModeStrip && primitive.mode != kModeFan) {
      document.fail(where + ": mode " + std::to_string(primitive.mode) + " is not a glTF primitive mode (0 to 6)");
    }
    if (primitive.material >= 0 && std::size_t(primitive.material) >= document.model.materials.size()) {
      document.fail(where + ": material " + std::to_string(primitive.material) + " does not exist (the file has " +
                    std::to_string(document.model.materials.size()) + ")");
    }
    if (primitive.attributes.count("COLOR_0") != 0) document.ignore("vertex colours (COLOR_0)");

    const auto attribute = [&](const char* name) {
      const auto it = primitive.attributes.find(name);
      return it == primitive.attributes.end() ? -1 : it->second;
    };
    const int positionAccessor = attribute("POSITION");
    if (positionAccessor < 0) document.fail(where + ": has no POSITION attribute");

    PrimitiveMesh converted;
    converted.material = primitive.material;
    Mesh& mesh = converted.mesh;
    mesh.name = gltfMesh.name.empty() ? "mesh " + std::to_string(meshIndex) : gltfMesh.name;
    if (gltfMesh.primitives.size() > 1) mesh.name += " primitive " + std::to_string(p);

    const AccessorUse positionUse{"POSITION of " + where, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false};
    mesh.positions = toVec3(reader.read(positionAccessor, positionUse));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      if (!isFinite(mesh.positions[i])) {
        document.fail("accessor " + std::to_string(positionAccessor) + " (" + positionUse.role + "): position " +
                      std::to_string(i) + " is not finite " + format(mesh.positions[i]));
      }
    }
    const std::size_t vertexCount = mesh.positions.size();
    if (vertexCount > UINT32_MAX) document.fail(where + ": more than 2^32 vertices");

    const auto expectCount = [&](std::size_t count, const char* name) {
      if (count != vertexCount) {
        document.fail(where + ": " + name + " has " + std::to_string(count) + " elements but POSITION has " +
                      std::to_string(vertexCount));
      }
    };
    if (const int normalAccessor = attribute("NORMAL"); normalAccessor >= 0) {
      mesh.normals = toVec3(reader.read(
          normalAccessor, {"NORMAL of " + where, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false}));
      expectCount(mesh.normals.size(), "NORMAL");
    }
    const auto readUvs = [&](const char* name) {
      std::vector<glm::vec2> out;
      const int uvAccessor = attribute(name);
      if (uvAccessor < 0) return out;
      const AccessorUse uvUse{std::string(name) + " of " + where,
                              TINYGLTF_TYPE_VEC2,
                              {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                              true};
      const std::vector<double> uvs = reader.read(uvAccessor, uvUse);
      out.resize(uvs.size() / 2);
      for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = glm::vec2(float(uvs[2 * i]), float(uvs[2 * i + 1]));
        if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y)) {
          document.fail("accessor " + std::to_string(uvAccessor) + " (" + uvUse.role + "): texture coordinate " +
                        std::to_string(i) + " is not finite");
        }
      }
      expectCount(out.size(), name);
      return out;
    };
    mesh.uvs = readUvs("TEXCOORD_0");
    mesh.uvs1 = readUvs("TEXCOORD_1");
    if (const int tangentAccessor = attribute("TANGENT"); tangentAccessor >= 0) {
      const AccessorUse tangentUse{"TANGENT of " + where, TINYGLTF_TYPE_VEC4, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false};
      const std::vector<double> values = reader.read(tangentAccessor, tangentUse);
      mesh.tangents.resize(values.size() / 4);
      for (std::size_t i = 0; i < mesh.tangents.size(); ++i) {
        const glm::dvec4 t(values[4 * i], values[4 * i + 1], values[4 * i + 2], values[4 * i + 3]);
        if (!std::isfinite(t.x + t.y + t.z + t.w)) {
          document.fail("accessor " + std::to_string(tangentAccessor) + " (" + tangentUse.role + "): tangent " +
                        std::to_string(i) + " is not finite");
        }
        // w is +1 or -1 (glTF 3.7.2.1); its sign is what the bitangent needs.
        mesh.tangents[i] = glm::vec4(glm::vec3(t), t.w < 0.0 ? -1.0f : 1.0f);
      }
      expectCount(mesh.tangents.size(), "TANGENT");
    }

    std::vector<std::uint32_t> vertices;
    if (primitive.indices >= 0) {
      const AccessorUse indexUse{"indices of " + where,
                                 TINYGLTF_TYPE_SCALAR,
                                 {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                 false};
      const std::vector<double> indices = reader.read(primitive.indices, indexUse);
      vertices.resize(indices.size());
      for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= double(vertexCount)) {
          document.fail("accessor " + std::to_string(primitive.indices) + " (" + indexUse.role + "): index " +
                        std::to_string(std::uint64_t(indices[i])) + " at position " + std::to_string(i) +
                        " is out of range (" + std::to_string(vertexCount) + " vertices)");
        }
        vertices[i] = std::uint32_t(indices[i]);
      }
    } else {
      vertices.resize(vertexCount);
      for (std::size_t i = 0; i < vertexCount; ++i) vertices[i] = std::uint32_t(i);
    }
    mesh.indices = triangulate(vertices, primitive.mode, document, where);
    if (const std::size_t dropped = dropZeroArea(mesh); dropped > 0) {
      document.warnOnce("degenerate", where + ": dropped " + std::to_string(dropped) +
                                          " triangles of zero area; later ones in this file are not reported");
    }
    if (!mesh.normals.empty()) repairNormals(mesh, document, where);
    if (!mesh.indices.empty()) out.push_back(std::move(converted));
  }
  return out;
}

}  // namespace raylab::gltf
