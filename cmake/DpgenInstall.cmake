# Install rules and the exported CMake package. After `cmake --install`,
# find_package(dpgen CONFIG) gives dpgen::dpgen (the tool, an imported
# executable), dpgen::runtime (the header-only runtime, with annotate.hpp) and
# dpgen_add_adjoints() (DpgenAdjoints.cmake), which runs the installed tool.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(DPGEN_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/dpgen
    CACHE STRING "Where dpgenConfig.cmake is installed (relative to the prefix)")

install(TARGETS dpgen dpgen_runtime EXPORT dpgenTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/include/dpgen
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT dpgenTargets NAMESPACE dpgen:: FILE dpgenTargets.cmake
        DESTINATION ${DPGEN_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dpgenConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dpgenConfig.cmake INSTALL_DESTINATION ${DPGEN_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the annotation or signature contract.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dpgenConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dpgenConfig.cmake ${PROJECT_BINARY_DIR}/dpgenConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/DpgenAdjoints.cmake
        DESTINATION ${DPGEN_INSTALL_CMAKEDIR})
