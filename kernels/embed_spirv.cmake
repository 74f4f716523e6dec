# cmake -DINPUT=x.spv -DOUTPUT=x_spv.h -DNAME=x -P embed_spirv.cmake
# Writes a header holding the SPIR-V words of INPUT as meshquilt::kernels::spirv::NAME.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" length)
math(EXPR remainder "${length} % 8")
if(length EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${INPUT}: not a SPIR-V module (size is not a whole number of words)")
endif()
# SPIR-V words are little-endian in the file: reverse the bytes of each word.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u, " words "${hex}")
# Eight words a line (CMake regexes have no {n} repetition).
string(REPEAT "[^ ]+ " 8 eight)
string(REGEX REPLACE "(${eight})" "\\1\n  " words "${words}")
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${NAME}.comp by embed_spirv.cmake; do not edit.\n"
  "#pragma once\n#include <cstdint>\n\n"
  "namespace meshquilt::kernels::spirv {\n"
  "inline constexpr std::uint32_t ${NAME}[] = {\n  ${words}\n};\n"
  "}  // namespace meshquilt::kernels::spirv\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
