// The JSON types of the glTF 2.0 properties raylab reads, checked before tinygltf parses the file: tinygltf
// 2.7 silently skips a property of the wrong type ("primitives": {} loads as a mesh without primitives), which
// would turn a broken file into a quietly wrong picture. Unknown properties are allowed, as glTF allows them.
#include <cstdint>
#include <string>
#include <vector>

#include "gltf_read/gltf_document.h"
#include "util/error.h"

namespace raylab::gltf {

namespace {

using nlohmann::json;

enum class Type { kObject, kArray, kString, kNumber, kIndex, kBool, kIndexMap };

struct Shape;

struct Property {
  std::string name;
  Type type;
  const Shape* shape = nullptr;  // kObject: its properties; kArray of kObject: each element's
  Type element = Type::kObject;  // kArray: the type of every element
  std::size_t length = 0;        // kArray: the exact length; 0 for any
  bool required = false;
};

struct Shape {
  std::vector<Property> properties;
  std::vector<Property> extensions;  // the extensions raylab reads, checked like properties
};

Property index(std::string name) { return {std::move(name), Type::kIndex}; }
Property number(std::string name) { return {std::move(name), Type::kNumber}; }
Property string(std::string name) { return {std::move(name), Type::kString}; }
Property boolean(std::string name) { return {std::move(name), Type::kBool}; }
Property object(std::string name, const Shape& shape) { return {std::move(name), Type::kObject, &shape}; }
Property indexMap(std::string name) { return {std::move(name), Type::kIndexMap}; }
Property objects(std::string name, const Shape& shape) {
  return {std::move(name), Type::kArray, &shape, Type::kObject};
}
Property numbers(std::string name, std::size_t length = 0) {
  return {std::move(name), Type::kArray, nullptr, Type::kNumber, length};
}
Property indices(std::string name) { return {std::move(name), Type::kArray, nullptr, Type::kIndex}; }
Property strings(std::string name) { return {std::move(name), Type::kArray, nullptr, Type::kString}; }
Property indexMaps(std::string name) { return {std::move(name), Type::kArray, nullptr, Type::kIndexMap}; }
Property required(Property property) {
  property.required = true;
  return property;
}

const Shape kAnyObject{};
const Shape kTextureTransform{{numbers("offset", 2), number("rotation"), numbers("scale", 2), index("texCoord")}};
const Shape kTextureInfo{{required(index("index")), index("texCoord")},
                         {object("KHR_texture_transform", kTextureTransform)}};
const Shape kNormalTextureInfo{{required(index("index")), index("texCoord"), number("scale")},
                               {object("KHR_texture_transform", kTextureTransform)}};
const Shape kOcclusionTextureInfo{{required(index("index")), index("texCoord"), number("strength")},
                                  {object("KHR_texture_transform", kTextureTransform)}};
const Shape kPbr{{numbers("baseColorFactor", 4), object("baseColorTexture", kTextureInfo), number("metallicFactor"),
                  number("roughnessFactor"), object("metallicRoughnessTexture", kTextureInfo)}};
const Shape kIor{{number("ior")}};
const Shape kEmissiveStrength{{number("emissiveStrength")}};
const Shape kTransmission{{number("transmissionFactor"), object("transmissionTexture", kTextureInfo)}};
const Shape kSpecular{{number("specularFactor"), object("specularTexture", kTextureInfo), numbers("specularColorFactor", 3),
                       object("specularColorTexture", kTextureInfo)}};
const Shape kClearcoat{{number("clearcoatFactor"), object("clearcoatTexture", kTextureInfo), number("clearcoatRoughnessFactor"),
                        object("clearcoatRoughnessTexture", kTextureInfo),
                        object("clearcoatNormalTexture", kNormalTextureInfo)}};
const Shape kIridescence{{number("iridescenceFactor"), object("iridescenceTexture", kTextureInfo),
                          number("iridescenceIor"), number("iridescenceThicknessMinimum"),
                          number("iridescenceThicknessMaximum"), object("iridescenceThicknessTexture", kTextureInfo)}};
const Shape kSheen{{numbers("sheenColorFactor", 3), object("sheenColorTexture", kTextureInfo),
                    number("sheenRoughnessFactor"), object("sheenRoughnessTexture", kTextureInfo)}};
const Shape kVolume{{number("thicknessFactor"), object("thicknessTexture", kTextureInfo), number("attenuationDistance"),
                     numbers("attenuationColor", 3)}};
const Shape kCoat{{number("coatFactor"), object("coatTexture", kTextureInfo), number("coatRoughnessFactor"),
                   object("coatRoughnessTexture", kTextureInfo), object("coatNormalTexture", kNormalTextureInfo),
                   number("coatIor"), numbers("coatColorFactor", 3), object("coatColorTexture", kTextureInfo),
                   number("coatDarkeningFactor"), number("coatAnisotropyStrength"), number("coatAnisotropyRotation"),
                   object("coatAnisotropyTexture", kTextureInfo)}};
const Shape kFuzz{{number("fuzzFactor"), object("fuzzTexture", kTextureInfo), numbers("fuzzColorFactor", 3),
                   object("fuzzColorTexture", kTextureInfo), number("fuzzRoughnessFactor"),
                   object("fuzzRoughnessTexture", kTextureInfo)}};
const Shape kDiffuseRoughness{{number("diffuseRoughnessFactor"), object("diffuseRoughnessTexture", kTextureInfo)}};
const Shape kDiffuseTransmission{{number("diffuseTransmissionFactor"), object("diffuseTransmissionTexture", kTextureInfo),
                                  numbers("diffuseTransmissionColorFactor", 3),
                                  object("diffuseTransmissionColorTexture", kTextureInfo)}};
const Shape kAnisotropy{{number("anisotropyStrength"), number("anisotropyRotation"),
                         object("anisotropyTexture", kTextureInfo)}};
const Shape kDispersion{{number("dispersion")}};
const Shape kMaterial{{string("name"), object("pbrMetallicRoughness", kPbr),
                       object("normalTexture", kNormalTextureInfo), object("occlusionTexture", kOcclusionTextureInfo),
                       object("emissiveTexture", kTextureInfo), numbers("emissiveFactor", 3), string("alphaMode"),
                       number("alphaCutoff"), boolean("doubleSided")},
                      {object("KHR_materials_ior", kIor), object("KHR_materials_emissive_strength", kEmissiveStrength),
                       object("KHR_materials_transmission", kTransmission), object("KHR_materials_specular", kSpecular),
                       object("KHR_materials_clearcoat", kClearcoat),
                       object("KHR_materials_iridescence", kIridescence), object("KHR_materials_sheen", kSheen),
                       object("KHR_materials_volume", kVolume), object("KHR_materials_coat", kCoat),
                       object("KHR_materials_fuzz", kFuzz),
                       object("KHR_materials_diffuse_roughness", kDiffuseRoughness),
                       object("KHR_materials_anisotropy", kAnisotropy),
                       object("KHR_materials_diffuse_transmission", kDiffuseTransmission),
                       object("KHR_materials_dispersion", kDispersion)}};
const Shape kPrimitive{{required(indexMap("attributes")), index("indices"), index("material"), index("mode"),
                        indexMaps("targets")}};
const Shape kMesh{{string("name"), required(objects("primitives", kPrimitive)), numbers("weights")}};
const Shape kNodeLight{{required(index("light"))}};
const Shape kNode{{string("name"), indices("children"), index("camera"), index("mesh"), index("skin"),
                   numbers("matrix", 16), numbers("rotation", 4), numbers("scale", 3), numbers("translation", 3),
                   numbers("weights")},
                  {object("KHR_lights_punctual", kNodeLight)}};
const Shape kScene{{string("name"), indices("nodes")}};
const Shape kSparseIndices{{required(index("bufferView")), index("byteOffset"), required(index("componentType"))}};
const Shape kSparseValues{{required(index("bufferView")), index("byteOffset")}};
const Shape kSparse{{required(index("count")), required(object("indices", kSparseIndices)),
                     required(object("values", kSparseValues))}};
const Shape kAccessor{{index("bufferView"), index("byteOffset"), required(index("componentType")),
                       boolean("normalized"), required(index("count")), required(string("type")), numbers("max"),
                       numbers("min"), object("sparse", kSparse), string("name")}};
const Shape kBufferView{{required(index("buffer")), index("byteOffset"), required(index("byteLength")),
                         index("byteStride"), index("target"), string("name")}};
const Shape kBuffer{{string("uri"), required(index("byteLength")), string("name")}};
const Shape kTexture{{index("sampler"), index("source"), string("name")}};
const Shape kImage{{string("uri"), string("mimeType"), index("bufferView"), string("name")}};
const Shape kSampler{{index("magFilter"), index("minFilter"), index("wrapS"), index("wrapT"), string("name")}};
const Shape kPerspective{{number("aspectRatio"), required(number("yfov")), number("zfar"), required(number("znear"))}};
const Shape kOrthographic{{required(number("xmag")), required(number("ymag")), required(number("zfar")),
                           required(number("znear"))}};
const Shape kCamera{{required(string("type")), object("perspective", kPerspective),
                     object("orthographic", kOrthographic), string("name")}};
const Shape kSpot{{number("innerConeAngle"), number("outerConeAngle")}};
const Shape kLight{{string("name"), numbers("color", 3), number("intensity"), required(string("type")),
                    number("range"), object("spot", kSpot)}};
const Shape kLights{{required(objects("lights", kLight))}};
const Shape kAsset{{required(string("version")), string("minVersion"), string("generator"), string("copyright")}};
const Shape kRoot{{required(object("asset", kAsset)), index("scene"), objects("scenes", kScene),
                   objects("nodes", kNode), objects("meshes", kMesh), objects("accessors", kAccessor),
                   objects("bufferViews", kBufferView), objects("buffers", kBuffer), objects("materials", kMaterial),
                   objects("textures", kTexture), objects("images", kImage), objects("samplers", kSampler),
                   objects("cameras", kCamera),
                   objects("skins", kAnyObject), objects("animations", kAnyObject), strings("extensionsUsed"),
                   strings("extensionsRequired")},
                  {object("KHR_lights_punctual", kLights)}};

// tinygltf keeps indices in int.
constexpr std::int64_t kMaxIndex = INT32_MAX;

bool isIndex(const json& value) {
  if (value.is_number_unsigned()) return value.get<std::uint64_t>() <= std::uint64_t(kMaxIndex);
  return value.is_number_integer() && value.get<std::int64_t>() >= 0 && value.get<std::int64_t>() <= kMaxIndex;
}

bool isIndexMap(const json& value) {
  if (!value.is_object()) return false;
  for (const auto& [key, entry] : value.items()) {
    if (!isIndex(entry)) return false;
  }
  return true;
}

bool hasType(const json& value, Type type) {
  switch (type) {
    case Type::kObject: return value.is_object();
    case Type::kArray: return value.is_array();
    case Type::kString: return value.is_string();
    case Type::kNumber: return value.is_number();
    case Type::kIndex: return isIndex(value);
    case Type::kBool: return value.is_boolean();
    case Type::kIndexMap: return isIndexMap(value);
  }
  return false;
}

std::string expected(Type type) {
  switch (type) {
    case Type::kObject: return "an object";
    case Type::kArray: return "an array";
    case Type::kString: return "a string";
    case Type::kNumber: return "a number";
    case Type::kIndex: return "a non-negative integer";
    case Type::kBool: return "true or false";
    case Type::kIndexMap: return "an object whose values are non-negative integers";
  }
  return "?";
}

std::string found(const json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  if (value.is_object()) return "an object " + text;
  if (value.is_array()) return "an array " + text;
  if (value.is_string()) return "the string " + text;
  return text;
}

class Checker {
 public:
  explicit Checker(const std::string& label) : label_(label) {}

  void checkObject(const json& value, const Shape& shape, const std::string& path) const {
    for (const Property& property : shape.properties) {
      const auto it = value.find(property.name);
      if (it == value.end()) {
        if (property.required) fail(path, "the required property '" + property.name + "' is missing");
        continue;
      }
      checkProperty(*it, property, join(path, property.name));
    }
    checkExtensions(value, shape, path);
  }

 private:
  static std::string join(const std::string& path, const std::string& name) {
    return path.empty() ? name : path + "." + name;
  }

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw Error(label_ + ": " + (path.empty() ? "top level" : path) + ": " + message);
  }

  void expect(const json& value, Type type, const std::string& path, const std::string& what) const {
    if (!hasType(value, type)) fail(path, "expected " + what + ", found " + found(value));
  }

  void checkProperty(const json& value, const Property& property, const std::string& path) const {
    if (property.type != Type::kArray) {
      expect(value, property.type, path, expected(property.type));
      if (property.type == Type::kObject) checkObject(value, *property.shape, path);
      return;
    }
    const std::string what = property.length > 0 ? "an array of " + std::to_string(property.length) + " numbers"
                                                  : "an array";
    expect(value, Type::kArray, path, what);
    if (property.length > 0 && value.size() != property.length) {
      fail(path, "expected " + what + ", found " + found(value));
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::string elementPath = path + "[" + std::to_string(i) + "]";
      expect(value[i], property.element, elementPath, expected(property.element));
      if (property.element == Type::kObject && property.shape != nullptr) {
        checkObject(value[i], *property.shape, elementPath);
      }
    }
  }

  // Every extension is an object (glTF 2.0 § 3.12); the ones raylab reads are checked in depth.
  void checkExtensions(const json& value, const Shape& shape, const std::string& path) const {
    const auto it = value.find("extensions");
    if (it == value.end()) return;
    const std::string extensionsPath = join(path, "extensions");
    expect(*it, Type::kObject, extensionsPath, "an object");
    for (const auto& [name, extension] : it->items()) {
      expect(extension, Type::kObject, extensionsPath + "." + name, "an object");
    }
    for (const Property& known : shape.extensions) {
      const auto extension = it->find(known.name);
      if (extension != it->end()) checkProperty(*extension, known, extensionsPath + "." + known.name);
    }
  }

  const std::string& label_;
};

}  // namespace

void checkSchema(const json& root, const std::string& label) {
  const Checker checker(label);
  if (!root.is_object()) throw Error(label + ": a glTF file is a JSON object, found " + found(root));
  checker.checkObject(root, kRoot, "");
  const std::string version = root["asset"]["version"].get<std::string>();
  if (version.rfind("2.", 0) != 0) {
    throw Error(label + ": asset.version is \"" + version + "\"; raylab reads glTF 2.0");
  }
}

}  // namespace raylab::gltf
