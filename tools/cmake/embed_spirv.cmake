# Turns a SPIR-V binary into a C++ source holding its words, so raylab runs from any directory.
# Usage: cmake -DSPV=in.spv -DOUT=out.cpp -DNAME=render.comp -DSYMBOL=kSpirv_render_comp -P embed_spirv.cmake
file(READ "${SPV}" hex HEX)
string(LENGTH "${hex}" hexLength)
math(EXPR remainder "${hexLength} % 8")
if(hexLength EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${SPV} is not a SPIR-V binary (size is not a whole number of 32-bit words)")
endif()
# SPIR-V words are stored little-endian; rebuild each word from its four bytes.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u," words "${hex}")
string(REGEX REPLACE "(([^,]*,){8})" "\\1\n    " words "${words}")
file(WRITE "${OUT}.tmp"
"// Generated from ${NAME} by tools/cmake/embed_spirv.cmake; do not edit.
#include <cstdint>
#include <span>
namespace raylab::embedded {
extern const std::uint32_t ${SYMBOL}[];
const std::uint32_t ${SYMBOL}[] = {
    ${words}
};
std::span<const std::uint32_t> ${SYMBOL}Words() { return {${SYMBOL}, sizeof(${SYMBOL}) / 4}; }
}  // namespace raylab::embedded
")
file(RENAME "${OUT}.tmp" "${OUT}")
