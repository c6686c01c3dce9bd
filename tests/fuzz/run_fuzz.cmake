# Builds and runs the glTF fuzzer (see CMakeLists.txt in this folder). Fails when the fuzzer
# reports a crash, a sanitizer error, a leak, a time-out or an out-of-memory; prints
# SNELL_FUZZ_SKIPPED (which CTest reports as a skip) when clang++ or libFuzzer is missing.
#
# Variables: SNELL_SOURCE_DIR (required), WORK_DIR (required), GEN and MAKE_PROGRAM (CMake
# generator of the sub-build; default Ninja), FUZZ_SECONDS (default 30).
cmake_minimum_required(VERSION 3.25)
foreach(_var SNELL_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_fuzz.cmake: -D${_var}=... is required")
  endif()
endforeach()
if(NOT DEFINED FUZZ_SECONDS)
  set(FUZZ_SECONDS 30)
endif()
if(NOT DEFINED GEN OR GEN STREQUAL "")
  set(GEN Ninja)
endif()

find_program(CLANGXX NAMES clang++ clang++-14 clang++-15 clang++-16)
if(NOT CLANGXX)
  message("SNELL_FUZZ_SKIPPED: clang++ not found (Debian: apt-get install clang libclang-rt-14-dev)")
  return()
endif()

set(_src "${SNELL_SOURCE_DIR}/tests/fuzz")
set(_build "${WORK_DIR}/build")
set(_make_arg)
if(DEFINED MAKE_PROGRAM AND NOT MAKE_PROGRAM STREQUAL "")
  set(_make_arg "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} -S "${_src}" -B "${_build}" -G "${GEN}" ${_make_arg}
          -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_BUILD_TYPE=
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
if(NOT _rc EQUAL 0)
  if(_out MATCHES "SNELL_FUZZ_NO_LIBFUZZER")
    message("SNELL_FUZZ_SKIPPED: ${CLANGXX} has no libFuzzer (Debian: libclang-rt-14-dev)")
    return()
  endif()
  message(FATAL_ERROR "configuring the fuzzer failed:\n${_out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${_build}"
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "building the fuzzer failed:\n${_out}")
endif()

# The working corpus lives in the build tree (libFuzzer adds the inputs it finds interesting to
# it, so later runs start where earlier ones stopped); the committed seeds are copied in.
set(_corpus "${WORK_DIR}/corpus")
set(_artifacts "${WORK_DIR}/artifacts")
file(MAKE_DIRECTORY "${_corpus}")
file(REMOVE_RECURSE "${_artifacts}")
file(MAKE_DIRECTORY "${_artifacts}")
file(GLOB _seeds "${_src}/corpus/*")
file(COPY ${_seeds} DESTINATION "${_corpus}")

message(STATUS "fuzzing the glTF loader for ${FUZZ_SECONDS} s (corpus ${_corpus})")
execute_process(
  COMMAND "${_build}/gltf_fuzzer" -max_total_time=${FUZZ_SECONDS} -rss_limit_mb=2048 -timeout=10
          -print_final_stats=1 "-dict=${_src}/gltf.dict" "-artifact_prefix=${_artifacts}/"
          "${_corpus}"
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
string(REGEX MATCHALL "stat::[a-z_]+: *[0-9]+" _stats "${_out}")
foreach(_stat IN LISTS _stats)
  message(STATUS "${_stat}")
endforeach()
if(NOT _rc EQUAL 0)
  file(GLOB _found "${_artifacts}/*")
  string(LENGTH "${_out}" _len)
  if(_len GREATER 12000)
    math(EXPR _from "${_len} - 12000")
    string(SUBSTRING "${_out}" ${_from} -1 _out)
  endif()
  message(FATAL_ERROR "the glTF fuzzer found a problem (exit code ${_rc}).\n"
                      "Reproduce with: ${_build}/gltf_fuzzer <file>\nInputs: ${_found}\n"
                      "Output (tail):\n${_out}")
endif()
message(STATUS "no crash found")
