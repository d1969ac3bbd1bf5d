# What `cmake --install` puts in place: libprism, its headers, the prism
# command, the format plugins (plugins/CMakeLists.txt), a CMake package
# (find_package(prism) with the imported target prism::prism) and prism.pc.
# tests/install/install_test.cmake installs into a temporary prefix and builds
# examples/ against it. Components: runtime (the library and plugins: all the
# Python package ships, pyproject.toml), development (headers, CMake package,
# prism.pc) and cli (the prism command).
include(CMakePackageConfigHelpers)

install(TARGETS prism EXPORT prismTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS prism_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
install(FILES include/prism.h ${CMAKE_BINARY_DIR}/include/prism_config.h TYPE INCLUDE COMPONENT development)

set(PRISM_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/prism)
install(EXPORT prismTargets NAMESPACE prism:: DESTINATION ${PRISM_CMAKE_INSTALL_DIR} COMPONENT development)
configure_package_config_file(cmake/prismConfig.cmake.in ${CMAKE_BINARY_DIR}/cmake/prismConfig.cmake
  INSTALL_DESTINATION ${PRISM_CMAKE_INSTALL_DIR})
# 0.x: a minor release may change the C API, so only the same minor version matches.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/prismConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/prismConfig.cmake ${CMAKE_BINARY_DIR}/cmake/prismConfigVersion.cmake
  DESTINATION ${PRISM_CMAKE_INSTALL_DIR} COMPONENT development)

# Relocatable: the prefix is found from the .pc file's own folder, so a package
# installed with `cmake --install --prefix P` anywhere describes itself rightly.
file(RELATIVE_PATH PRISM_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" PRISM_PC_TO_PREFIX "${PRISM_PC_TO_PREFIX}")
configure_file(cmake/prism.pc.in ${CMAKE_BINARY_DIR}/cmake/prism.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/cmake/prism.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)
