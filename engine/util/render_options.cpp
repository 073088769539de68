#include "util/render_options.h"

#include "util/error.h"

namespace raylab {

std::string choiceList(const ChoiceOption& option) {
  std::string list;
  for (std::size_t i = 0; i < option.values.size(); ++i) {
    if (i > 0) list += i + 1 == option.values.size() ? " or " : ", ";
    list += option.values[i];
  }
  return list;
}

std::size_t choiceIndex(const ChoiceOption& option, std::string_view value, const std::string& where) {
  for (std::size_t i = 0; i < option.values.size(); ++i) {
    if (option.values[i] == value) return i;
  }
  throw Error(where + ": " + std::string(option.name) + " is " + choiceList(option) + ", not '" + std::string(value) +
                  "'",
              kExitUsage);
}

void checkCount(const CountOption& option, std::int64_t value, const std::string& where) {
  if (value < std::int64_t(option.min) || value > std::int64_t(option.max)) {
    throw Error(where + ": " + std::string(option.name) + " must be within " + std::to_string(option.min) + ".." +
                    std::to_string(option.max) + ", not " + std::to_string(value),
                kExitUsage);
  }
}

}  // namespace raylab
