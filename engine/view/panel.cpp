#include "view/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <filesystem>

#include "brdf_params/material_params.h"
#include "render/kernel_features.h"
#include "scene/radiance_limits.h"
#include "shared/features.h"
#include "util/progress.h"
#include "view/material_editor.h"

namespace raylab {

namespace {

// The textures the material reads (the use, the image's name and size, its UV set, and its transform or scale),
// and its alpha mode.
void drawMaterialTextures(const Scene& scene, const gpu::MaterialRecord& record) {
  if (record.textures < 0 || std::size_t(record.textures) >= scene.materialTextures.size()) return;
  static constexpr const char* kUses[] = {
      "base colour", "metallic-roughness", "normal", "emissive", "specular", "specular colour", "coat weight",
      "coat roughness", "fuzz colour", "fuzz roughness", "thin-film weight", "thin-film thickness", "transmission",
      "coat colour", "fuzz weight", "diffuse roughness", "diffuse transmission", "diffuse transmission colour",
      "anisotropy", "coat normal", "coat anisotropy"};
  static_assert(std::size(kUses) == gpu::kTextureUses, "one name per texture use");
  const gpu::MaterialTextures& uses = scene.materialTextures[std::size_t(record.textures)];
  for (std::uint32_t use = 0; use < gpu::kTextureUses; ++use) {
    const gpu::TextureRef& ref = uses.refs[use];
    if (ref.texture < 0 || std::size_t(ref.texture) >= scene.textures.size()) continue;
    const Texture& texture = scene.textures[std::size_t(ref.texture)];
    const bool transformed = ref.row0 != glm::vec3(1.0f, 0.0f, 0.0f) || ref.row1 != glm::vec3(0.0f, 1.0f, 0.0f);
    std::string details = std::to_string(texture.width) + "x" + std::to_string(texture.height) + ", TEXCOORD_" +
                          std::to_string(ref.texCoord);
    if (transformed) details += ", transformed";
    if ((use == gpu::kTextureNormal || use == gpu::kTextureCoatNormal) && ref.scale != 1.0f) details += ", scale " + formatParamValue(glm::vec3(ref.scale), false);
    ImGui::TextWrapped("%s texture: %s (%s)", kUses[use], texture.name.c_str(), details.c_str());
  }
  if (uses.alphaMode == gpu::kAlphaMask) {
    ImGui::Text("alpha mask: alpha %.3g, cutoff %.3g", double(uses.alpha), double(uses.alphaCutoff));
  } else if (uses.alphaMode == gpu::kAlphaBlend) {
    ImGui::Text("alpha blend (stochastic): alpha %.3g", double(uses.alpha));
  }
}

constexpr std::size_t kListRows = 6;  // list boxes scroll beyond this many names

float listHeight(float rows) {
  return rows * ImGui::GetTextLineHeightWithSpacing() + 2.0f * ImGui::GetStyle().FramePadding.y;
}

std::string itemLabel(const std::string& name, const char* kind, std::size_t index) {
  return name.empty() ? std::string(kind) + " " + std::to_string(index) : name;
}

// The environment image's strength and rotation about +Y, or the uniform background without an image.
bool drawEnvironment(Scene& scene) {
  Environment& environment = scene.environment;
  if (!environment.hasImage()) {
    return ImGui::ColorEdit3("background", &scene.background.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
  }
  const std::string file = std::filesystem::path(environment.path).filename().string();
  ImGui::Text("%s  %ux%u", file.c_str(), environment.width, environment.height);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", environment.path.c_str());
  // The slider's top keeps strength x the brightest texel within the one radiance bound (radiance_limits.h).
  const float strongest = environment.brightest > 0.0f ? std::min(100.0f, kMaxRadiance / environment.brightest) : 100.0f;
  bool changed = ImGui::SliderFloat("strength", &environment.strength, 0.0f, strongest, "%.3g",
                                    ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
  float degrees = glm::degrees(environment.rotation);
  if (ImGui::SliderFloat("rotation", &degrees, -180.0f, 180.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp)) {
    environment.rotation = glm::radians(degrees);
    changed = true;
  }
  return changed;
}

bool drawLight(Light& light, float dragSpeed) {
  PunctualLight& record = light.record;
  bool changed = false;
  if (record.type == gpu::kLightDirectional) {
    if (ImGui::DragFloat3("direction", &record.direction.x, 0.01f, -1.0f, 1.0f)) {
      if (glm::length(record.direction) > 1.0e-6f) record.direction = glm::normalize(record.direction);
      else record.direction = glm::vec3(0.0f, -1.0f, 0.0f);
      changed = true;
    }
  } else {
    // A headlight's position is its offset along the camera's right, up and forward axes.
    changed |= ImGui::DragFloat3(record.type == gpu::kLightHeadlight ? "offset" : "position", &record.position.x,
                                 dragSpeed);
  }
  const float brightest = std::max({record.intensity.x, record.intensity.y, record.intensity.z});
  const float intensitySpeed = 0.01f * std::max(1.0f, brightest);
  changed |= ImGui::DragFloat3("intensity", &record.intensity.x, intensitySpeed, 0.0f, kMaxRadiance, "%.3g",
                               ImGuiSliderFlags_AlwaysClamp);
  return changed;
}

}  // namespace

// Two lines: one line held everything and the panel's width clipped its end (the rays per second).
std::string statusLine(const PanelStatus& status) {
  char text[160];
  std::snprintf(text, sizeof text, "%u spp  %ux%u%s\n%.1f ms/frame  %s", status.spp, status.traceExtent.x,
                status.traceExtent.y, status.preview ? " (preview)" : "", status.frameMs,
                formatCount(status.raysPerSecond, "rays/s").c_str());
  return status.denoise.empty() ? std::string(text) : std::string(text) + "\n" + status.denoise;
}

PanelEdits drawPanel(Scene& scene, ViewSettings& settings, PanelSelection& selection, const PanelStatus& status,
                     float sceneSize, float height, const std::function<void()>& materialSections) {
  PanelEdits edits;
  // Docked to the left edge, beside the image: a floating panel hid a third of a 960x540 window.
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), height), ImGuiCond_Always);
  ImGui::Begin("raylab", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushItemWidth(-130.0f);  // room for the longest label ("resolution scale") right of every widget
  ImGui::TextUnformatted(statusLine(status).c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", status.device.c_str());
  ImGui::PopStyleColor();
  if (status.compiling) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "compiling kernel...");
  if (!status.message.empty()) ImGui::TextWrapped("%s", status.message.c_str());

  if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) {
    // The integrators a kernel runs (the option's values after auto, which the viewer resolves when it opens).
    const char* integrators[] = {kIntegratorValues[std::size_t(IntegratorChoice::kSlides)].data(),
                                 kIntegratorValues[std::size_t(IntegratorChoice::kPath)].data()};
    int integrator = settings.integrator == gpu::kIntegratorPath ? 1 : 0;
    if (ImGui::Combo("integrator", &integrator, integrators, 2)) {
      settings.integrator = integrator == 1 ? gpu::kIntegratorPath : gpu::kIntegratorSlides;
      edits.integrator = true;
    }
    int depth = static_cast<int>(settings.maxDepth);
    if (ImGui::SliderInt("max depth", &depth, int(kMaxDepthOption.min), int(kMaxDepthOption.max), "%d",
                         ImGuiSliderFlags_AlwaysClamp)) {
      settings.maxDepth = static_cast<std::uint32_t>(depth);
      edits.maxDepth = true;
    }
    ImGui::SliderFloat("exposure", &settings.exposure, -20.0f, 20.0f, "%.2f stops", ImGuiSliderFlags_AlwaysClamp);
    const char* curves[] = {"clamp", "reinhard", "aces"};
    int curve = static_cast<int>(settings.toneMap);
    if (ImGui::Combo("tone curve", &curve, curves, 3)) settings.toneMap = static_cast<ToneMap>(curve);
    if (ImGui::SliderFloat("resolution scale", &settings.resolutionScale, 0.25f, 1.0f, "%.2f",
                           ImGuiSliderFlags_AlwaysClamp)) {
      edits.resolutionScale = true;
    }
    ImGui::SliderFloat("target frame", &settings.targetMs, 5.0f, 1000.0f, "%.0f ms",
                       ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
    // Open Image Denoise on the still image; comparisons stay raw (docs/viewer.md, "Denoising").
    if (ImGui::Checkbox("denoise (N)", &settings.denoise)) edits.denoise = true;
    if (ImGui::Button("reset view (R)")) edits.resetView = true;
    ImGui::SameLine();
    if (ImGui::Button("screenshot (F12)")) edits.screenshot = true;
  }

  if (ImGui::CollapsingHeader("Environment", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::PushID("environment");
    edits.environment |= drawEnvironment(scene);
    ImGui::PopID();
  }

  if (ImGui::CollapsingHeader("Materials", ImGuiTreeNodeFlags_DefaultOpen) && !scene.materials.empty()) {
    selection.material = std::min<std::size_t>(selection.material, scene.materials.size() - 1);
    const float rows = float(std::min<std::size_t>(scene.materials.size(), kListRows));
    if (ImGui::BeginListBox("##materials", ImVec2(-FLT_MIN, listHeight(rows)))) {
      for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& material = scene.materials[i];
        const std::string label = itemLabel(material.name, "material", i) + "  (" +
                                  std::string(modelInfo(material.record.model).name) + ")";
        if (ImGui::Selectable(label.c_str(), i == selection.material)) selection.material = i;
      }
      ImGui::EndListBox();
    }
    ImGui::PushID("material");
    edits.materials |= drawMaterialEditor(scene.materials[selection.material].record);
    drawMaterialTextures(scene, scene.materials[selection.material].record);
    ImGui::PopID();
  }
  if (materialSections) materialSections();

  if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen) && !scene.lights.empty()) {
    selection.light = std::min<std::size_t>(selection.light, scene.lights.size() - 1);
    const float rows = float(std::min<std::size_t>(scene.lights.size(), kListRows));
    if (ImGui::BeginListBox("##lights", ImVec2(-FLT_MIN, listHeight(rows)))) {
      for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (ImGui::Selectable(itemLabel(scene.lights[i].name, "light", i).c_str(), i == selection.light)) {
          selection.light = i;
        }
      }
      ImGui::EndListBox();
    }
    ImGui::PushID("light");
    edits.lights |= drawLight(scene.lights[selection.light], 0.002f * sceneSize);
    ImGui::PopID();
  }

  if (ImGui::CollapsingHeader("Controls")) {
    ImGui::TextUnformatted(
        "left drag: orbit    shift+left / middle drag: pan\n"
        "wheel: zoom         right drag: look, + WASD/QE: fly\n"
        "R / Home: reset view    F1 / Tab: panel\n"
        "F12 / P: screenshot     Esc: quit");
  }
  ImGui::PopItemWidth();
  ImGui::End();
  return edits;
}

}  // namespace raylab
