// `raylab brdf eval` as users and scripts run it: help, both backends on a committed CSV (they agree, and
// match values known in closed form), malformed rows reported with line and field while the other rows are
// still written, usage errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"
#include "util/files.h"

namespace raylab::test {
namespace {

const std::string kData = std::string(RAYLAB_SOURCE_DIR) + "/tests/data/brdf/";

std::string scratchDir() {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raylab_brdf_cli_test";
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::istringstream stream(text);
  for (double x; stream >> x;) values.push_back(x);
  return values;
}

// "id/quantity" -> value text, from an output file; checks the header and the echoed columns.
std::map<std::string, std::string> readValues(const std::string& path) {
  const std::vector<std::string> lines = splitLines(readInputFile(path, kMaxCaseFileBytes));
  std::map<std::string, std::string> values;
  EXPECT_FALSE(lines.empty()) << path;
  if (lines.empty()) return values;
  EXPECT_EQ(lines[0], "id,model,params,wi,wo,n,t,quantity,value");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> fields = splitFields(lines[i]);
    EXPECT_EQ(fields.size(), 9u) << lines[i];
    if (fields.size() == 9) values[fields[0] + "/" + fields[7]] = fields[8];
  }
  return values;
}

TEST(BrdfCliTest, HelpDescribesTheSubcommands) {
  const CommandResult top = runRaylab({"--help"});
  EXPECT_NE(top.output.find("brdf"), std::string::npos) << top.output;
  const CommandResult brdf = runRaylab({"brdf", "--help"});
  EXPECT_EQ(brdf.exitCode, 0) << brdf.output;
  EXPECT_NE(brdf.output.find("Usage: raylab brdf"), std::string::npos) << brdf.output;
  EXPECT_NE(brdf.output.find("eval"), std::string::npos) << brdf.output;
  const CommandResult eval = runRaylab({"brdf", "eval", "--help"});
  EXPECT_EQ(eval.exitCode, 0) << eval.output;
  for (const char* text : {"Usage: raylab brdf eval", "--in", "--out", "--backend", "--device", "F_schlick_naive"}) {
    EXPECT_NE(eval.output.find(text), std::string::npos) << text << "\n" << eval.output;
  }
}

// The test tree's model (tests/models/minnaert.*) is registered in the README's build, which builds the tests, but
// exists only for the tests (RAYLAB_TEST_MODELS=1): a user's `brdf models`, help, messages and scenes never see it.
TEST(BrdfCliTest, TheTestTreesModelExistsOnlyForTheTests) {
  const CommandResult tests = runRaylab({"brdf", "models"}, {"RAYLAB_TEST_MODELS=1"});
  EXPECT_NE(tests.output.find("minnaert"), std::string::npos) << tests.output;
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"brdf", "models"}, {"brdf", "models", "--json"}, {"render", "--help"},
        {"render", "--material", "phong=nosuchmodel", "--out", "never.exr"}}) {
    const CommandResult user = runRaylab(command, {"RAYLAB_TEST_MODELS="});
    EXPECT_NE(user.output.find(command[0] == "render" && command[1] == "--help" ? "--material" : "lambert"), std::string::npos) << user.output;
    EXPECT_EQ(user.output.find("minnaert"), std::string::npos) << command[0] << " " << command[1] << "\n" << user.output;
  }
  const CommandResult render = runRaylab({"render", "--material", "phong=minnaert", "--width", "8", "--height", "8",
                                          "--spp", "1", "--out", "never.exr"},
                                         {"RAYLAB_TEST_MODELS="});
  EXPECT_EQ(render.exitCode, 2) << render.output;
}

TEST(BrdfCliTest, UsageErrorsExitTwoAndNameTheProblem) {
  struct Case {
    std::vector<std::string> args;
    std::string mentions;
  };
  const Case cases[] = {
      {{"brdf"}, "Usage: raylab brdf"},
      {{"brdf", "plotz"}, "plotz"},
      {{"brdf", "eval", "--out", "x.csv"}, "--in"},
      {{"brdf", "eval", "--in", kData + "cases.csv"}, "--out"},
      {{"brdf", "eval", "--in", kData + "cases.csv", "--out", "x.csv", "--backend", "fpga"}, "--backend"},
  };
  for (const Case& c : cases) {
    const CommandResult result = runRaylab(c.args);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << result.output;
  }
  const CommandResult missing = runRaylab({"brdf", "eval", "--in", "no/such/cases.csv", "--out", "x.csv", "--backend", "cpu"});
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_NE(missing.output.find("no/such/cases.csv"), std::string::npos) << missing.output;
}

TEST(BrdfCliTest, BothBackendsAgreeAndMatchClosedForms) {
  const std::string dir = scratchDir();
  std::map<std::string, std::map<std::string, std::string>> byBackend;
  for (const std::string backend : {"gpu", "cpu"}) {
    const std::string out = dir + "/nested/values_" + backend + ".csv";
    std::filesystem::remove(out);
    // Run in `dir`: raylab creates the missing nested/ only below its working directory.
    const CommandResult result =
        runRaylab({"brdf", "eval", "--in", kData + "cases.csv", "--out", out, "--backend", backend}, {}, dir);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    // The one-line timing summary: rows and the evaluation time.
    EXPECT_NE(result.output.find("15 rows (0 malformed)"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(backend == "gpu" ? "dispatch" : "evaluation"), std::string::npos) << result.output;
    byBackend[backend] = readValues(out);
  }
  const auto& gpu = byBackend["gpu"];
  const auto& cpu = byBackend["cpu"];
  // 12 BRDF rows with one f each, 3 glass rows with six quantities each.
  EXPECT_EQ(gpu.size(), 12u + 3u * 6u);
  ASSERT_EQ(gpu.size(), cpu.size());
  for (const auto& [key, gpuText] : gpu) {
    ASSERT_TRUE(cpu.count(key)) << key;
    const std::string& cpuText = cpu.at(key);
    if (gpuText == "none" || cpuText == "none") {
      EXPECT_EQ(gpuText, cpuText) << key;
      continue;
    }
    const std::vector<double> g = numbers(gpuText);
    const std::vector<double> c = numbers(cpuText);
    ASSERT_EQ(g.size(), c.size()) << key << ": " << gpuText << " vs " << cpuText;
    // The rows are ordinary cases: the library agrees with the reference to 1e-4 (tests/gpu/brdf_parity_test).
    for (std::size_t i = 0; i < g.size(); ++i) {
      EXPECT_NEAR(g[i], c[i], 1e-4 * std::max(1.0, std::abs(c[i]))) << key << ": " << gpuText << " vs " << cpuText;
    }
  }
  for (const auto* values : {&gpu, &cpu}) {
    const std::vector<double> lambert = numbers(values->at("lambert-colour/f"));
    ASSERT_EQ(lambert.size(), 3u);
    EXPECT_NEAR(lambert[0], 0.8 / M_PI, 1e-7);
    EXPECT_NEAR(lambert[2], 0.2 / M_PI, 1e-7);
    EXPECT_NEAR(numbers(values->at("lambert-defaults/f")).at(0), 0.5 / M_PI, 1e-7);  // the default rho_d
    EXPECT_NEAR(numbers(values->at("phong-mirror/f")).at(0), 12.0 / (2.0 * M_PI), 1e-5);  // (s+2)/(2 pi) at c = 1
    EXPECT_EQ(values->at("below-horizon/f"), "0");
    EXPECT_NEAR(numbers(values->at("glass-normal/F_exact")).at(0), 0.04, 1e-7);
    EXPECT_EQ(values->at("glass-normal/tir"), "0");
    const std::vector<double> refracted = numbers(values->at("glass-normal/refract"));
    ASSERT_EQ(refracted.size(), 3u);
    EXPECT_NEAR(refracted[2], -1.0, 1e-7);
    EXPECT_EQ(values->at("glass-inside-tir/tir"), "1");
    EXPECT_EQ(values->at("glass-inside-tir/refract"), "none");
    EXPECT_EQ(values->at("glass-inside-tir/F_exact"), "1");
  }
}

TEST(BrdfCliTest, MalformedRowsAreReportedWithLineAndFieldAndTheOthersWritten) {
  const std::string out = scratchDir() + "/malformed_values.csv";
  for (const std::string backend : {"gpu", "cpu"}) {
    std::filesystem::remove(out);
    const CommandResult result =
        runRaylab({"brdf", "eval", "--in", kData + "malformed.csv", "--out", out, "--backend", backend});
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const std::string file = kData + "malformed.csv";
    const std::vector<std::pair<std::string, std::string>> expected = {
        {file + ":3: field 'model'", "lambertian"},
        {file + ":4: field 'params'", "[1, 10000]"},
        {file + ":5: field 'params'", "roughness"},
        {file + ":6: field 'wi'", "0 1"},
        {file + ":7: field 'wo'", "0 0 x"},
        {file + ":8: field 'n'", "length"},
        {file + ":9: field 'wo'", "only glass"},
        {file + ":10:", "7 fields"},
        // openpbr's layers as any model's parameters: the weight, a negative depth, NaN.
        {file + ":11: field 'params'", "coat_weight = 1.5 is outside [0, 1]"},
        {file + ":12: field 'params'", "transmission_depth = -1 is outside [0, 1000]"},
        {file + ":13: field 'params'", "thin_film_weight"},
    };
    for (const auto& [where, what] : expected) {
      const std::size_t at = result.output.find(where);
      EXPECT_NE(at, std::string::npos) << where << "\n" << result.output;
      if (at != std::string::npos) {
        const std::string line = result.output.substr(at, result.output.find('\n', at) - at);
        EXPECT_NE(line.find(what), std::string::npos) << line;
      }
    }
    EXPECT_NE(result.output.find("2 rows (11 malformed)"), std::string::npos) << result.output;
    const std::map<std::string, std::string> values = readValues(out);
    EXPECT_EQ(values.size(), 1u + 6u) << backend;
    EXPECT_TRUE(values.count("good-first/f")) << backend;
    EXPECT_TRUE(values.count("good-last/F_exact")) << backend;
  }
}

}  // namespace
}  // namespace raylab::test
