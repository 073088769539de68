#include "util/files.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace raylab {

void createParentDirectories(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(parent, error);
  if (error) throw Error(path + ": cannot create directory " + parent.string() + ": " + error.message());
}

std::string readTextFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(path + ": cannot open file");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace raylab
