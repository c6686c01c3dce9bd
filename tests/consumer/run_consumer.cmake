# Packaging test driver, run by CTest as a script:
#   cmake -DSNELL_SOURCE_DIR=<snell source> -DWORK_DIR=<scratch dir> -DMODE=find_package|add_subdirectory
#         [-DGEN=<generator>] [-DMAKE_PROGRAM=<path>] [-DCXX_COMPILER=<path>] -P run_consumer.cmake
#
# find_package:     configure Snell (tests/samples off, install on), install it into
#                   WORK_DIR/prefix, then configure, build and run tests/consumer/find_package
#                   against that prefix.
# add_subdirectory: configure, build and run tests/consumer/add_subdirectory, which embeds the
#                   Snell source tree.
cmake_minimum_required(VERSION 3.25)

foreach(_var IN ITEMS SNELL_SOURCE_DIR WORK_DIR MODE)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer.cmake: -D${_var}=... is required")
  endif()
endforeach()
if(NOT MODE MATCHES "^(find_package|add_subdirectory)$")
  message(FATAL_ERROR "run_consumer.cmake: MODE must be find_package or add_subdirectory, got '${MODE}'")
endif()

set(_consumer_src "${CMAKE_CURRENT_LIST_DIR}/${MODE}")
set(_config Release)

# Options shared by every configure step: same generator (and tools) as the outer build.
set(_common_args)
if(GEN)
  list(APPEND _common_args -G "${GEN}")
endif()
if(MAKE_PROGRAM)
  list(APPEND _common_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
if(CXX_COMPILER)
  list(APPEND _common_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
list(APPEND _common_args "-DCMAKE_BUILD_TYPE=${_config}")

# Runs one step; on failure stops with the step's name, command and output.
function(run_step name)
  list(JOIN ARGN " " _cmdline)
  message(STATUS "[${MODE}] ${name}: ${_cmdline}")
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE _rc
    OUTPUT_VARIABLE _out
    ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR
      "consumer test '${MODE}': step '${name}' failed (exit ${_rc})\n"
      "command: ${_cmdline}\n"
      "---- output ----\n${_out}\n---- end of output ----")
  endif()
  set(STEP_OUTPUT "${_out}" PARENT_SCOPE)
endfunction()

# Fresh scratch directory every run.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

set(_consumer_build "${WORK_DIR}/consumer-build")
set(_consumer_args)

if(MODE STREQUAL "find_package")
  set(_snell_build "${WORK_DIR}/snell-build")
  set(_prefix "${WORK_DIR}/prefix")
  run_step("configure snell"
    ${CMAKE_COMMAND} -S "${SNELL_SOURCE_DIR}" -B "${_snell_build}" ${_common_args}
      -DSNELL_BUILD_TESTS=OFF -DSNELL_BUILD_SAMPLES=OFF -DSNELL_INSTALL=ON)
  run_step("build snell" ${CMAKE_COMMAND} --build "${_snell_build}" --config ${_config})
  run_step("install snell"
    ${CMAKE_COMMAND} --install "${_snell_build}" --config ${_config} --prefix "${_prefix}")
  list(APPEND _consumer_args "-DCMAKE_PREFIX_PATH=${_prefix}" "-DSNELL_EXPECTED_PREFIX=${_prefix}")
else()
  list(APPEND _consumer_args "-DSNELL_SOURCE_DIR=${SNELL_SOURCE_DIR}")
endif()

run_step("configure consumer"
  ${CMAKE_COMMAND} -S "${_consumer_src}" -B "${_consumer_build}" ${_common_args} ${_consumer_args})
run_step("build consumer" ${CMAKE_COMMAND} --build "${_consumer_build}" --config ${_config})

# The consumer projects put their executable in <build>/bin (no per-config subfolder).
set(_exe "${_consumer_build}/bin/snell-consumer")
if(CMAKE_HOST_WIN32)
  string(APPEND _exe ".exe")
endif()
if(NOT EXISTS "${_exe}")
  message(FATAL_ERROR "consumer test '${MODE}': expected executable not found: ${_exe}")
endif()
run_step("run consumer" "${_exe}")
message(STATUS "[${MODE}] passed:\n${STEP_OUTPUT}")
# The runtime consumer (snell::scene + snell::runtime), built when the package has the runtime.
set(_runtime_exe "${_consumer_build}/bin/snell-consumer-runtime${CMAKE_EXECUTABLE_SUFFIX}")
if(EXISTS "${_runtime_exe}")
  run_step("run runtime consumer" "${_runtime_exe}")
  message(STATUS "[${MODE}] runtime consumer passed:\n${STEP_OUTPUT}")
endif()
# The C++17 host: water through the registry, one frame on lavapipe with validation.
set(_host17_exe "${_consumer_build}/bin/snell-consumer-host17${CMAKE_EXECUTABLE_SUFFIX}")
if(EXISTS "${_host17_exe}")
  run_step("run C++17 host consumer" "${_host17_exe}")
  message(STATUS "[${MODE}] C++17 host consumer passed:\n${STEP_OUTPUT}")
elseif(MODE STREQUAL "find_package")
  message(FATAL_ERROR "consumer test '${MODE}': the C++17 host was not built: ${_host17_exe}")
endif()
