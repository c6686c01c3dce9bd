# Proves "drop the headers in": compiles samples/math-only/main.cpp with the C++ compiler and
# nothing but `-I include` (GLM from the system include path), with warnings as errors, runs it
# and checks its output. Also compiles every math header on its own (each is self-contained).
# Inputs: SNELL_SOURCE_DIR, WORK_DIR, CXX_COMPILER.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(flags -std=c++17 -Wall -Wextra -Wpedantic -Werror)

execute_process(
  COMMAND "${CXX_COMPILER}" ${flags} -I "${SNELL_SOURCE_DIR}/include"
          "${SNELL_SOURCE_DIR}/samples/math-only/main.cpp" -o "${WORK_DIR}/math-only"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compiling samples/math-only with only -I include failed:\n${out}")
endif()
execute_process(COMMAND "${WORK_DIR}/math-only" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "samples/math-only exited with ${rc}:\n${out}")
endif()
foreach(expected "mirrored eye" "oblique_projection" "Fresnel reflectance" "critical angle")
  string(FIND "${out}" "${expected}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "samples/math-only output lacks '${expected}':\n${out}")
  endif()
endforeach()

file(GLOB headers "${SNELL_SOURCE_DIR}/include/snell/math/*.hpp")
list(APPEND headers "${SNELL_SOURCE_DIR}/include/snell/math.hpp")
foreach(header IN LISTS headers)
  get_filename_component(name "${header}" NAME_WE)
  file(WRITE "${WORK_DIR}/${name}.cpp" "#include \"${header}\"\n")
  execute_process(
    COMMAND "${CXX_COMPILER}" ${flags} -fsyntax-only "${WORK_DIR}/${name}.cpp"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${header} does not compile on its own:\n${out}")
  endif()
endforeach()
list(LENGTH headers n)
message(STATUS "math-only sample and ${n} headers compile with only -I include")
