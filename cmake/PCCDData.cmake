# Real data for tests, examples, benchmarks and the demo, from the archive of Debian's libcgal-demo
# package (data.tar.gz): the scanned meshes (PCCD_DATA_DIR) and every point file of data/points_3
# (PCCD_POINTS_DIR, read by the command-line tests). They are extracted into the build tree at
# configure time and never committed. When the package is absent, both stay empty and every
# consumer falls back to PCCD's procedural shapes (or skips), saying so.
set(PCCD_CGAL_DATA_ARCHIVE "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH
    "Archive of CGAL's data files (Debian package libcgal-demo)")
set(PCCD_DATA_FILES data/meshes/bunny00.off data/meshes/elephant.off data/meshes/eight.off
    data/meshes/sphere.off data/meshes/knot1.off data/meshes/armadillo.off data/meshes/ChineseDragon-10kv.off
    # CAD and mechanical parts (sharp edges, thin walls, handles) for the contact validation
    data/meshes/anchor.off data/meshes/joint.off data/meshes/cheese.off data/meshes/helmet.off
    data/meshes/handle.off data/meshes/fandisk.off data/meshes/pipe.off data/meshes/itemb.off data/meshes/part.off)
set(PCCD_DATA_DIR "")
set(PCCD_POINTS_DIR "")

# _pccd_extract(<file that shows it is done> <archive members>...): extracts the members into
# ${_pccd_data_root} unless the marker file exists already.
function(_pccd_extract marker)
  if(EXISTS "${_pccd_data_root}/${marker}")
    return()
  endif()
  file(MAKE_DIRECTORY "${_pccd_data_root}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E tar xzf "${PCCD_CGAL_DATA_ARCHIVE}" ${ARGN}
                  WORKING_DIRECTORY "${_pccd_data_root}" RESULT_VARIABLE _pccd_tar_result)
  if(NOT _pccd_tar_result EQUAL 0)
    message(WARNING "PCCD: could not extract ${ARGN} from ${PCCD_CGAL_DATA_ARCHIVE}")
  endif()
endfunction()

if(EXISTS "${PCCD_CGAL_DATA_ARCHIVE}")
  set(_pccd_data_root "${PROJECT_BINARY_DIR}/cgal-data")
  # The marker is the last mesh added, so that a build tree made before it extracts it too.
  _pccd_extract(data/meshes/part.off ${PCCD_DATA_FILES})
  if(EXISTS "${_pccd_data_root}/data/meshes/bunny00.off")
    set(PCCD_DATA_DIR "${_pccd_data_root}/data/meshes")
    message(STATUS "PCCD: scanned meshes from libcgal-demo in ${PCCD_DATA_DIR}")
  endif()
  # The whole directory (31 files in libcgal-demo 5.5, 17 MB: .ply, .xyz, .pwn, .off).
  _pccd_extract(data/points_3/hippo2.ply data/points_3)
  if(EXISTS "${_pccd_data_root}/data/points_3/hippo2.ply")
    set(PCCD_POINTS_DIR "${_pccd_data_root}/data/points_3")
    message(STATUS "PCCD: point files from libcgal-demo in ${PCCD_POINTS_DIR}")
  endif()
else()
  message(STATUS "PCCD: libcgal-demo not installed; tests and demo use procedural shapes only")
endif()

# pccd_data: an interface target carrying PCCD_DATA_DIR as a compile definition ("" when absent).
add_library(pccd_data INTERFACE)
target_compile_definitions(pccd_data INTERFACE PCCD_DATA_DIR="${PCCD_DATA_DIR}")
