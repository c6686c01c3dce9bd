# Per-target warning flags for Snell's own targets. Never applied globally, so projects that
# embed Snell keep their own flags.
#
#   snell_target_warnings(<target>)
#
# Adds PRIVATE warnings (-Wall -Wextra -Wpedantic, or /W4 for MSVC-like compilers) and, when
# SNELL_WARNINGS_AS_ERRORS is ON (the default when Snell is the top-level project), -Werror / /WX.
# Sanitizers are not set here: they come from the `asan` preset (CMAKE_CXX_FLAGS of the
# top-level build only).
include_guard(GLOBAL)

function(snell_target_warnings target)
  if(NOT TARGET ${target})
    message(FATAL_ERROR "snell_target_warnings: '${target}' is not a target")
  endif()
  if(MSVC)
    set(_flags /W4)
    if(SNELL_WARNINGS_AS_ERRORS)
      list(APPEND _flags /WX)
    endif()
  elseif(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    set(_flags -Wall -Wextra -Wpedantic)
    if(SNELL_WARNINGS_AS_ERRORS)
      list(APPEND _flags -Werror)
    endif()
  else()
    set(_flags)
  endif()
  target_compile_options(${target} PRIVATE ${_flags})
endfunction()
