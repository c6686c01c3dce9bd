# Install rules and the relocatable CMake package `snell` (find_package(snell CONFIG)).
# Included from the root CMakeLists.txt when SNELL_INSTALL is ON.
include_guard(GLOBAL)

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SNELL_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/snell"
    CACHE STRING "Where the snell CMake package files are installed (relative to the prefix)")
mark_as_advanced(SNELL_INSTALL_CMAKEDIR)

# Public headers (math now; runtime and plugin headers later live under include/snell too).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.hpp")

# Snell's GLSL (shaders/snell/*.glsl) for hosts' own shaders: `#include "snell/probe.glsl"` with
# ${snell_GLSL_INCLUDE_DIR} (set by snellConfig.cmake) on the GLSL include path.
set(SNELL_INSTALL_GLSLDIR "${CMAKE_INSTALL_DATADIR}/snell/glsl")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/shaders/snell/"
        DESTINATION "${SNELL_INSTALL_GLSLDIR}/snell"
        FILES_MATCHING PATTERN "*.glsl")

# Targets: the math headers always; the CPU scene library and the Vulkan runtime when built.
set(_snell_install_targets snell_math)
if(TARGET snell_runtime)
  list(APPEND _snell_install_targets snell_scene snell_runtime)
endif()
# Plugins: every plugin library, snell::effects (register_builtin_effects) and their headers.
if(TARGET snell_effects)
  list(APPEND _snell_install_targets ${SNELL_PLUGIN_TARGETS} snell_effects)
  file(GLOB _snell_plugin_includes LIST_DIRECTORIES true "${PROJECT_SOURCE_DIR}/plugins/*/include")
  foreach(_dir IN LISTS _snell_plugin_includes)
    install(DIRECTORY "${_dir}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
            FILES_MATCHING PATTERN "*.hpp")
  endforeach()
endif()
install(TARGETS ${_snell_install_targets}
        EXPORT snellTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
if(TARGET snell)
  install(TARGETS snell RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()

install(EXPORT snellTargets
        NAMESPACE snell::
        DESTINATION "${SNELL_INSTALL_CMAKEDIR}"
        FILE snellTargets.cmake)

configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/snellConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/snellConfig.cmake"
  INSTALL_DESTINATION "${SNELL_INSTALL_CMAKEDIR}"
  PATH_VARS SNELL_INSTALL_GLSLDIR)

# 0.x: a minor bump may break the API, so only the same major.minor is compatible.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/snellConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)

install(FILES "${PROJECT_BINARY_DIR}/snellConfig.cmake"
              "${PROJECT_BINARY_DIR}/snellConfigVersion.cmake"
        DESTINATION "${SNELL_INSTALL_CMAKEDIR}")
