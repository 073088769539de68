// OpenEXR files raylab's own writer refuses to make (NaN and infinite pixels), written with OpenEXR directly, so
// that the readers' refusals can be tested.
#pragma once

#include <string>

#include "image/image.h"

namespace raylab::test {

// Writes `image` as float RGBA, non-finite values included; not atomic, no checks.
void writeExrUnchecked(const std::string& path, const Image& image);

}  // namespace raylab::test
