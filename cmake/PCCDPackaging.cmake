# Packaging: a pkg-config file (pccd.pc) beside the CMake package config, and CPack's Debian package
# libpccd-dev: the headers, the CMake config, pccd.pc and, when built, the `pccd` tool.
#   cmake --build build && (cd build && cpack -G DEB)        # -> build/libpccd-dev_<version>_<arch>.deb
# test/install_consumer/run_deb_consumer.cmake unpacks it and builds consumers with find_package(PCCD)
# and with pkg-config (ctest: install_deb_consumer).

# pccd.pc, relocatable (prefix found from the file's own place): installed into share/pkgconfig
# since the library is header-only.
set(PCCD_PC_REQUIRES "eigen3 nanoflann")
set(PCCD_PC_CFLAGS "")
if(TBB_FOUND)
  string(APPEND PCCD_PC_REQUIRES " tbb")
  set(PCCD_PC_CFLAGS " -DPCCD_HAS_TBB")
endif()
file(WRITE ${PROJECT_BINARY_DIR}/pccd.pc
"prefix=\${pcfiledir}/../..
includedir=\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}

Name: PCCD
Description: ${PROJECT_DESCRIPTION} (header-only, C++20; Boost.Graph headers are needed too)
Version: ${PROJECT_VERSION}
Requires: ${PCCD_PC_REQUIRES}
Cflags: -I\${includedir}${PCCD_PC_CFLAGS}
")
install(FILES ${PROJECT_BINARY_DIR}/pccd.pc DESTINATION ${CMAKE_INSTALL_DATADIR}/pkgconfig)

set(CPACK_PACKAGE_NAME "libpccd-dev")
set(CPACK_PACKAGE_VENDOR "PCCD")
set(CPACK_PACKAGE_CONTACT "PCCD maintainers <pccd@localhost>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "PCCD answers whether two point clouds touch, and where, without reconstructing a mesh: a smooth implicit surface over each cloud, intersected stochastically. Header-only C++20 library with CMake and pkg-config files, and the pccd command-line tool.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "libdevel")
set(CPACK_DEBIAN_PACKAGE_LICENSE "BSD-3-Clause")
# The headers need these; the tool's shared libraries are found by dpkg-shlibdeps.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libeigen3-dev, libboost-graph-dev, libnanoflann-dev")
if(TBB_FOUND)
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", libtbb-dev")
endif()
# libcgal-dev: for PCCD/IO and PCCD/Exact; libcgal-demo: the scanned meshes of pccd demo.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libcgal-dev, libcgal-demo")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_SOURCE_IGNORE_FILES "/build.*/;/\\\\.git/")
include(CPack)
