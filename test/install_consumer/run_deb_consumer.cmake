# ctest driver of install_deb_consumer: builds the libpccd-dev Debian package with CPack, unpacks it
# into a temporary root (dpkg-deb -x, nothing is installed on the machine), checks its contents,
# runs the packaged `pccd` (when the build has the tool), then builds and runs two consumers
# against the unpacked tree: the CMake project of this directory with find_package(PCCD), and the
# umbrella-header program with nothing but `pkg-config --cflags --libs pccd`.
#   cmake -DPCCD_BINARY_DIR=<build> -DWORK=<scratch dir> -DCONSUMER_SOURCE_DIR=<this dir>
#         -DUMBRELLA_PROGRAM=<test/umbrella/umbrella_program.cpp> -DCMAKE_CXX_COMPILER=<c++>
#         -DCPACK=<cpack> -DVERSION=<x.y.z> -DWITH_TOOL=<1 when the build has the pccd tool>
#         -P run_deb_consumer.cmake
function(run)
  cmake_parse_arguments(R "" "WHAT;DIR" "COMMAND" ${ARGN})
  execute_process(COMMAND ${R_COMMAND} WORKING_DIRECTORY "${R_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message("${R_WHAT}: exit ${rc}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${R_WHAT} failed (${rc})")
  endif()
  set(RUN_OUTPUT "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
run(WHAT "cpack -G DEB" DIR "${PCCD_BINARY_DIR}"
    COMMAND "${CPACK}" -G DEB -B "${WORK}/package" --config "${PCCD_BINARY_DIR}/CPackConfig.cmake")
file(GLOB debs "${WORK}/package/libpccd-dev_${VERSION}_*.deb")
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one libpccd-dev_${VERSION}_*.deb in ${WORK}/package, found ${count}")
endif()
run(WHAT "dpkg-deb -f (package name)" DIR "${WORK}" COMMAND dpkg-deb -f "${debs}" Package)
if(NOT RUN_OUTPUT MATCHES "^libpccd-dev")
  message(FATAL_ERROR "the package is not named libpccd-dev")
endif()
set(root "${WORK}/root")
run(WHAT "dpkg-deb -x" DIR "${WORK}" COMMAND dpkg-deb -x "${debs}" "${root}")
set(files usr/include/PCCD/PCCD.h usr/include/PCCD/Point_cloud.h usr/share/cmake/PCCD/PCCDConfig.cmake
          usr/share/cmake/PCCD/PCCDConfigVersion.cmake usr/share/pkgconfig/pccd.pc)
if(WITH_TOOL)
  list(APPEND files usr/bin/pccd)
endif()
foreach(file IN LISTS files)
  if(NOT EXISTS "${root}/${file}")
    message(FATAL_ERROR "the package lacks /${file}")
  endif()
endforeach()
if(WITH_TOOL)
  run(WHAT "packaged pccd --version" DIR "${WORK}" COMMAND "${root}/usr/bin/pccd" --version)
  if(NOT RUN_OUTPUT MATCHES "${VERSION}")
    message(FATAL_ERROR "the packaged pccd does not report version ${VERSION}")
  endif()
endif()

# find_package(PCCD) from the unpacked tree.
run(WHAT "configure the consumer (find_package)" DIR "${WORK}"
    COMMAND "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${WORK}/cmake_consumer"
            "-DCMAKE_PREFIX_PATH=${root}/usr" "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}" -DCMAKE_BUILD_TYPE=Release
            "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON")
file(READ "${WORK}/cmake_consumer/CMakeCache.txt" cache)
if(NOT cache MATCHES "PCCD_DIR:PATH=${root}/usr/share/cmake/PCCD")
  message(FATAL_ERROR "find_package(PCCD) did not find the unpacked package's config")
endif()
run(WHAT "build the consumer (find_package)" DIR "${WORK}" COMMAND "${CMAKE_COMMAND}" --build "${WORK}/cmake_consumer")
run(WHAT "run the consumer (find_package)" DIR "${WORK}" COMMAND "${WORK}/cmake_consumer/consumer")

# pkg-config from the unpacked tree: the relocatable pccd.pc points into it.
set(ENV{PKG_CONFIG_PATH} "${root}/usr/share/pkgconfig")
run(WHAT "pkg-config --cflags pccd" DIR "${WORK}" COMMAND pkg-config --cflags pccd)
string(STRIP "${RUN_OUTPUT}" cflags)
if(NOT cflags MATCHES "-I${root}/usr/share/pkgconfig/../../include" AND NOT cflags MATCHES "-I${root}/usr/include")
  message(FATAL_ERROR "pkg-config --cflags pccd does not point into the unpacked tree: ${cflags}")
endif()
separate_arguments(cflags UNIX_COMMAND "${cflags}")
run(WHAT "pkg-config --libs pccd" DIR "${WORK}" COMMAND pkg-config --libs pccd)
string(STRIP "${RUN_OUTPUT}" libs)
separate_arguments(libs UNIX_COMMAND "${libs}")
run(WHAT "compile the umbrella program (pkg-config)" DIR "${WORK}"
    COMMAND "${CMAKE_CXX_COMPILER}" -std=c++20 -O2 ${cflags} "${UMBRELLA_PROGRAM}" -o "${WORK}/pkg_config_consumer"
            ${libs})
run(WHAT "run the umbrella program (pkg-config)" DIR "${WORK}" COMMAND "${WORK}/pkg_config_consumer")
