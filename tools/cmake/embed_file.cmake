# Turns any file into a C++ source holding its bytes (the built-in default scene's glTF text).
# Usage: cmake -DIN=file -DOUT=out.cpp -DSYMBOL=kShowcaseGltf -P embed_file.cmake
file(READ "${IN}" hex HEX)
string(REGEX REPLACE "(..)" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "(([^,]*,){16})" "\\1\n    " bytes "${bytes}")
file(WRITE "${OUT}.tmp"
"// Generated from ${IN} by tools/cmake/embed_file.cmake; do not edit.
#include <string_view>
namespace raylab::embedded {
namespace {
const char kBytes[] = {
    ${bytes}
};
}  // namespace
std::string_view ${SYMBOL}() { return {kBytes, sizeof(kBytes)}; }
}  // namespace raylab::embedded
")
file(RENAME "${OUT}.tmp" "${OUT}")
