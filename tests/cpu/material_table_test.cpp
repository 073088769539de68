// The BRDF parameter table is defined once, in the table each model's GLSL file opens with, from which the build
// generates the code's table (tools/cmake/brdf_registry.py). Two texts repeat it for their readers: the contract
// the code cites (docs/brdf_contract.md) and the model pages (docs/brdfs.md). This test reads both, and the GLSL
// tables as the generator's check, and requires each to name the same models with the same parameters, ranges
// and defaults as the code (and the model pages the same log scales), so that none can drift alone. Models that
// live in the test tree (tests/models) are not documented for users.
#include <gtest/gtest.h>

#include <algorithm>

#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

#include "shared/features.h"
#include "brdf_params/material_params.h"
#include "util/error.h"

namespace raylab::test {
namespace {

struct DocParam {
  std::string name;
  double min, max, defaultValue;
  std::optional<bool> logScale;  // only where the text says
};

using Table = std::map<std::string, std::vector<DocParam>>;

std::string readSource(const std::string& path) {
  std::ifstream file(std::string(RAYLAB_SOURCE_DIR) + "/" + path);
  EXPECT_TRUE(file.good()) << path << " cannot be read";
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// docs/brdf_contract.md: one row per model, `model` | `name` [min, max] = default, ...
Table contractTable() {
  const std::string text = readSource("docs/brdf_contract.md");
  Table table;
  const std::regex row(R"(^\| `(\w+)` \| (.*) \|$)");
  const std::regex param(R"(`(\w+)` \[([-0-9.e]+), ([-0-9.e]+)\] = ([-0-9.e]+))");
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch match;
    if (!std::regex_match(line, match, row)) continue;
    std::vector<DocParam>& params = table[match[1]];
    const std::string cells = match[2];
    for (std::sregex_iterator it(cells.begin(), cells.end(), param), end; it != end; ++it) {
      params.push_back({(*it)[1], std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4]), std::nullopt});
    }
  }
  return table;
}

// A row of a parameter table: | name | [min, max] ... | default | meaning |, the name possibly in backticks.
std::optional<DocParam> parameterRow(const std::string& line) {
  static const std::regex row(R"(^(?://\s*)?\|\s*`?(\w+)`?\s*\|\s*\[([-0-9.e]+), ([-0-9.e]+)\]([^|]*)\|\s*([-0-9.e]+)\s*\|)");
  std::smatch match;
  if (!std::regex_search(line, match, row)) return std::nullopt;
  const std::string after = match[4];
  std::optional<bool> logScale;
  if (after.find("log") != std::string::npos) logScale = true;
  return DocParam{match[1], std::stod(match[2]), std::stod(match[3]), std::stod(match[5]), logScale};
}

// docs/brdfs.md: a section per model (or per family: "### `ward`, `ward_duer`, ...") with a parameter table, or
// "Parameters as `other`".
Table modelPagesTable() {
  const std::string text = readSource("docs/brdfs.md");
  Table table;
  std::map<std::string, std::string> sameAs;
  std::vector<std::string> models;  // of the current section
  const std::regex name("`(\\w+)`");
  const std::regex alias("Parameters as `(\\w+)`");
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("## ", 0) == 0) models.clear();
    if (line.rfind("### ", 0) == 0) {
      models.clear();
      const std::string heading = line.substr(0, line.find(" — "));
      for (std::sregex_iterator it(heading.begin(), heading.end(), name), end; it != end; ++it) {
        if (findModel((*it)[1].str()) != nullptr) models.push_back((*it)[1]);
      }
      continue;
    }
    std::smatch match;
    if (std::regex_search(line, match, alias)) {
      for (const std::string& model : models) sameAs[model] = match[1];
    }
    if (const std::optional<DocParam> param = parameterRow(line)) {
      for (const std::string& model : models) table[model].push_back(*param);
    }
  }
  for (const auto& [model, other] : sameAs) {
    if (table[model].empty()) table[model] = table[other];
  }
  return table;
}

// The models users see: the library's, not the test tree's.
std::vector<const ModelInfo*> documentedModels() {
  std::vector<const ModelInfo*> models;
  for (const ModelInfo& model : allModels()) {
    if (!model.glslFile.starts_with("tests/")) models.push_back(&model);
  }
  return models;
}

// Each model's GLSL file: the table in the file's opening comment.
Table glslTable() {
  Table table;
  for (const ModelInfo& model : allModels()) {
    std::istringstream lines(readSource(std::string(model.glslFile)));
    std::string line;
    while (std::getline(lines, line) && line.rfind("//", 0) == 0) {
      if (const std::optional<DocParam> param = parameterRow(line)) table[std::string(model.name)].push_back(*param);
    }
  }
  return table;
}

void expectSameAsCode(const Table& table, const std::string& where, const std::vector<const ModelInfo*>& models) {
  EXPECT_EQ(table.size(), models.size()) << where << " lists another set of models";
  for (const ModelInfo* modelPointer : models) {
    const ModelInfo& model = *modelPointer;
    const auto row = table.find(std::string(model.name));
    ASSERT_NE(row, table.end()) << model.name << " is missing from " << where;
    ASSERT_EQ(row->second.size(), model.params.size()) << where << ": " << model.name;
    for (std::size_t i = 0; i < model.params.size(); ++i) {
      const ParamInfo& code = model.params[i];
      const DocParam& doc = row->second[i];
      EXPECT_EQ(doc.name, code.name) << where << ": " << model.name;
      EXPECT_FLOAT_EQ(float(doc.min), code.min) << where << ": " << model.name << "." << code.name;
      EXPECT_FLOAT_EQ(float(doc.max), code.max) << where << ": " << model.name << "." << code.name;
      EXPECT_FLOAT_EQ(float(doc.defaultValue), code.defaultValue) << where << ": " << model.name << "." << code.name;
      if (doc.logScale) {
        EXPECT_EQ(*doc.logScale, code.logScale) << where << ": " << model.name << "." << code.name;
      }
    }
  }
}

TEST(MaterialTable, TheContractsTableEqualsTheCodes) {
  expectSameAsCode(contractTable(), "docs/brdf_contract.md", documentedModels());
}

TEST(MaterialTable, TheModelPagesTablesEqualTheCodes) {
  const Table table = modelPagesTable();
  expectSameAsCode(table, "docs/brdfs.md", documentedModels());
  // The pages mark log scales: every log parameter of the code says so there.
  for (const ModelInfo* model : documentedModels()) {
    const std::vector<DocParam>& params = table.at(std::string(model->name));
    for (std::size_t i = 0; i < model->params.size() && i < params.size(); ++i) {
      EXPECT_EQ(params[i].logScale.value_or(false), model->params[i].logScale)
          << "docs/brdfs.md: " << model->name << "." << model->params[i].name << " log scale";
    }
  }
}

TEST(MaterialTable, EveryGlslModelFileOpensWithTheCodesTable) {
  std::vector<const ModelInfo*> all;
  for (const ModelInfo& model : allModels()) all.push_back(&model);
  expectSameAsCode(glslTable(), "the models' GLSL files", all);
}

// A named metal sets ggx_conductor's eta and k from its file's preset lines, before the list's other entries,
// which refine it; an unknown name lists the known ones; a preset is not a number.
TEST(MaterialTable, NamedMetalsSetEtaAndKAndTheOtherEntriesRefineThem) {
  const ModelInfo& conductor = *findModel("ggx_conductor");
  ASSERT_TRUE(isPresetKey(conductor, "metal"));
  EXPECT_FALSE(isPresetKey(conductor, "eta"));
  EXPECT_EQ(conductor.presets.size(), 5u);
  gpu::MaterialRecord record = defaultRecord(conductor.id);
  applyParamList(record, "k=1, metal=Au, alpha_x=0.3", "test");
  EXPECT_FLOAT_EQ(getParam(record, "eta").x, 0.143036f);
  EXPECT_FLOAT_EQ(getParam(record, "eta").z, 1.44205f);
  EXPECT_EQ(getParam(record, "k"), glm::vec3(1.0f)) << "the explicit k refines the preset";
  EXPECT_FLOAT_EQ(getParam(record, "alpha_x").x, 0.3f);

  std::string message;
  try {
    applyParamList(record, "metal=Unobtainium", "scene.gltf: material 2 'ring'");
  } catch (const Error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("scene.gltf: material 2 'ring': metal 'Unobtainium' is not one of ggx_conductor's "
                         "(Ag, Al, Au, Cr, Cu)"), std::string::npos) << message;
  EXPECT_THROW(applyParamList(record, "metal=Au,metal=Cu", "test"), Error) << "given twice";
  gpu::MaterialRecord lambert = defaultRecord(findModel("lambert")->id);
  EXPECT_THROW(applyParamList(lambert, "metal=Au", "test"), Error) << "lambert has no metals";
}

// The viewer groups a layered model's sliders by layer: openpbr's parameters are all LAYER_rest; gltf_pbr's are not
// (metallic, roughness), so it gets none.
TEST(MaterialTable, OnlyALayeredModelsParametersHaveLayers) {
  const ModelInfo& openpbr = *findModel("openpbr");
  EXPECT_EQ(paramLayer(openpbr, *findParam(openpbr, "coat_ior")), "coat");
  EXPECT_EQ(paramLayer(openpbr, *findParam(openpbr, "specular_roughness_anisotropy")), "specular");
  EXPECT_EQ(paramLayer(openpbr, *findParam(openpbr, "base_color")), "base");
  EXPECT_EQ(paramLayer(openpbr, *findParam(openpbr, "thin_film_ior")), "thin_film") << "a layer is the prefix with a _weight";
  const ModelInfo& gltf = *findModel("gltf_pbr");
  EXPECT_EQ(paramLayer(gltf, *findParam(gltf, "base_color")), "");
  const ModelInfo& conductor = *findModel("ggx_conductor");
  EXPECT_EQ(paramLayer(conductor, *findParam(conductor, "alpha_x")), "") << "alpha_x and alpha_y alone are no layers";
  const ModelInfo& ward = *findModel("ward");
  EXPECT_EQ(paramLayer(ward, *findParam(ward, "rho_d")), "") << "Ward's pairs rho_ and alpha_ are no layers";
}

// A model's `feature:` lines take kSpecFeatures bits above the integrators' fixed ones, each its own.
// openpbr's emission parameters are the material's emission: setting either keeps record.emission (what the
// kernels and the light list read) equal to luminance x colour, and setEmission writes them back from a radiance.
TEST(MaterialTable, AModelsOwnEmissionParametersAreTheMaterialsEmission) {
  const ModelInfo& openpbr = *findModel("openpbr");
  ASSERT_TRUE(hasOwnEmission(openpbr));
  EXPECT_FALSE(hasOwnEmission(*findModel("lambert")));
  gpu::MaterialRecord record = defaultRecord(openpbr.id);
  EXPECT_EQ(record.emission, glm::vec3(0.0f));
  setParam(record, "emission_color", glm::vec3(1.0f, 0.5f, 0.25f), "test");
  setParam(record, "emission_luminance", glm::vec3(4.0f), "test");
  EXPECT_EQ(record.emission, glm::vec3(4.0f, 2.0f, 1.0f));
  setEmission(record, glm::vec3(0.5f, 2.0f, 1.0f), "test");
  EXPECT_FLOAT_EQ(getParam(record, "emission_luminance").x, 2.0f);
  EXPECT_EQ(getParam(record, "emission_color"), glm::vec3(0.25f, 1.0f, 0.5f));
  EXPECT_EQ(record.emission, glm::vec3(0.5f, 2.0f, 1.0f));
  gpu::MaterialRecord lambert = defaultRecord(findModel("lambert")->id);
  setEmission(lambert, glm::vec3(3.0f), "test");
  EXPECT_EQ(lambert.emission, glm::vec3(3.0f)) << "a model without emission parameters keeps the radiance itself";
}

TEST(MaterialTable, ModelFeaturesHaveTheirOwnBitsAboveTheFixedFeatures) {
  std::uint32_t seen = 0;
  for (const ModelInfo& model : allModels()) {
    std::uint32_t own = 0;  // the bits of this model's features: the lines of one name share one
    for (const ModelFeature& feature : model.features) {
      EXPECT_GE(feature.bit, 1u << gpu::kFirstModelFeatureBit) << model.name << " " << feature.name;
      const bool sameNameBefore = std::any_of(model.features.begin(), model.features.end(), [&](const ModelFeature& other) {
        return &other < &feature && other.name == feature.name;
      });
      if (sameNameBefore) {
        EXPECT_NE(own & feature.bit, 0u) << model.name << " " << feature.name << ": its name's bit";
      } else {
        EXPECT_EQ(seen & feature.bit, 0u) << model.name << " " << feature.name << " shares a bit";
      }
      own |= feature.bit;
      seen |= feature.bit;
      const ParamInfo* param = findParam(model, feature.param);
      ASSERT_NE(param, nullptr) << model.name << " " << feature.name;
      EXPECT_FALSE(param->rgb);
    }
  }
  const ModelInfo& openpbr = *findModel("openpbr");
  ASSERT_EQ(openpbr.features.size(), 9u);
  EXPECT_EQ(openpbr.features[0].name, "coat");
  EXPECT_EQ(openpbr.features[0].param, "coat_weight");
  EXPECT_EQ(openpbr.features[1].name, "thin_film");
  EXPECT_EQ(openpbr.features[1].param, "thin_film_weight");
  EXPECT_EQ(openpbr.features[2].name, "fuzz");
  EXPECT_EQ(openpbr.features[2].param, "fuzz_weight");
  EXPECT_EQ(openpbr.features[3].name, "transmission");
  EXPECT_EQ(openpbr.features[3].param, "transmission_weight");
  EXPECT_EQ(openpbr.features[4].name, "thin_walled");
  EXPECT_EQ(openpbr.features[4].param, "geometry_thin_walled");
  EXPECT_EQ(openpbr.features[5].name, "dispersion");
  EXPECT_EQ(openpbr.features[5].param, "transmission_dispersion_scale");
  for (std::size_t i = 6; i < 9; ++i) {
    EXPECT_EQ(openpbr.features[i].name, "coat_frame");
    EXPECT_EQ(openpbr.features[i].bit, openpbr.features[6].bit) << "one part, one bit";
  }
  EXPECT_EQ(openpbr.features[8].param, "geometry_coat_tangent_angle");
}

}  // namespace
}  // namespace raylab::test
