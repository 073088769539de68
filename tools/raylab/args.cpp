#include "args.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "util/error.h"

namespace raylab {

ArgParser::ArgParser(std::string command, std::string synopsis, std::string summary)
    : command_(std::move(command)), synopsis_(std::move(synopsis)), summary_(std::move(summary)) {}

void ArgParser::fail(const std::string& message) const {
  throw Error(command_ + ": " + message + " (see `" + command_ + " --help`)", kExitUsage);
}

void ArgParser::flag(const std::string& name, bool* value, const std::string& help) {
  options_.push_back({name, "", help, [value](const std::string&) { *value = true; }});
}

void ArgParser::option(const std::string& name, std::string* value, const std::string& metavar,
                       const std::string& help) {
  options_.push_back({name, metavar, help, [value](const std::string& text) { *value = text; }});
}

void ArgParser::option(const std::string& name, std::uint32_t* value, const std::string& help, std::uint32_t min,
                       std::uint32_t max) {
  const std::string range = " [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  options_.push_back({name, "N", help + range, [this, name, value, min, max](const std::string& text) {
                        char* end = nullptr;
                        errno = 0;
                        const unsigned long long parsed = std::strtoull(text.c_str(), &end, 10);
                        if (text.empty() || *end != '\0' || errno != 0 || text[0] == '-') {
                          fail(name + ": expected a whole number, got '" + text + "'");
                        }
                        if (parsed < min || parsed > max) {
                          fail(name + ": " + text + " is outside [" + std::to_string(min) + ", " +
                               std::to_string(max) + "]");
                        }
                        *value = static_cast<std::uint32_t>(parsed);
                      }});
}

void ArgParser::option(const std::string& name, std::optional<std::uint32_t>* value, const std::string& help) {
  options_.push_back({name, "N", help, [this, name, value](const std::string& text) {
                        char* end = nullptr;
                        errno = 0;
                        const unsigned long parsed = std::strtoul(text.c_str(), &end, 10);
                        if (text.empty() || *end != '\0' || errno != 0 || text[0] == '-' || parsed > UINT32_MAX) {
                          fail(name + ": expected a whole number, got '" + text + "'");
                        }
                        *value = static_cast<std::uint32_t>(parsed);
                      }});
}

float ArgParser::parseNumber(const std::string& name, const std::string& text, float min, float max) const {
  char* end = nullptr;
  const float parsed = std::strtof(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(parsed)) fail(name + ": expected a finite number, got '" + text + "'");
  if (parsed < min || parsed > max) {
    char bounds[64];
    std::snprintf(bounds, sizeof bounds, "[%g, %g]", min, max);
    fail(name + ": " + text + " is outside " + bounds);
  }
  return parsed;
}

void ArgParser::numberOption(const std::string& name, const std::string& help, float min, float max,
                             std::function<void(float)> store) {
  char range[64];
  std::snprintf(range, sizeof range, " [%g, %g]", min, max);
  options_.push_back({name, "X", help + range, [this, name, min, max, store](const std::string& text) {
                        store(parseNumber(name, text, min, max));
                      }});
}

void ArgParser::option(const std::string& name, float* value, const std::string& help, float min, float max) {
  numberOption(name, help, min, max, [value](float parsed) { *value = parsed; });
}

void ArgParser::option(const std::string& name, std::optional<float>* value, const std::string& help, float min,
                       float max) {
  numberOption(name, help, min, max, [value](float parsed) { *value = parsed; });
}

void ArgParser::choice(const std::string& name, std::string* value, const std::vector<std::string>& choices,
                       const std::string& help) {
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : "|") + c;
  options_.push_back({name, list, help, [this, name, value, choices, list](const std::string& text) {
                        for (const std::string& c : choices) {
                          if (c == text) {
                            *value = text;
                            return;
                          }
                        }
                        fail(name + ": '" + text + "' is not one of " + list);
                      }});
}

void ArgParser::positional(const std::string& name, std::string* value, const std::string& help) {
  positionals_.push_back({name, help, value});
}

bool ArgParser::parse(int argc, char** argv) {
  std::size_t nextPositional = 0;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::fputs(help().c_str(), stdout);
      return false;
    }
    if (arg.rfind("--", 0) == 0) {
      const std::size_t equals = arg.find('=');
      const std::string name = arg.substr(0, equals);
      const Option* option = nullptr;
      for (const Option& candidate : options_) {
        if (candidate.name == name) option = &candidate;
      }
      if (option == nullptr) fail("unknown option " + name);
      if (option->metavar.empty()) {
        if (equals != std::string::npos) fail(name + " takes no value");
        option->set("");
      } else if (equals != std::string::npos) {
        option->set(arg.substr(equals + 1));
      } else {
        if (i + 1 >= argc) fail(name + ": missing value (" + option->metavar + ")");
        option->set(argv[++i]);
      }
      continue;
    }
    if (nextPositional >= positionals_.size()) fail("unexpected argument '" + arg + "'");
    *positionals_[nextPositional++].value = arg;
  }
  return true;
}

std::string ArgParser::help() const {
  std::string text = "Usage: " + command_ + " " + synopsis_ + "\n\n" + summary_ + "\n";
  if (!positionals_.empty()) {
    text += "\nArguments:\n";
    for (const Positional& p : positionals_) {
      char line[512];
      std::snprintf(line, sizeof line, "  %-24s %s\n", p.name.c_str(), p.help.c_str());
      text += line;
    }
  }
  text += "\nOptions:\n";
  for (const Option& option : options_) {
    const std::string left = option.name + (option.metavar.empty() ? "" : " " + option.metavar);
    char line[1024];
    if (left.size() > 24) {
      std::snprintf(line, sizeof line, "  %s\n  %-24s %s\n", left.c_str(), "", option.help.c_str());
    } else {
      std::snprintf(line, sizeof line, "  %-24s %s\n", left.c_str(), option.help.c_str());
    }
    text += line;
  }
  text += "  --help                   show this help and exit\n";
  return text;
}

}  // namespace raylab
