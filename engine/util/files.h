// Small file-system helpers whose errors name the file.
#pragma once

#include <string>

namespace raylab {

// Creates the directories above `path` so that it can be written.
void createParentDirectories(const std::string& path);

// The whole file; throws Error naming the path when it cannot be read.
std::string readTextFile(const std::string& path);

}  // namespace raylab
