# Install rules and the CMake package, so that an integrator's own project can do
#
#   find_package(hush CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE hush::graph hush::shaders)   # hush::graph brings hush::rhi
#
#   target_link_libraries(app PRIVATE hush::c)                      # or the C API (hush/hush.h)
#
# Installed: the static libraries, their public headers, the C API's libhush.so with
# hush/hush.h and hush/hush_vulkan.h, <libdir>/pkgconfig/hush.pc (for
# `pkg-config --cflags --libs hush`), the `hush` CLI, and
# <libdir>/cmake/hush/{hushConfig,hushConfigVersion,hushTargets}.cmake.
# tests/consumer proves it by building a small project against an installed tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HUSH_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/hush"
    CACHE STRING "Where the hush CMake package files are installed, relative to the prefix")

# Consumers see hush::core, hush::rhi, hush::graph, hush::passes and hush::shaders (each target sets its EXPORT_NAME).
install(TARGETS hush_core hush_rhi hush_graph hush_shaders hush_passes hush_c
  EXPORT hushTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
# (The include directory reaches consumers through each target's own
# $<INSTALL_INTERFACE:include>, set in rhi/ and shaders/.)

# Public headers keep their <hush/<layer>/...> paths.
foreach(layer_include IN ITEMS core/include rhi/include graph/include passes/include shaders/include capi/include)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${layer_include}/hush"
          DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
          FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
endforeach()

install(FILES "${PROJECT_BINARY_DIR}/hush.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")

if(TARGET hush)
  install(TARGETS hush RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()

install(EXPORT hushTargets
  NAMESPACE hush::
  FILE hushTargets.cmake
  DESTINATION "${HUSH_INSTALL_CMAKEDIR}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/hushConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/hushConfig.cmake"
  INSTALL_DESTINATION "${HUSH_INSTALL_CMAKEDIR}")
# 0.x: minor versions may break the API, so only the same minor version matches.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/hushConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/hushConfig.cmake" "${PROJECT_BINARY_DIR}/hushConfigVersion.cmake"
        DESTINATION "${HUSH_INSTALL_CMAKEDIR}")
