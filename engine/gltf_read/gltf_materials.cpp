#include "gltf_read/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

#include <stb_image.h>

#include "brdf_params/material_params.h"
#include "measured/measured_library.h"
#include "image/image.h"
#include "gltf_read/gltf_files.h"
#include "scene/radiance_limits.h"
#include "util/error.h"
#include "util/log.h"

namespace raylab::gltf {

namespace {

using nlohmann::json;

constexpr float kMaxEta = 10.0f;  // the contract's range of eta, [1, 10]
constexpr glm::vec3 kDefaultGrey{0.8f};

// A glTF factor must lie in [low, high]; the error names the material and the property.
float checkedFactor(double value, double low, double high, const std::string& where, const std::string& property) {
  if (!(value >= low && value <= high)) {
    // Exit 2, as a material parameter out of its range is wherever it comes from (brdf_params, setParam).
    throw Error(where + ": " + property + " = " + formatNumber(value) + " is outside [" + formatNumber(low) + ", " +
                formatNumber(high) + "]", kExitUsage);
  }
  return static_cast<float>(value);
}

// L_e = emissiveFactor x KHR_materials_emissive_strength.emissiveStrength (default 1), linear RGB. Checked as the
// float the kernel uses: finite, >= 0, and at most kMaxRadiance (scene/radiance_limits.h).
glm::vec3 emittedRadiance(const tinygltf::Material& material, const json& materialJson, const std::string& where) {
  glm::dvec3 factor(0.0);
  if (material.emissiveFactor.size() == 3) {
    factor = glm::dvec3(material.emissiveFactor[0], material.emissiveFactor[1], material.emissiveFactor[2]);
  }
  double strength = 1.0;
  if (const json* value = findPath(materialJson, {"extensions", "KHR_materials_emissive_strength", "emissiveStrength"})) {
    if (!value->is_number()) throw Error(where + ": emissiveStrength must be a number, found " + quote(*value));
    strength = value->get<double>();
  }
  if (!(strength >= 0.0) || !std::isfinite(strength)) {
    throw Error(where + ": emissiveStrength " + formatNumber(strength) + " must be finite and >= 0");
  }
  for (int c = 0; c < 3; ++c) {
    if (!(factor[c] >= 0.0) || !std::isfinite(factor[c])) {
      throw Error(where + ": emissiveFactor must be three finite numbers >= 0");
    }
  }
  const glm::dvec3 radiance = factor * strength;
  if (std::max({radiance.r, radiance.g, radiance.b}) > double(kMaxRadiance)) {
    throw Error(where + ": emissiveFactor x emissiveStrength = " + formatNumber(std::max({radiance.r, radiance.g, radiance.b})) +
                " is over raylab's limit of 1e+20 (docs/scenes.md, Limits)");
  }
  return glm::vec3(radiance);
}

std::uint32_t wrapMode(int glMode, const std::string& where) {
  switch (glMode) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return gpu::kWrapRepeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return gpu::kWrapClamp;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return gpu::kWrapMirror;
  }
  throw Error(where + ": wrap mode " + std::to_string(glMode) +
              " is not 10497 (repeat), 33071 (clamp) or 33648 (mirror)");
}

// A PNG's size from its IHDR chunk. stb_image refuses to report the size of a PNG past 2^30 bytes of pixels
// ("too large"), which would otherwise read as "not a PNG"; the limits below then name the size instead.
bool pngHeaderSize(const std::vector<unsigned char>& bytes, int& width, int& height) {
  static const unsigned char kSignature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 24 || !std::equal(std::begin(kSignature), std::end(kSignature), bytes.begin()) ||
      std::string(bytes.begin() + 12, bytes.begin() + 16) != "IHDR") {
    return false;
  }
  const auto be32 = [&](std::size_t at) {
    return std::uint32_t(bytes[at]) << 24 | std::uint32_t(bytes[at + 1]) << 16 | std::uint32_t(bytes[at + 2]) << 8 |
           std::uint32_t(bytes[at + 3]);
  };
  width = int(std::min<std::uint32_t>(be32(16), INT32_MAX));
  height = int(std::min<std::uint32_t>(be32(20), INT32_MAX));
  return true;
}

// What an image that is neither PNG nor JPEG is, when stb could decode it anyway ("a BMP image"); empty for a PNG, a
// JPEG, and bytes stb cannot read either (those get stb's reason).
std::string_view otherImageKind(const std::vector<unsigned char>& bytes) {
  const auto starts = [&](std::string_view magic) {
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin(),
                                                      [](char a, unsigned char b) { return static_cast<unsigned char>(a) == b; });
  };
  if (starts("\x89PNG\r\n\x1a\n") || starts("\xff\xd8\xff")) return {};
  if (starts("BM")) return "a BMP image";
  if (starts("GIF8")) return "a GIF image";
  if (starts("#?RADIANCE") || starts("#?RGBE")) return "a Radiance HDR image";
  if (starts("8BPS")) return "a Photoshop image";
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7') return "a PNM image";
  int width = 0, height = 0, channels = 0;
  const int size = static_cast<int>(std::min<std::size_t>(bytes.size(), INT32_MAX));
  return stbi_info_from_memory(bytes.data(), size, &width, &height, &channels) ? "an image of another format (TGA?)"
                                                                               : std::string_view();
}

// stb's reason for refusing an image, or a plain one where it gives none.
std::string decodeFailure() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr && *reason != '\0' ? std::string(reason) : std::string("damaged or unsupported data");
}

// Base-colour textures as RGBA8, each glTF texture converted once however many materials use it.
class TextureConverter {
 public:
  TextureConverter(Document& document, Scene& scene) : document_(document), scene_(scene) {}

  // The scene texture of glTF texture `index`, or -1 when it has no image raylab can use (reported once).
  int convert(int index, const std::string& where) {
    const auto cached = cache_.find(index);
    if (cached != cache_.end()) return cached->second;
    const tinygltf::Model& model = document_.model;
    if (index < 0 || std::size_t(index) >= model.textures.size()) {
      document_.fail(where + ": texture " + std::to_string(index) + " does not exist (the file has " +
                     std::to_string(model.textures.size()) + ")");
    }
    const tinygltf::Texture& gltfTexture = model.textures[std::size_t(index)];
    const std::string textureName = describe("texture", index, gltfTexture.name);
    if (gltfTexture.source < 0) {
      // Sources in extensions (KHR_texture_basisu, EXT_texture_webp) only.
      document_.ignore("textures without a PNG or JPEG source");
      return cache_[index] = -1;
    }
    if (std::size_t(gltfTexture.source) >= model.images.size()) {
      document_.fail(textureName + ": image " + std::to_string(gltfTexture.source) + " does not exist (the file has " +
                     std::to_string(model.images.size()) + ")");
    }
    Texture texture = decoded(gltfTexture.source, where);
    if (gltfTexture.sampler >= 0) {
      if (std::size_t(gltfTexture.sampler) >= model.samplers.size()) {
        document_.fail(textureName + ": sampler " + std::to_string(gltfTexture.sampler) + " does not exist");
      }
      const tinygltf::Sampler& sampler = model.samplers[std::size_t(gltfTexture.sampler)];
      const std::string samplerName = document_.label + ": " + describe("sampler", gltfTexture.sampler, sampler.name);
      texture.wrapS = wrapMode(sampler.wrapS, samplerName + " wrapS");
      texture.wrapT = wrapMode(sampler.wrapT, samplerName + " wrapT");
      // Without mipmaps (textures.glsl) the minification filter has nothing to choose between.
      texture.nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    }
    if (!gltfTexture.name.empty()) texture.name = gltfTexture.name;
    scene_.textures.push_back(std::move(texture));
    return cache_[index] = static_cast<int>(scene_.textures.size() - 1);
  }

 private:
  // Image `imageIndex` decoded, once however many textures use it (each with its own sampler); `use` (the material
  // and the texture use) starts the messages of its errors.
  Texture decoded(int imageIndex, const std::string& use) {
    const auto cached = images_.find(imageIndex);
    if (cached != images_.end()) return cached->second;
    return images_[imageIndex] = decode(document_.model.images[std::size_t(imageIndex)], imageIndex, use);
  }

  // The image's bytes are still encoded (gltf_files.h, keepEncodedImage): its size is read from the header
  // and checked against the limits before anything is decoded. stb converts any channel count to RGBA, 8-bit
  // images to RGBA8 and 16-bit ones to RGBA16, with the colour still sRGB-encoded.
  Texture decode(const tinygltf::Image& image, int imageIndex, const std::string& use) {
    const std::string where = use + ": " + describe("image", imageIndex, image.name) +
                              (!image.uri.empty() && !tinygltf::IsDataURI(image.uri) ? " ('" + image.uri + "')" : "");
    const auto* bytes = image.image.data();
    const int size = static_cast<int>(std::min<std::size_t>(image.image.size(), INT32_MAX));
    int width = 0, height = 0, channels = 0;
    if (image.image.empty()) {
      // tinygltf only warns when an image's file cannot be read, and leaves it empty: the folder rule, which the
      // loader's file callbacks enforce, is named as it is for every other URI.
      const bool external = !image.uri.empty() && !tinygltf::IsDataURI(image.uri);
      if (external) {
        try {
          resolveUri(image.uri, document_.baseDirectory, document_.uriPolicy);
        } catch (const Error& error) {
          document_.fail(where + ": " + error.what());
        }
      }
      document_.fail(where + (external ? ": its file is missing or unreadable (URIs resolve against the scene's folder)"
                                       : ": has no image data"));
    }
    // glTF 2.0 images are PNG or JPEG (3.8.4.1); stb would also decode BMP, GIF, TGA, PPM and HDR, which other
    // viewers refuse.
    if (const std::string_view kind = otherImageKind(image.image); !kind.empty()) {
      document_.fail(where + ": is " + std::string(kind) + ", not a PNG or JPEG image (glTF 2.0's two formats)");
    }
    if (!stbi_info_from_memory(bytes, size, &width, &height, &channels) &&
        !pngHeaderSize(image.image, width, height)) {
      document_.fail(where + ": is not a PNG or JPEG image raylab can read (" + decodeFailure() + ")");
    }
    const std::uint64_t texels = std::uint64_t(width) * std::uint64_t(height);
    if (texels > kMaxImageTexels || width > int(kMaxImageSide) || height > int(kMaxImageSide)) {
      document_.fail(where + ": is " + std::to_string(width) + "x" + std::to_string(height) +
                     ", over raylab's limit of " + std::to_string(kMaxImageTexels) +
                     " texels and " + std::to_string(kMaxImageSide) + " a side (docs/scenes.md, Limits); scale it down");
    }
    // A 16-bit image keeps its precision (a normal map's slopes, a roughness ramp) and takes twice the memory.
    const bool sixteen = stbi_is_16_bit_from_memory(bytes, size) != 0;
    decodedTexels_ += sixteen ? 2 * texels : texels;
    if (decodedTexels_ > kMaxSceneTexels) {
      document_.fail(where + ": the scene's textures together exceed raylab's limit of " +
                     std::to_string(kMaxSceneTexels) + " texels (16-bit images count twice; docs/scenes.md, Limits)");
    }
    Texture texture;
    if (sixteen) {
      stbi_us* pixels = stbi_load_16_from_memory(bytes, size, &width, &height, &channels, 4);
      if (pixels == nullptr) document_.fail(where + ": cannot be decoded (" + decodeFailure() + ")");
      texture.rgba16.assign(pixels, pixels + texels * 4);
      stbi_image_free(pixels);
    } else {
      stbi_uc* pixels = stbi_load_from_memory(bytes, size, &width, &height, &channels, 4);
      if (pixels == nullptr) document_.fail(where + ": cannot be decoded (" + decodeFailure() + ")");
      texture.rgba.assign(pixels, pixels + texels * 4);
      stbi_image_free(pixels);
    }
    texture.name = !image.name.empty() ? image.name
                   : (!image.uri.empty() && !tinygltf::IsDataURI(image.uri)) ? image.uri
                                                                             : "image " + std::to_string(imageIndex);
    texture.width = std::uint32_t(width);
    texture.height = std::uint32_t(height);
    return texture;
  }

  Document& document_;
  Scene& scene_;
  std::map<int, int> cache_;       // glTF texture -> scene texture
  std::map<int, Texture> images_;  // glTF image -> its texels
  std::uint64_t decodedTexels_ = 0;
};

// KHR_texture_transform: uv' = T R S (u, v, 1), the extension's offset, rotation and scale matrices; their
// product's rows are (cos sx, sin sy, ox) and (-sin sx, cos sy, oy).
void applyTextureTransform(gpu::TextureRef& ref, const json& transform, const std::string& where) {
  // Every value and the matrix built from them must be finite as floats (the kernel's).
  const auto finite = [](double v) { return std::abs(v) <= double(std::numeric_limits<float>::max()); };
  const auto pair = [&](const char* key, glm::dvec2 fallback) {
    const json* value = findPath(transform, {key});
    if (value == nullptr) return fallback;
    const glm::dvec2 v((*value)[0].get<double>(), (*value)[1].get<double>());
    if (!finite(v.x) || !finite(v.y)) throw Error(where + ".KHR_texture_transform." + key + " is not finite");
    return v;
  };
  const glm::dvec2 offset = pair("offset", glm::dvec2(0.0));
  const glm::dvec2 scale = pair("scale", glm::dvec2(1.0));
  double rotation = 0.0;
  if (const json* value = findPath(transform, {"rotation"})) rotation = value->get<double>();
  if (!finite(rotation)) throw Error(where + ".KHR_texture_transform.rotation is not finite");
  const double c = std::cos(rotation), s = std::sin(rotation);
  ref.row0 = glm::vec3(float(c * scale.x), float(s * scale.y), float(offset.x));
  ref.row1 = glm::vec3(float(-s * scale.x), float(c * scale.y), float(offset.y));
  if (const json* texCoord = findPath(transform, {"texCoord"})) ref.texCoord = texCoord->get<std::uint32_t>();
}

// A glTF textureInfo object (baseColorTexture, normalTexture, ...) with its KHR_texture_transform as one use of
// the scene texture `convert` gives for its index.
gpu::TextureRef convertTextureUse(const json& info, const std::string& where, Document& document,
                                  const std::function<int(int)>& convert) {
  gpu::TextureRef ref = noTextureRef();
  const int index = info.at("index").get<int>();
  if (const json* texCoord = findPath(info, {"texCoord"})) ref.texCoord = texCoord->get<std::uint32_t>();
  if (const json* scale = findPath(info, {"scale"})) {
    // Checked as a double: converting one beyond float's range is undefined behaviour.
    const double value = scale->get<double>();
    if (!(std::abs(value) <= double(std::numeric_limits<float>::max()))) throw Error(where + ".scale is not finite");
    ref.scale = float(value);
  }
  if (const json* transform = findPath(info, {"extensions", "KHR_texture_transform"})) {
    applyTextureTransform(ref, *transform, where);
  }
  if (ref.texCoord > 1) {
    document.ignore("textures on TEXCOORD_2 and above");
    return noTextureRef();
  }
  ref.texture = convert(index);
  return ref;
}

// A base-colour texture multiplies the model's diffuse colour (MaterialRecord::diffuseParam).
bool hasDiffuseColour(std::uint32_t model) { return findRole(modelInfo(model), "diffuse") != nullptr; }

// KHR_materials_volume's Beer-Lambert law: what passes `distances` attenuation distances of the medium.
glm::vec3 volumeTransmittance(glm::vec3 attenuationColor, float distances) {
  return glm::pow(attenuationColor, glm::vec3(distances));
}

// A KHR_materials_ior index for `param` of `model`: as it is, or its table's largest (with a warning saying so).
// The model's formula holds for any index; its table stops where common dielectrics end.
float indexWithin(float ior, const gpu::MaterialRecord& record, std::string_view param, const std::string& where) {
  const ModelInfo& model = modelInfo(record.model);
  const float iorMax = findParam(model, param)->max;
  if (ior > iorMax) {
    warn(where + ": KHR_materials_ior.ior = " + formatNumber(ior) + " is above " + std::string(model.name) + "'s " +
         formatNumber(iorMax) + "; using " + formatNumber(iorMax));
  }
  return std::min(ior, iorMax);
}

// glTF's anisotropy strength s (KHR_materials_anisotropy, KHR_materials_coat's coatAnisotropyStrength) stretches GGX
// along the tangent to alpha_t = mix(alpha, 1, s^2), alpha_b = alpha (alpha = roughness^2); openpbr's anisotropy a
// sets the ratio alpha_b / alpha_t = 1 - a: the same ratio, so the same shape of highlight, of a slightly different
// size (docs/gltf.md).
float anisotropyOf(float roughness, float strength) {
  const float alpha = std::max(roughness * roughness, 1e-3f);
  const float alphaT = alpha + (1.0f - alpha) * strength * strength;
  return std::clamp(1.0f - alpha / alphaT, 0.0f, 1.0f);
}

// KHR_materials_clearcoat, KHR_materials_iridescence and KHR_materials_sheen onto openpbr: the core factors as its
// base, the coat as its coat, the iridescent film as its thin film and the sheen as its fuzz.
// The sheen's layering is the fuzz's, f_sheen + (1 - max(sheenColor) E_sheen) f_base, so that sheenColor =
// fuzz_weight fuzz_color with fuzz_weight = max(sheenColor): a black sheen is none. Only the lobe differs: glTF's
// is Estevez & Kulla's "Charlie", openpbr's Zeltner et al.'s (docs/gltf.md). The extension's coat is a dielectric of index 1.5 whose Fresnel
// term scales the base below it, with no internal reflections: openpbr's coat with coat_darkening 0 (albedo scaling
// alone). KHR_materials_specular's factors go to specular_weight and specular_color, which mean nearly what they
// mean in glTF (docs/gltf.md, "Material extensions").
gpu::MaterialRecord mapLayered(const MetallicRoughness& input, const std::string& where) {
  gpu::MaterialRecord record = defaultRecord(modelId("openpbr"));
  const std::string mapped = where + " (metallic-roughness as openpbr's base)";
  setParam(record, "base_color", input.baseColor, mapped);
  setParam(record, "base_metalness", glm::vec3(input.metallic), mapped);
  setParam(record, "specular_roughness", glm::vec3(input.roughness), mapped);
  setParam(record, "specular_ior", glm::vec3(indexWithin(input.ior, record, "specular_ior", where)),
           where + " (KHR_materials_ior)");
  setParam(record, "specular_weight", glm::vec3(input.specular), where + " (KHR_materials_specular)");
  setParam(record, "specular_color", glm::min(input.specularColor, glm::vec3(1.0f)), where + " (KHR_materials_specular)");
  if (input.hasCoat) {
    const std::string coat = where + " (KHR_materials_coat)";
    setParam(record, "coat_weight", glm::vec3(input.coat), coat);
    setParam(record, "coat_roughness", glm::vec3(input.coatRoughness), coat);
    setParam(record, "coat_ior", glm::vec3(indexWithin(input.coatIor, record, "coat_ior", coat)), coat);
    setParam(record, "coat_color", input.coatColor, coat);
    setParam(record, "coat_darkening", glm::vec3(input.coatDarkening), coat);
    if (input.coatAnisotropy > 0.0f) {
      setParam(record, "coat_roughness_anisotropy",
               glm::vec3(anisotropyOf(input.coatRoughness, input.coatAnisotropy)), coat);
      // The coat's tangent is turned from the shading frame's, which the base's anisotropyRotation has already
      // turned (kernel/hit_common.glsl): by the difference, wrapped.
      const double baseTurn = input.anisotropy > 0.0f ? input.anisotropyRotation : 0.0;
      const double angle = std::remainder(double(input.coatAnisotropyRotation) - baseTurn, 2.0 * std::numbers::pi);
      if (angle != 0.0) setParam(record, "geometry_coat_tangent_angle", glm::vec3(float(angle)), coat);
    }
  } else {
    setParam(record, "coat_weight", glm::vec3(input.clearcoat), where + " (KHR_materials_clearcoat)");
    setParam(record, "coat_roughness", glm::vec3(input.clearcoatRoughness), where + " (KHR_materials_clearcoat)");
    setParam(record, "coat_ior", glm::vec3(1.5f), where + " (KHR_materials_clearcoat)");
    setParam(record, "coat_darkening", glm::vec3(0.0f), where + " (KHR_materials_clearcoat)");
  }
  if (input.anisotropy > 0.0f) {
    setParam(record, "specular_roughness_anisotropy", glm::vec3(anisotropyOf(input.roughness, input.anisotropy)),
             where + " (KHR_materials_anisotropy)");
  }
  if (input.diffuseRoughness > 0.0f) {
    setParam(record, "base_diffuse_roughness", glm::vec3(input.diffuseRoughness),
             where + " (KHR_materials_diffuse_roughness)");
  }
  // A layer's parameters are set only where the layer is: at its neutral value a layer is none, and the material
  // keeps openpbr's defaults for it.
  if (input.iridescence > 0.0f) {
    const std::string film = where + " (KHR_materials_iridescence)";
    const ParamInfo& thickness = *findParam(modelInfo(record.model), "thin_film_thickness");
    const ParamInfo& filmIor = *findParam(modelInfo(record.model), "thin_film_ior");
    const float micrometres = input.iridescenceThicknessNm / 1000.0f;
    if (micrometres > thickness.max || input.iridescenceIor > filmIor.max) {
      warn(film + ": the film's thickness " + formatNumber(input.iridescenceThicknessNm) + " nm and index " +
           formatNumber(input.iridescenceIor) + " are used up to openpbr's " + formatNumber(1000.0f * thickness.max) +
           " nm and " + formatNumber(filmIor.max));
    }
    setParam(record, "thin_film_weight", glm::vec3(input.iridescence), film);
    setParam(record, "thin_film_thickness", glm::vec3(std::min(micrometres, thickness.max)), film);
    setParam(record, "thin_film_ior", glm::vec3(std::clamp(input.iridescenceIor, filmIor.min, filmIor.max)), film);
  }
  // KHR_materials_transmission and KHR_materials_volume onto the translucent base: a finite attenuation distance is
  // the volume (transmission_depth, transmission_color = attenuationColor); without one, glTF tints what passes by
  // the base colour, which is openpbr's tint at the surface (depth 0).
  if (input.transmission > 0.0f) {
    const std::string through = where + " (KHR_materials_transmission)";
    setParam(record, "transmission_weight", glm::vec3(input.transmission), through);
    const ParamInfo& depth = *findParam(modelInfo(record.model), "transmission_depth");
    if (input.volumeThickness > 0.0f && std::isfinite(input.attenuationDistance)) {
      if (input.attenuationDistance > depth.max) {
        warn(where + " (KHR_materials_volume): attenuationDistance " + formatNumber(input.attenuationDistance) +
             " is used as openpbr's largest transmission_depth, " + formatNumber(depth.max));
      }
      setParam(record, "transmission_depth", glm::vec3(std::min(input.attenuationDistance, depth.max)),
               where + " (KHR_materials_volume)");
      setParam(record, "transmission_color", input.attenuationColor, where + " (KHR_materials_volume)");
    } else {
      setParam(record, "transmission_color", input.baseColor, through);
    }
    // KHR_materials_dispersion: dispersion = 20 / V_d, and openpbr's V = abbe_number / scale, so scale = dispersion
    // with abbe_number 20 up to 1, then scale 1 with abbe_number = 20 / dispersion (down to openpbr's least Abbe
    // number). The extension builds on the volume: a surface without one (thicknessFactor 0) is thin and does not
    // refract, so it does not disperse either.
    if (input.dispersion > 0.0f) {
      const std::string dispersion = where + " (KHR_materials_dispersion)";
      if (!(input.volumeThickness > 0.0f)) {
        warn(dispersion + ": not applied: without KHR_materials_volume's thickness the surface is thin and does not "
                          "refract");
      } else {
        const ParamInfo& abbe = *findParam(modelInfo(record.model), "transmission_dispersion_abbe_number");
        const float scale = std::min(input.dispersion, 1.0f), abbeNumber = 20.0f / std::max(input.dispersion, 1.0f);
        if (abbeNumber < abbe.min) {
          warn(dispersion + ": dispersion " + formatNumber(input.dispersion) + " is used as openpbr's least Abbe " +
               "number, " + formatNumber(abbe.min) + " (dispersion " + formatNumber(20.0f / abbe.min) + ")");
        }
        setParam(record, "transmission_dispersion_scale", glm::vec3(scale), dispersion);
        setParam(record, "transmission_dispersion_abbe_number", glm::vec3(std::max(abbeNumber, abbe.min)), dispersion);
      }
    }
  }
  // KHR_materials_diffuse_transmission: the diffuse lobe becomes mix(diffuse BRDF of the base colour, diffuse BTDF
  // of diffuseTransmissionColor, factor), which is openpbr's thin-walled subsurface that passes all its light
  // (subsurface_scatter_anisotropy 1) mixed in by subsurface_weight: exact, below the same specular layer. glTF's
  // surfaces without a volume are thin. With KHR_materials_volume the text makes the object translucent: light
  // crosses the boundary by the diffuse BTDF and is absorbed inside. raylab takes it as the Sample Viewer does: the
  // same thin sheet, its BTDF attenuated by Beer-Lambert over the volume's thickness,
  // attenuationColor^(thicknessFactor / attenuationDistance). With a specular transmission too, the volume belongs
  // to that transmission and the diffuse one is not applied (one warning).
  if (input.diffuseTransmission > 0.0f && input.transmission < 1.0f) {
    const std::string diffuse = where + " (KHR_materials_diffuse_transmission)";
    const bool volume = input.volumeThickness > 0.0f && std::isfinite(input.attenuationDistance);
    if (volume && input.transmission > 0.0f) {
      warn(diffuse + ": with KHR_materials_transmission and KHR_materials_volume it is not applied (the volume is "
                     "the specular transmission's; raylab's diffuse transmission is a thin wall's)");
    } else {
      glm::vec3 colour = input.diffuseTransmissionColor;
      if (volume) colour *= volumeTransmittance(input.attenuationColor, input.volumeThickness / input.attenuationDistance);
      setParam(record, "geometry_thin_walled", glm::vec3(1.0f), diffuse);
      setParam(record, "subsurface_weight", glm::vec3(input.diffuseTransmission), diffuse);
      setParam(record, "subsurface_color", colour, volume ? diffuse + " through KHR_materials_volume" : diffuse);
      setParam(record, "subsurface_scatter_anisotropy", glm::vec3(1.0f), diffuse);
    }
  }
  if (input.hasFuzz && input.fuzz > 0.0f) {
    const std::string fuzz = where + " (KHR_materials_fuzz)";
    setParam(record, "fuzz_weight", glm::vec3(input.fuzz), fuzz);
    setParam(record, "fuzz_color", input.fuzzColor, fuzz);
    setParam(record, "fuzz_roughness", glm::vec3(input.fuzzRoughness), fuzz);
  } else if (const float sheenWeight = std::max({input.sheenColor.r, input.sheenColor.g, input.sheenColor.b});
             !input.hasFuzz && sheenWeight > 0.0f) {
    const std::string sheen = where + " (KHR_materials_sheen)";
    setParam(record, "fuzz_weight", glm::vec3(sheenWeight), sheen);
    setParam(record, "fuzz_color", input.sheenColor / sheenWeight, sheen);
    setParam(record, "fuzz_roughness", glm::vec3(input.sheenRoughness), sheen);
  }
  return record;
}

// The layered extensions' textures (each text's channels: kernel/hit_common.glsl), each scaling the openpbr
// parameter its factor sets. The drafts' channels are their texts' (KhronosGroup/glTF, extensions/2.0/Khronos): coat
// R weight, G roughness, sRGB colour; fuzz R weight, sRGB colour, A roughness; diffuse roughness R. Diffuse
// transmission's (ratified): A the factor, sRGB RGB the colour.
struct LayerTexture {
  const char* extension;
  const char* key;
  const char* param;
  const char* layerWeight;  // the weight that says whether the layer is there at all
  std::uint32_t use;        // gpu::kTexture...
  const char* replacedBy;   // the extension whose layer replaces this one's where a material has both, or nullptr
};
constexpr LayerTexture kLayerTextures[] = {
    {"KHR_materials_clearcoat", "clearcoatTexture", "coat_weight", "coat_weight", gpu::kTextureCoat,
     "KHR_materials_coat"},
    {"KHR_materials_clearcoat", "clearcoatRoughnessTexture", "coat_roughness", "coat_weight", gpu::kTextureCoatRoughness,
     "KHR_materials_coat"},
    {"KHR_materials_coat", "coatTexture", "coat_weight", "coat_weight", gpu::kTextureCoat, nullptr},
    {"KHR_materials_coat", "coatRoughnessTexture", "coat_roughness", "coat_weight", gpu::kTextureCoatRoughness, nullptr},
    {"KHR_materials_coat", "coatColorTexture", "coat_color", "coat_weight", gpu::kTextureCoatColor, nullptr},
    {"KHR_materials_sheen", "sheenColorTexture", "fuzz_color", "fuzz_weight", gpu::kTextureSheenColor,
     "KHR_materials_fuzz"},
    {"KHR_materials_sheen", "sheenRoughnessTexture", "fuzz_roughness", "fuzz_weight", gpu::kTextureSheenRoughness,
     "KHR_materials_fuzz"},
    {"KHR_materials_fuzz", "fuzzTexture", "fuzz_weight", "fuzz_weight", gpu::kTextureFuzz, nullptr},
    {"KHR_materials_fuzz", "fuzzColorTexture", "fuzz_color", "fuzz_weight", gpu::kTextureSheenColor, nullptr},
    {"KHR_materials_fuzz", "fuzzRoughnessTexture", "fuzz_roughness", "fuzz_weight", gpu::kTextureSheenRoughness, nullptr},
    {"KHR_materials_diffuse_roughness", "diffuseRoughnessTexture", "base_diffuse_roughness", "base_diffuse_roughness",
     gpu::kTextureDiffuseRoughness, nullptr},
    {"KHR_materials_diffuse_transmission", "diffuseTransmissionTexture", "subsurface_weight", "subsurface_weight",
     gpu::kTextureDiffuseTransmission, nullptr},
    {"KHR_materials_diffuse_transmission", "diffuseTransmissionColorTexture", "subsurface_color", "subsurface_weight",
     gpu::kTextureDiffuseTransmissionColor, nullptr},
    {"KHR_materials_iridescence", "iridescenceTexture", "thin_film_weight", "thin_film_weight", gpu::kTextureIridescence,
     nullptr},
    {"KHR_materials_iridescence", "iridescenceThicknessTexture", "thin_film_thickness", "thin_film_weight",
     gpu::kTextureIridescenceThickness, nullptr},
    {"KHR_materials_transmission", "transmissionTexture", "transmission_weight", "transmission_weight",
     gpu::kTextureTransmission, nullptr},
};

// iridescenceThicknessTexture's G runs the film from the minimum (G = 0) to the maximum (G = 1) thickness, which
// the parameter holds: the floor of the scale is minimum / maximum.
float thicknessFloor(const MetallicRoughness& input) {
  return input.iridescenceThicknessNm > 0.0f
             ? std::clamp(input.iridescenceThicknessMinimumNm / input.iridescenceThicknessNm, 0.0f, 1.0f)
             : 0.0f;
}

}  // namespace

gpu::MaterialRecord mapMetallicRoughness(const MetallicRoughness& input, const std::string& where) {
  const bool sheen = input.sheenColor != glm::vec3(0.0f);
  const bool layered = input.clearcoat > 0.0f || input.iridescence > 0.0f || sheen || (input.hasCoat && input.coat > 0.0f) ||
                       (input.hasFuzz && input.fuzz > 0.0f) || input.diffuseRoughness > 0.0f ||
                       input.anisotropy > 0.0f || (input.diffuseTransmission > 0.0f && input.transmission < 1.0f) ||
                       (input.dispersion > 0.0f && input.transmission > 0.0f && input.volumeThickness > 0.0f);
  const bool volume = input.volumeThickness > 0.0f && std::isfinite(input.attenuationDistance);
  if (input.transmission >= 1.0f && !volume && !layered) {
    // Glass: smooth up to a roughness of 0.001, rough (ggx_dielectric, alpha = roughness^2 as glTF's own BRDF)
    // beyond, unless the index is too close to 1 for an interface, where smooth glass is as invisible as both.
    const gpu::MaterialRecord smooth = defaultRecord(modelId("glass"));
    const ModelInfo& rough = modelInfo(modelId("ggx_dielectric"));
    const bool isRough = input.roughness > 0.001f && input.ior >= findParam(rough, "eta")->min;
    gpu::MaterialRecord record = isRough ? defaultRecord(rough.id) : smooth;
    if (isRough) {
      const float alpha = std::max(input.roughness * input.roughness, findParam(rough, "alpha_x")->min);
      setParam(record, "alpha_x", glm::vec3(alpha), where + " (roughness squared)");
      setParam(record, "alpha_y", glm::vec3(alpha), where + " (roughness squared)");
    }
    setParam(record, "eta", glm::vec3(input.ior), where + " (KHR_materials_ior)");
    setParam(record, "tint", input.baseColor, where + " (base colour as glass tint)");
    return record;
  }
  if (layered || input.transmission > 0.0f) return mapLayered(input, where);
  // glTF's own BRDF (Appendix B): the factors as they are, nothing approximated.
  gpu::MaterialRecord record = defaultRecord(modelId("gltf_pbr"));
  const std::string mapped = where + " (metallic-roughness)";
  setParam(record, "base_color", input.baseColor, mapped);
  setParam(record, "metallic", glm::vec3(input.metallic), mapped);
  setParam(record, "roughness", glm::vec3(input.roughness), mapped);
  // gltf_pbr's table stops at 3 (f0 = 0.25), beyond any common dielectric.
  setParam(record, "ior", glm::vec3(indexWithin(input.ior, record, "ior", where)), where + " (KHR_materials_ior)");
  setParam(record, "specular", glm::vec3(input.specular), where + " (KHR_materials_specular)");
  // The colour reaches F0 only through min(f0 colour, 1); the model's largest colour, 25, already lifts the default
  // ior's f0 of 0.04 to 1. Larger colours (valid glTF) are used as the largest, with a warning.
  const float colourMax = findParam(modelInfo(record.model), "specular_color")->max;
  if (glm::any(glm::greaterThan(input.specularColor, glm::vec3(colourMax)))) {
    warn(where + ": KHR_materials_specular.specularColorFactor is above gltf_pbr's " + formatNumber(colourMax) +
         "; using " + formatNumber(colourMax));
  }
  setParam(record, "specular_color", glm::min(input.specularColor, glm::vec3(colourMax)),
           where + " (KHR_materials_specular)");
  return record;
}

void applyRaylabMaterial(gpu::MaterialRecord& record, const json& raylab, const std::string& where, Document* document) {
  const std::string extras = where + ": extras.raylab";
  if (!raylab.is_object()) throw Error(extras + ": expected an object, found " + quote(raylab));
  if (const auto model = raylab.find("model"); model != raylab.end()) {
    const ModelInfo* info = model->is_string() ? findModel(model->get<std::string>()) : nullptr;
    if (info == nullptr) {
      throw Error(extras + ".model: " + quote(*model) + " is not a model (the models are " + modelNames() + ")");
    }
    record = defaultRecord(info->id);
  }
  const ModelInfo& model = modelInfo(record.model);
  // Presets first ("metal": "Au"), so that the object's other values refine them.
  for (const auto& [key, value] : raylab.items()) {
    if (!isPresetKey(model, key)) continue;
    if (!value.is_string()) throw Error(extras + "." + key + ": expected a name, found " + quote(value));
    applyPreset(record, key, value.get<std::string>(), extras);
  }
  for (const auto& [key, value] : raylab.items()) {
    if (key == "model" || isPresetKey(model, key)) continue;
    const ParamInfo* param = findParam(model, key);
    if (param == nullptr) {
      setParam(record, key, glm::vec3(0.0f), extras);  // throws, listing the model's parameters
      continue;
    }
    if (isFileParam(*param)) {
      // A URI like every other: relative to the scene's folder and inside it (unless the loader allows otherwise).
      if (!value.is_string()) throw Error(extras + "." + key + ": expected a file name, found " + quote(value));
      if (document == nullptr) throw Error(extras + "." + key + ": a file outside a scene file has no folder to be in");
      std::string path;
      try {
        path = resolveUri(value.get<std::string>(), document->baseDirectory, document->uriPolicy);
      } catch (const Error& error) {
        throw Error(extras + "." + key + ": " + error.what());
      }
      setFileParam(record, key, path, extras);
      continue;
    }
    glm::vec3 v(0.0f);
    if (param->rgb) {
      const bool rgb = value.is_array() && value.size() == 3 && value[0].is_number() && value[1].is_number() &&
                       value[2].is_number();
      if (!rgb) throw Error(extras + "." + key + ": expected [r, g, b], found " + quote(value));
      v = glm::vec3(value[0].get<float>(), value[1].get<float>(), value[2].get<float>());
    } else {
      if (!value.is_number()) throw Error(extras + "." + key + ": expected a number, found " + quote(value));
      v = glm::vec3(value.get<float>());
    }
    setParam(record, key, v, extras);
  }
  checkFileParams(record, extras);
}

void convertMaterials(Document& document, Scene& scene) {
  TextureConverter textures(document, scene);
  const MeasuredFileLimit measuredLimit(document.label);
  const json* materialsJson = findPath(document.json, {"materials"});
  for (std::size_t i = 0; i < document.model.materials.size(); ++i) {
    const tinygltf::Material& material = document.model.materials[i];
    const json& materialJson = materialsJson->at(i);
    const std::string where = document.label + ": " + describe("material", int(i), material.name);
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;

    MetallicRoughness input;
    for (int c = 0; c < 3; ++c) {
      input.baseColor[c] = checkedFactor(pbr.baseColorFactor[std::size_t(c)], 0.0, 1.0, where,
                                         "baseColorFactor[" + std::to_string(c) + "]");
    }
    input.metallic = checkedFactor(pbr.metallicFactor, 0.0, 1.0, where, "metallicFactor");
    input.roughness = checkedFactor(pbr.roughnessFactor, 0.0, 1.0, where, "roughnessFactor");
    if (const json* ior = findPath(materialJson, {"extensions", "KHR_materials_ior", "ior"})) {
      input.ior = checkedFactor(ior->get<double>(), 1.0, kMaxEta, where, "KHR_materials_ior.ior");
    }
    if (const json* transmission =
            findPath(materialJson, {"extensions", "KHR_materials_transmission", "transmissionFactor"})) {
      input.transmission =
          checkedFactor(transmission->get<double>(), 0.0, 1.0, where, "KHR_materials_transmission.transmissionFactor");
    }
    if (const json* factor = findPath(materialJson, {"extensions", "KHR_materials_specular", "specularFactor"})) {
      input.specular = checkedFactor(factor->get<double>(), 0.0, 1.0, where, "KHR_materials_specular.specularFactor");
    }
    if (const json* colour = findPath(materialJson, {"extensions", "KHR_materials_specular", "specularColorFactor"})) {
      for (int c = 0; c < 3; ++c) {
        input.specularColor[c] = checkedFactor((*colour)[std::size_t(c)].get<double>(), 0.0,
                                               std::numeric_limits<float>::max(), where,
                                               "KHR_materials_specular.specularColorFactor[" + std::to_string(c) + "]");
      }
    }

    if (const json* coat = findPath(materialJson, {"extensions", "KHR_materials_clearcoat"})) {
      // The schema (gltf_schema.cpp) has checked the types.
      const std::string name = "KHR_materials_clearcoat";
      if (const json* factor = findPath(*coat, {"clearcoatFactor"})) {
        input.clearcoat = checkedFactor(factor->get<double>(), 0.0, 1.0, where, name + ".clearcoatFactor");
      }
      if (const json* factor = findPath(*coat, {"clearcoatRoughnessFactor"})) {
        input.clearcoatRoughness = checkedFactor(factor->get<double>(), 0.0, 1.0, where, name + ".clearcoatRoughnessFactor");
      }
    }
    if (const json* film = findPath(materialJson, {"extensions", "KHR_materials_iridescence"})) {
      const std::string name = "KHR_materials_iridescence";
      const double kLargest = std::numeric_limits<float>::max();
      if (const json* factor = findPath(*film, {"iridescenceFactor"})) {
        input.iridescence = checkedFactor(factor->get<double>(), 0.0, 1.0, where, name + ".iridescenceFactor");
      }
      if (const json* ior = findPath(*film, {"iridescenceIor"})) {
        input.iridescenceIor = checkedFactor(ior->get<double>(), 1.0, kLargest, where, name + ".iridescenceIor");
      }
      // Without a thickness texture the film is iridescenceThicknessMaximum thick (the extension's text); the
      // minimum only matters with one.
      if (const json* value = findPath(*film, {"iridescenceThicknessMinimum"})) {
        input.iridescenceThicknessMinimumNm =
            checkedFactor(value->get<double>(), 0.0, kLargest, where, name + ".iridescenceThicknessMinimum");
      }
      if (const json* value = findPath(*film, {"iridescenceThicknessMaximum"})) {
        input.iridescenceThicknessNm =
            checkedFactor(value->get<double>(), 0.0, kLargest, where, name + ".iridescenceThicknessMaximum");
      }
    }

    // The layered extensions' factors, each checked against its range; messages name the extension and the key.
    const auto readColour = [&](const json& owner, const char* key, const std::string& name, glm::vec3& colour) {
      if (const json* value = findPath(owner, {key})) {
        for (int c = 0; c < 3; ++c) {
          colour[c] = checkedFactor((*value)[std::size_t(c)].get<double>(), 0.0, 1.0, where,
                                    name + "." + key + "[" + std::to_string(c) + "]");
        }
      }
    };
    const auto readFactor = [&](const json& owner, const char* key, const std::string& name, double lo, double hi,
                                float& factor) {
      if (const json* value = findPath(owner, {key})) factor = checkedFactor(value->get<double>(), lo, hi, where, name + "." + key);
    };
    if (const json* volume = findPath(materialJson, {"extensions", "KHR_materials_volume"})) {
      const std::string name = "KHR_materials_volume";
      const double kLargest = std::numeric_limits<float>::max();
      readFactor(*volume, "thicknessFactor", name, 0.0, kLargest, input.volumeThickness);
      readFactor(*volume, "attenuationDistance", name, 1e-30, kLargest, input.attenuationDistance);
      readColour(*volume, "attenuationColor", name, input.attenuationColor);
      if (volume->contains("thicknessTexture")) document.ignore(name + ".thicknessTexture (thicknessFactor stands for the whole surface)");
    }
    if (const json* dispersion = findPath(materialJson, {"extensions", "KHR_materials_dispersion"})) {
      readFactor(*dispersion, "dispersion", "KHR_materials_dispersion", 0.0, std::numeric_limits<float>::max(),
                 input.dispersion);
    }
    if (const json* coat = findPath(materialJson, {"extensions", "KHR_materials_coat"})) {
      const std::string name = "KHR_materials_coat";
      input.hasCoat = true;
      readFactor(*coat, "coatFactor", name, 0.0, 1.0, input.coat);
      readFactor(*coat, "coatRoughnessFactor", name, 0.0, 1.0, input.coatRoughness);
      readFactor(*coat, "coatIor", name, 1.0, kMaxEta, input.coatIor);
      readFactor(*coat, "coatDarkeningFactor", name, 0.0, 1.0, input.coatDarkening);
      readColour(*coat, "coatColorFactor", name, input.coatColor);
      readFactor(*coat, "coatAnisotropyStrength", name, 0.0, 1.0, input.coatAnisotropy);
      readFactor(*coat, "coatAnisotropyRotation", name, -std::numeric_limits<float>::max(),
                 std::numeric_limits<float>::max(), input.coatAnisotropyRotation);
      input.coatAnisotropyRotation =
          float(std::remainder(double(input.coatAnisotropyRotation), 2.0 * std::numbers::pi));
    }
    if (const json* fuzz = findPath(materialJson, {"extensions", "KHR_materials_fuzz"})) {
      const std::string name = "KHR_materials_fuzz";
      input.hasFuzz = true;
      readFactor(*fuzz, "fuzzFactor", name, 0.0, 1.0, input.fuzz);
      readFactor(*fuzz, "fuzzRoughnessFactor", name, 0.0, 1.0, input.fuzzRoughness);
      readColour(*fuzz, "fuzzColorFactor", name, input.fuzzColor);
    }
    if (const json* anisotropy = findPath(materialJson, {"extensions", "KHR_materials_anisotropy"})) {
      const std::string name = "KHR_materials_anisotropy";
      readFactor(*anisotropy, "anisotropyStrength", name, 0.0, 1.0, input.anisotropy);
      readFactor(*anisotropy, "anisotropyRotation", name, -std::numeric_limits<float>::max(),
                 std::numeric_limits<float>::max(), input.anisotropyRotation);
      // The angle only turns the direction: within one turn it is exact in single precision.
      input.anisotropyRotation = float(std::remainder(double(input.anisotropyRotation), 2.0 * std::numbers::pi));
    }
    if (const json* diffuse = findPath(materialJson, {"extensions", "KHR_materials_diffuse_roughness"})) {
      const std::string name = "KHR_materials_diffuse_roughness";
      readFactor(*diffuse, "diffuseRoughnessFactor", name, 0.0, 1.0, input.diffuseRoughness);
    }
    if (const json* diffuse = findPath(materialJson, {"extensions", "KHR_materials_diffuse_transmission"})) {
      const std::string name = "KHR_materials_diffuse_transmission";
      readFactor(*diffuse, "diffuseTransmissionFactor", name, 0.0, 1.0, input.diffuseTransmission);
      readColour(*diffuse, "diffuseTransmissionColorFactor", name, input.diffuseTransmissionColor);
    }
    if (const json* sheen = findPath(materialJson, {"extensions", "KHR_materials_sheen"})) {
      const std::string name = "KHR_materials_sheen";
      readColour(*sheen, "sheenColorFactor", name, input.sheenColor);
      readFactor(*sheen, "sheenRoughnessFactor", name, 0.0, 1.0, input.sheenRoughness);
    }

    gpu::MaterialRecord record = mapMetallicRoughness(input, where);
    if (const json* raylab = findPath(materialJson, {"extras", "raylab"})) applyRaylabMaterial(record, *raylab, where, &document);

    // The textures (glTF 3.9.2-3.9.3), each use with its UV set and transform; an occlusion texture is checked
    // and not used: the path integrator computes occlusion (docs/gltf.md).
    const std::string materialName = describe("material", int(i), material.name);
    const auto use = [&](std::initializer_list<const char*> path) { return findPath(materialJson, path); };
    const auto convertUse = [&](const json* info, const std::string& property) {
      return convertTextureUse(*info, where + ": " + property, document,
                               [&](int index) { return textures.convert(index, materialName + " " + property); });
    };
    gpu::MaterialTextures uses = noMaterialTextures();
    // glTF 3.9.4: MASK cuts holes where alpha < alphaCutoff, BLEND is (here) stochastic transparency; alpha is
    // baseColorFactor's fourth value times the base-colour texture's alpha.
    // Absent means OPAQUE; present, it must be one of the three names ("" is not absent).
    const std::string alphaMode = materialJson.contains("alphaMode") && materialJson["alphaMode"].is_string()
                                      ? materialJson["alphaMode"].get<std::string>()
                                      : "OPAQUE";
    if (alphaMode == "MASK" || alphaMode == "BLEND") {
      uses.alphaMode = alphaMode == "MASK" ? gpu::kAlphaMask : gpu::kAlphaBlend;
      uses.alpha = checkedFactor(pbr.baseColorFactor[3], 0.0, 1.0, where, "baseColorFactor[3]");
      if (alphaMode == "MASK") {
        uses.alphaCutoff = checkedFactor(material.alphaCutoff, 0.0, std::numeric_limits<float>::max(), where,
                                         "alphaCutoff");
      }
    } else if (alphaMode != "OPAQUE") {
      throw Error(where + ": alphaMode " + quote(json(alphaMode)) + " is not OPAQUE, MASK or BLEND");
    }
    const bool readsBaseColour = hasDiffuseColour(record.model) || uses.alphaMode != gpu::kAlphaOpaque;
    if (const json* info = use({"pbrMetallicRoughness", "baseColorTexture"}); info && readsBaseColour) {
      uses.refs[gpu::kTextureBaseColor] = convertUse(info, "baseColorTexture");
    }
    if (const json* info = use({"pbrMetallicRoughness", "metallicRoughnessTexture"})) {
      if (record.textureParams != (gpu::kNoTextureParam | (gpu::kNoTextureParam << 8u))) {
        uses.refs[gpu::kTextureMetallicRoughness] = convertUse(info, "metallicRoughnessTexture");
      }
    }
    // KHR_materials_specular's textures, for a model with the roles they scale (gltf_pbr).
    if (const json* info = use({"extensions", "KHR_materials_specular", "specularTexture"})) {
      if (((record.textureParams >> 16u) & 0xFFu) != gpu::kNoTextureParam) {
        uses.refs[gpu::kTextureSpecular] = convertUse(info, "KHR_materials_specular.specularTexture");
      }
    }
    if (const json* info = use({"extensions", "KHR_materials_specular", "specularColorTexture"})) {
      if ((record.textureParams >> 24u) != gpu::kNoTextureParam) {
        uses.refs[gpu::kTextureSpecularColor] = convertUse(info, "KHR_materials_specular.specularColorTexture");
      }
    }
    // The layered extensions' textures, onto the openpbr parameters their factors set (kLayerTextures).
    for (const LayerTexture& layer : kLayerTextures) {
      const json* info = use({"extensions", layer.extension, layer.key});
      if (info == nullptr) continue;
      const std::string property = std::string(layer.extension) + "." + layer.key;
      if (layer.replacedBy != nullptr && use({"extensions", layer.replacedBy})) {
        document.ignore(property + " (" + layer.replacedBy + " replaces its layer)");
        continue;
      }
      const ParamInfo* param = findParam(modelInfo(record.model), layer.param);
      // A layer's parameters are set only where the layer is (mapLayered): an absent layer has nothing to scale.
      if (param == nullptr || !(getParam(record, layer.layerWeight).x > 0.0f)) {
        document.ignore(property + " (" +
                        (param == nullptr ? "the material's model has no " + std::string(layer.param) : "its layer is absent") +
                        ")");
        continue;
      }
      gpu::TextureRef ref = convertUse(info, property);
      ref.param = param->slot;
      ref.scale = layer.use == gpu::kTextureIridescenceThickness ? thicknessFloor(input) : 0.0f;
      uses.refs[layer.use] = ref;
      uses.layerModel = record.model;
    }
    // KHR_materials_anisotropy's direction (its rotation and texture), where the material has the anisotropy.
    if (const ParamInfo* ratio = findParam(modelInfo(record.model), "specular_roughness_anisotropy");
        ratio != nullptr && input.anisotropy > 0.0f) {
      if (const json* info = use({"extensions", "KHR_materials_anisotropy", "anisotropyTexture"})) {
        uses.refs[gpu::kTextureAnisotropy] = convertUse(info, "KHR_materials_anisotropy.anisotropyTexture");
        uses.refs[gpu::kTextureAnisotropy].param = ratio->slot;
        uses.refs[gpu::kTextureAnisotropy].scale = input.anisotropy;
      }
      uses.anisotropyRotation = input.anisotropyRotation;
      if (uses.refs[gpu::kTextureAnisotropy].texture >= 0 || uses.anisotropyRotation != 0.0f) uses.layerModel = record.model;
    } else if (use({"extensions", "KHR_materials_anisotropy", "anisotropyTexture"})) {
      document.ignore("KHR_materials_anisotropy.anisotropyTexture (the anisotropy is absent)");
    }
    // KHR_materials_coat's anisotropy texture, where the coat is anisotropic; also without one when the base's
    // texture turns the shading frame's tangent texel by texel, which the coat's direction must not follow.
    const json* coatAnisotropy = use({"extensions", "KHR_materials_coat", "coatAnisotropyTexture"});
    if (const ParamInfo* coatRatio = findParam(modelInfo(record.model), "coat_roughness_anisotropy");
        coatRatio != nullptr && input.hasCoat && input.coat > 0.0f && input.coatAnisotropy > 0.0f) {
      if (coatAnisotropy != nullptr || uses.refs[gpu::kTextureAnisotropy].texture >= 0) {
        gpu::TextureRef& ref = uses.refs[gpu::kTextureCoatAnisotropy];
        if (coatAnisotropy != nullptr) ref = convertUse(coatAnisotropy, "KHR_materials_coat.coatAnisotropyTexture");
        ref.param = coatRatio->slot | findParam(modelInfo(record.model), "coat_roughness")->slot << 8u |
                    findParam(modelInfo(record.model), "geometry_coat_tangent_angle")->slot << 16u;
        ref.scale = input.coatAnisotropy;
        uses.layerModel = record.model;
      }
    } else if (coatAnisotropy != nullptr) {
      document.ignore("KHR_materials_coat.coatAnisotropyTexture (the coat's anisotropy is absent)");
    }
    // The coat's own normal map (KHR_materials_coat's, else KHR_materials_clearcoat's), where the material has a coat:
    // the kernel writes the normal it gives, in the shading frame, into geometry_coat_normal_x and _y at each hit.
    for (const auto& [extension, key] : {std::pair{"KHR_materials_coat", "coatNormalTexture"},
                                         std::pair{"KHR_materials_clearcoat", "clearcoatNormalTexture"}}) {
      const json* info = use({"extensions", extension, key});
      if (info == nullptr) continue;
      const std::string property = std::string(extension) + "." + key;
      const ParamInfo* normal = findParam(modelInfo(record.model), "geometry_coat_normal_x");
      if (input.hasCoat && std::string_view(extension) == "KHR_materials_clearcoat") {
        document.ignore(property + " (KHR_materials_coat replaces its layer)");
      } else if (normal == nullptr || !(getParam(record, "coat_weight").x > 0.0f)) {
        document.ignore(property + " (" + (normal == nullptr ? "the material's model has no coat" : "its layer is absent") + ")");
      } else {
        uses.refs[gpu::kTextureCoatNormal] = convertUse(info, property);
        uses.refs[gpu::kTextureCoatNormal].param = normal->slot;
        uses.layerModel = record.model;
      }
    }
    if (const json* info = use({"normalTexture"})) uses.refs[gpu::kTextureNormal] = convertUse(info, "normalTexture");
    if (const json* info = use({"occlusionTexture"})) convertUse(info, "occlusionTexture");
    // glTF's emissive factor and strength; a model with its own emission (openpbr) takes it as its parameters unless
    // extras.raylab gave those (then the factor must be absent or black).
    const glm::vec3 emissive = emittedRadiance(material, materialJson, where);
    if (!hasOwnEmission(modelInfo(record.model)) || glm::any(glm::greaterThan(emissive, glm::vec3(0.0f)))) {
      setEmission(record, emissive, where + " (emissiveFactor)");
    }
    // The factor multiplies the texture (glTF 2.0 3.9.3); with the factor's default of zero the texture emits
    // nothing and is not uploaded.
    if (const json* info = use({"emissiveTexture"}); info && glm::any(glm::greaterThan(record.emission, glm::vec3(0.0f)))) {
      uses.refs[gpu::kTextureEmissive] = convertUse(info, "emissiveTexture");
      // Without its texels (a source raylab cannot decode, reported) the factor alone would light the whole
      // surface, labels as bright as their background: such a material emits nothing.
      if (uses.refs[gpu::kTextureEmissive].texture < 0) setEmission(record, glm::vec3(0.0f), where);
    }
    const bool textured = std::any_of(std::begin(uses.refs), std::end(uses.refs),
                                      [](const gpu::TextureRef& ref) { return ref.texture >= 0; });
    if (textured || uses.alphaMode != gpu::kAlphaOpaque || uses.anisotropyRotation != 0.0f) {
      record.textures = int(scene.materialTextures.size());
      scene.materialTextures.push_back(uses);
    }
    scene.materials.push_back({material.name.empty() ? "material " + std::to_string(i) : material.name, record});
  }
}

std::uint32_t DefaultMaterial::index(Scene& scene) {
  if (index_ < 0) {
    index_ = static_cast<std::int64_t>(scene.materials.size());
    scene.materials.push_back({"default", lambertMaterial(kDefaultGrey)});
  }
  return static_cast<std::uint32_t>(index_);
}

}  // namespace raylab::gltf
