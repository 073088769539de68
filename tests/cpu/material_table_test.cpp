// The BRDF parameter table exists once in code (engine/scene/material_params.cpp) and once in the contract
// the code cites (docs/brdf_contract.md). This test reads the contract's table and requires the two to name
// the same models with the same parameters, ranges and defaults, so that neither can drift alone.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "brdf_params/material_params.h"

namespace raylab::test {
namespace {

struct DocParam {
  std::string name;
  double min, max, defaultValue;
};

std::map<std::string, std::vector<DocParam>> contractTable() {
  std::ifstream file(std::string(RAYLAB_SOURCE_DIR) + "/docs/brdf_contract.md");
  std::stringstream text;
  text << file.rdbuf();
  std::map<std::string, std::vector<DocParam>> table;
  const std::regex row(R"(^\| `(\w+)` \| (.*) \|$)");
  const std::regex param(R"(`(\w+)` \[([-0-9.e]+), ([-0-9.e]+)\] = ([-0-9.e]+))");
  std::string line;
  while (std::getline(text, line)) {
    std::smatch match;
    if (!std::regex_match(line, match, row)) continue;
    std::vector<DocParam>& params = table[match[1]];
    const std::string cells = match[2];
    for (std::sregex_iterator it(cells.begin(), cells.end(), param), end; it != end; ++it) {
      params.push_back({(*it)[1], std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
    }
  }
  return table;
}

TEST(MaterialTable, TheContractsTableEqualsTheCodes) {
  const auto table = contractTable();
  ASSERT_EQ(table.size(), allModels().size()) << "docs/brdf_contract.md lists another set of models";
  for (const ModelInfo& model : allModels()) {
    const auto row = table.find(std::string(model.name));
    ASSERT_NE(row, table.end()) << model.name << " is missing from docs/brdf_contract.md";
    ASSERT_EQ(row->second.size(), model.params.size()) << model.name;
    for (std::size_t i = 0; i < model.params.size(); ++i) {
      const ParamInfo& code = model.params[i];
      const DocParam& doc = row->second[i];
      EXPECT_EQ(doc.name, code.name) << model.name;
      EXPECT_FLOAT_EQ(float(doc.min), code.min) << model.name << "." << code.name;
      EXPECT_FLOAT_EQ(float(doc.max), code.max) << model.name << "." << code.name;
      EXPECT_FLOAT_EQ(float(doc.defaultValue), code.defaultValue) << model.name << "." << code.name;
    }
  }
}

}  // namespace
}  // namespace raylab::test
