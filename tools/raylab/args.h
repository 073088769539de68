// A small command-line parser for raylab's subcommands: `--name value`, `--name=value`, flags, positionals,
// ranges checked on the spot, and --help generated from the declarations. Errors throw Error(kExitUsage)
// naming the option.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

class ArgParser {
 public:
  // `command`: "raylab render"; `synopsis`: "[SCENE] [options]"; `summary`: one paragraph.
  ArgParser(std::string command, std::string synopsis, std::string summary);

  void flag(const std::string& name, bool* value, const std::string& help);
  void option(const std::string& name, std::string* value, const std::string& metavar, const std::string& help);
  void option(const std::string& name, std::uint32_t* value, const std::string& help, std::uint32_t min,
              std::uint32_t max);
  void option(const std::string& name, std::optional<std::uint32_t>* value, const std::string& help);
  void option(const std::string& name, float* value, const std::string& help, float min, float max);
  void option(const std::string& name, std::optional<float>* value, const std::string& help, float min, float max);
  // One of `choices`.
  void choice(const std::string& name, std::string* value, const std::vector<std::string>& choices,
              const std::string& help);
  void positional(const std::string& name, std::string* value, const std::string& help);

  // False when --help was asked for (and printed); the caller then exits 0.
  bool parse(int argc, char** argv);
  std::string help() const;

 private:
  struct Option {
    std::string name;
    std::string metavar;  // empty for flags
    std::string help;
    std::function<void(const std::string&)> set;
  };
  struct Positional {
    std::string name;
    std::string help;
    std::string* value;
  };
  [[noreturn]] void fail(const std::string& message) const;
  // A finite number in [min, max], or fail() naming the option.
  float parseNumber(const std::string& name, const std::string& text, float min, float max) const;
  // An option taking such a number, which `store` keeps.
  void numberOption(const std::string& name, const std::string& help, float min, float max,
                    std::function<void(float)> store);

  std::string command_;
  std::string synopsis_;
  std::string summary_;
  std::vector<Option> options_;
  std::vector<Positional> positionals_;
};

}  // namespace raylab
