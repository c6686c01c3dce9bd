# cmake -P helper: writes a SPIR-V binary (INPUT) as a C++ array (OUTPUT) named NAMESPACE::SYMBOL
# (see SnellShaders.cmake). The words are in an anonymous namespace, so the generated files of
# different targets never clash; only the span NAMESPACE::SYMBOL is an external symbol.
foreach(_var IN ITEMS INPUT OUTPUT SYMBOL NAMESPACE)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "SnellEmbedSpirv.cmake: -D${_var}=... is required")
  endif()
endforeach()
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" n)
math(EXPR rem "${n} % 8")
if(n EQUAL 0 OR NOT rem EQUAL 0)
  message(FATAL_ERROR "${INPUT}: not a SPIR-V binary (size not a multiple of 4 bytes)")
endif()
# Little-endian words: bytes b0 b1 b2 b3 -> 0xb3b2b1b0.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u," words "${hex}")
string(REGEX REPLACE "(0x........u,0x........u,0x........u,0x........u,0x........u,0x........u,)"
       "\\1\n" words "${words}")
file(WRITE "${OUTPUT}" "// Generated from ${INPUT}\n#include <cstdint>\n#include <span>\n"
     "namespace ${NAMESPACE} {\nnamespace {\nconst std::uint32_t words[] = {\n${words}};\n}\n"
     "extern const std::span<const std::uint32_t> ${SYMBOL};\n"
     "const std::span<const std::uint32_t> ${SYMBOL}{words};\n} // namespace ${NAMESPACE}\n")
