# Test tooling, included from the root CMakeLists.txt when SNELL_BUILD_TESTS is ON, before the
# runtime and the plugins: plugins build and register their own tests (snell_add_plugin TESTS),
# so doctest and doctest_discover_tests() must exist before plugins/ is added.
include_guard(GLOBAL)

# doctestConfig.cmake appends its own directory to CMAKE_MODULE_PATH. That is directory scope:
# Snell's root and below, never a host project's. It provides doctest_discover_tests().
find_package(doctest CONFIG REQUIRED)
include(doctest)

# doctest_discover_tests() registers one CTest test per case, and CMake splits a name at ';' into
# two tests that match nothing and pass without running. Refuse such names at configure time.
#   snell_check_test_case_names(<source>...)
function(snell_check_test_case_names)
  foreach(_src IN LISTS ARGN)
    get_filename_component(_abs "${_src}" ABSOLUTE)
    file(STRINGS "${_abs}" _bad REGEX "TEST_CASE\\(\"[^\"]*;")
    if(_bad)
      message(FATAL_ERROR "${_abs}: a TEST_CASE name contains ';' (CTest would not run it): ${_bad}")
    endif()
  endforeach()
endfunction()
