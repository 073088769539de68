#include "render/kernel_features.h"

#include "brdf_params/material_params.h"
#include "render/light_records.h"
#include "shared/features.h"
#include "util/error.h"
#include "util/render_options.h"

namespace raylab {

namespace {

// Whether one of the material's layer textures writes `param` at each hit (the coat's normal map sets
// geometry_coat_normal_x): the part it turns on is needed even where the factor is 0.
bool textureSets(const Scene& scene, const gpu::MaterialRecord& record, std::string_view param) {
  if (!hasLayerTextures(scene, record)) return false;
  const ParamInfo* info = findParam(modelInfo(record.model), param);
  const gpu::MaterialTextures& uses = scene.materialTextures[std::size_t(record.textures)];
  if (info == nullptr) return false;
  for (std::uint32_t use = gpu::kFirstLayerTexture; use < gpu::kTextureUses; ++use) {
    const gpu::TextureRef& ref = uses.refs[use];
    // The coat's anisotropy writes its ratio (with a texture) and the coat's tangent angle (always), packed.
    if (use == gpu::kTextureCoatAnisotropy) {
      if (ref.param != 0u && (((ref.param >> 16u) & 0xFFu) == info->slot ||
                              (ref.texture >= 0 && (ref.param & 0xFFu) == info->slot))) {
        return true;
      }
    } else if (ref.texture >= 0 && ref.param == info->slot) {
      return true;
    }
  }
  return false;
}

}  // namespace

KernelFeatures featuresOf(const Scene& scene) {
  KernelFeatures f;
  for (const Material& material : scene.materials) {
    f.models |= 1u << material.record.model;
    if (isDeltaOnly(material.record.model)) f.features |= gpu::kFeatureDeltaBsdf;
    if (material.record.delta > 0.0f) f.features |= gpu::kFeatureMirror;
    if (material.record.textures >= 0) {
      f.features |= gpu::kFeatureTextures;
      if (hasLayerTextures(scene, material.record)) f.features |= gpu::kFeatureLayerTextures;
    }
    if (hasAlpha(scene, material.record)) f.features |= gpu::kFeatureAlpha;
    for (const ModelFeature& feature : modelInfo(material.record.model).features) {
      if (getParam(material.record, feature.param).x != 0.0f || textureSets(scene, material.record, feature.param)) {
        f.features |= feature.bit;
      }
    }
  }
  if (scene.environment.hasImage()) f.features |= gpu::kFeatureEnvironment;
  f.lightKinds = lightKindsOf(scene);
  return f;
}

KernelFeatures allFeatures() {
  KernelFeatures f;
  f.models = gpu::kAllModels;
  f.features = gpu::kAllFeatures;
  f.lightKinds = gpu::kAllLightKinds;
  return f;
}

std::uint32_t chooseIntegrator(const Scene& scene, IntegratorChoice choice) {
  if (choice == IntegratorChoice::kSlides) return gpu::kIntegratorSlides;
  if (choice == IntegratorChoice::kPath) return gpu::kIntegratorPath;
  return hasEmissiveGeometry(scene) || scene.environment.hasImage() ? gpu::kIntegratorPath : gpu::kIntegratorSlides;
}

std::string_view integratorName(std::uint32_t integrator) {
  return kIntegratorValues[std::size_t(integrator == gpu::kIntegratorPath ? IntegratorChoice::kPath
                                                                           : IntegratorChoice::kSlides)];
}

std::string describe(const KernelFeatures& features) {
  std::string models;
  for (const ModelInfo& model : allModels()) {
    if (features.models & (1u << model.id)) models += (models.empty() ? "" : ", ") + std::string(model.name);
  }
  struct Named {
    std::uint32_t bit;
    const char* name;
  };
  constexpr Named kNames[] = {{gpu::kFeatureDeltaBsdf, "glass"},
                              {gpu::kFeatureMirror, "mirror reflection"},
                              {gpu::kFeatureTextures, "textures"},
                              {gpu::kFeatureLayerTextures, "layer textures"},
                              {gpu::kFeatureAlpha, "alpha"},
                              {gpu::kFeatureEnvironment, "environment image"},
                              {gpu::kFeatureAovs, "denoiser albedo and normal"},
                              {gpu::kFeatureGuiding, "path guiding"}};
  std::string list;
  for (const Named& named : kNames) {
    if (features.features & named.bit) list += (list.empty() ? "" : ", ") + std::string(named.name);
  }
  if (features.features != gpu::kAllFeatures) {
    for (const ModelInfo& model : allModels()) {
      std::uint32_t listed = 0;  // a feature of several parameters is one name
      for (const ModelFeature& feature : model.features) {
        if ((features.features & feature.bit) && !(listed & feature.bit)) {
          listed |= feature.bit;
          list += (list.empty() ? "" : ", ") + std::string(model.name) + " " + std::string(feature.name);
        }
      }
    }
  }
  for (std::uint32_t kind = 0; kind < gpu::kLightKindCount; ++kind) {
    if (features.lightKinds & (1u << kind)) list += (list.empty() ? "" : ", ") + std::string(gpu::kLightKindNames[kind]) + " lights";
  }
  return std::string("integrator: ") + std::string(integratorName(features.integrator)) + "; models: " + (models.empty() ? std::string("none") : models) +
         "; features: " + (list.empty() ? std::string("none") : list) +
         ((features.features & gpu::kFeatureDeltaBsdf) && features.schlickFresnel ? "; glass Fresnel: Schlick" : "");
}

KernelFeatures kernelFor(const Scene& scene, const KernelOptions& options) {
  KernelFeatures kernel = options.allFeatures ? allFeatures() : featuresOf(scene);
  kernel.schlickFresnel = options.schlickFresnel;
  kernel.integrator = chooseIntegrator(scene, options.integrator);
  kernel.sampling = options.sampling;
  return kernel;
}

}  // namespace raylab
