# Writing a plugin outside Snell's tree, as a user would (CTest: consumer.plugin_template):
#   cmake -DSNELL_SOURCE_DIR=<snell> -DWORK_DIR=<scratch> [-DGEN=] [-DMAKE_PROGRAM=]
#         [-DCXX_COMPILER=] -P run_plugin_template.cmake
# Copies tests/plugin_template/probe_mirror (a mirror quad built only from the plugin toolkit)
# into WORK_DIR/plugins, configures Snell with -DSNELL_PLUGIN_DIRS=WORK_DIR/plugins, builds the
# plugin's own test and runs it (a pixel probe of a marker's mirror image, validation on).
# Snell's source tree is not touched: the plugin exists only in the scratch folder.
cmake_minimum_required(VERSION 3.25)
foreach(_var IN ITEMS SNELL_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "run_plugin_template.cmake: -D${_var}=... is required")
  endif()
endforeach()

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    list(JOIN ARGN " " cmdline)
    message(FATAL_ERROR "plugin template: ${name} failed (${rc}): ${cmdline}\n${out}\n${err}")
  endif()
  set(STEP_OUTPUT "${out}" PARENT_SCOPE)
endfunction()

set(_plugins "${WORK_DIR}/plugins")
set(_build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${_plugins}")
file(MAKE_DIRECTORY "${_plugins}")
file(COPY "${CMAKE_CURRENT_LIST_DIR}/probe_mirror" DESTINATION "${_plugins}")

set(_args -DCMAKE_BUILD_TYPE=Release -DSNELL_BUILD_SAMPLES=OFF -DSNELL_INSTALL=OFF
          -DSNELL_BUILD_TESTS=ON "-DSNELL_PLUGIN_DIRS=${_plugins}")
if(GEN)
  list(APPEND _args -G "${GEN}")
endif()
if(MAKE_PROGRAM)
  list(APPEND _args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
if(CXX_COMPILER)
  list(APPEND _args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
run_step("configure Snell with the plugin folder"
  ${CMAKE_COMMAND} -S "${SNELL_SOURCE_DIR}" -B "${_build}" ${_args})
run_step("build the plugin's test"
  ${CMAKE_COMMAND} --build "${_build}" --target snell_probe_mirror_tests)
set(_exe "${_build}/plugins/external/probe_mirror/snell_probe_mirror_tests")
run_step("run the plugin's test" ${CMAKE_COMMAND} -E env SNELL_VALIDATION=1 "${_exe}")
message(STATUS "plugin template passed:\n${STEP_OUTPUT}")
