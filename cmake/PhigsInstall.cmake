# Install rules and the CMake package: `cmake --install build --prefix P` puts the public
# headers under P/include, the libraries under P/lib, and phigsConfig.cmake, its version file
# and the exported targets (namespace phigs::) under P/lib/cmake/phigs. The static libraries
# an installed one links (shaders inside phigs_vk) are installed and exported with it.
include(CMakePackageConfigHelpers)
set(PHIGS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/phigs)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/geom/include/ ${PROJECT_SOURCE_DIR}/phigs/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
set(phigs_installed geom shaders phigs phigs_hardcopy)
foreach(target IN ITEMS phigs_vk phigs_window)
  if(TARGET ${target})
    list(APPEND phigs_installed ${target})
  endif()
endforeach()
install(TARGETS ${phigs_installed} EXPORT phigsTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT phigsTargets NAMESPACE phigs:: DESTINATION ${PHIGS_CMAKE_DIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/geom/exchange/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(TARGETS geom_exchange EXPORT phigsExchangeTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT phigsExchangeTargets NAMESPACE phigs:: DESTINATION ${PHIGS_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/phigsConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/phigsConfig.cmake INSTALL_DESTINATION ${PHIGS_CMAKE_DIR})
# 0.x: no compatibility promise between minor versions yet.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/phigsConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/phigsConfig.cmake ${PROJECT_BINARY_DIR}/phigsConfigVersion.cmake
        DESTINATION ${PHIGS_CMAKE_DIR})
