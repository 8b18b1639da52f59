# Real data for tests, examples, benchmarks and the demo: the scanned meshes shipped in Debian's
# libcgal-demo package (data.tar.gz). They are extracted into the build tree at configure time and
# never committed. When the package is absent, PCCD_DATA_DIR stays empty and every consumer falls
# back to PCCD's procedural shapes, saying so.
set(PCCD_CGAL_DATA_ARCHIVE "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH
    "Archive of CGAL's data files (Debian package libcgal-demo)")
set(PCCD_DATA_FILES data/meshes/bunny00.off data/meshes/elephant.off data/meshes/eight.off
    data/meshes/sphere.off data/meshes/knot1.off)
set(PCCD_DATA_DIR "")
if(EXISTS "${PCCD_CGAL_DATA_ARCHIVE}")
  set(_pccd_data_root "${PROJECT_BINARY_DIR}/cgal-data")
  if(NOT EXISTS "${_pccd_data_root}/data/meshes/bunny00.off")
    file(MAKE_DIRECTORY "${_pccd_data_root}")
    execute_process(COMMAND ${CMAKE_COMMAND} -E tar xzf "${PCCD_CGAL_DATA_ARCHIVE}" ${PCCD_DATA_FILES}
                    WORKING_DIRECTORY "${_pccd_data_root}" RESULT_VARIABLE _pccd_tar_result)
    if(NOT _pccd_tar_result EQUAL 0)
      message(WARNING "PCCD: could not extract ${PCCD_CGAL_DATA_ARCHIVE}; using procedural data only")
    endif()
  endif()
  if(EXISTS "${_pccd_data_root}/data/meshes/bunny00.off")
    set(PCCD_DATA_DIR "${_pccd_data_root}/data/meshes")
    message(STATUS "PCCD: scanned meshes from libcgal-demo in ${PCCD_DATA_DIR}")
  endif()
else()
  message(STATUS "PCCD: libcgal-demo not installed; tests and demo use procedural shapes only")
endif()

# pccd_data: an interface target carrying PCCD_DATA_DIR as a compile definition ("" when absent).
add_library(pccd_data INTERFACE)
target_compile_definitions(pccd_data INTERFACE PCCD_DATA_DIR="${PCCD_DATA_DIR}")
