# Build settings of PCCD's own programs (tests, examples, benchmarks, tools), never exported:
# pccd_warnings carries the warning flags and the optional sanitizers (PCCD_SANITIZE);
# pccd_kinetic_scenes carries the recorded animations of benchmark/scenes/; pccd_add_program() adds
# an example or benchmark executable.
add_library(pccd_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(pccd_warnings INTERFACE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endif()
if(PCCD_SANITIZE)
  target_compile_options(pccd_warnings INTERFACE -fsanitize=${PCCD_SANITIZE} -fno-omit-frame-pointer
                         -fno-sanitize-recover=all)
  target_link_options(pccd_warnings INTERFACE -fsanitize=${PCCD_SANITIZE})
endif()

# pccd_kinetic_scenes: the kinetic scenes of benchmark/scenes/ (cloth, deforming cloud, random
# motion, run_kinetic_scene), included as <scenes/NAME.h> by the kinetic tests, benchmark, example
# and `pccd kinetic-bench`. Not library code, never installed. CGAL: the deforming cloud reads its
# OFF file with PCCD::IO::read_triangle_mesh.
find_package(CGAL REQUIRED)
add_library(pccd_kinetic_scenes INTERFACE)
target_include_directories(pccd_kinetic_scenes INTERFACE ${PROJECT_SOURCE_DIR}/benchmark)
target_link_libraries(pccd_kinetic_scenes INTERFACE PCCD::PCCD CGAL::CGAL)

# pccd_add_program(<name> [CGAL]) -- an executable from <name>.cpp in the current directory, linked
# with PCCD, the data location and the options above; CGAL: also CGAL::CGAL. Used by examples/ and
# benchmark/.
function(pccd_add_program name)
  cmake_parse_arguments(ARG "CGAL" "" "" ${ARGN})
  add_executable(${name} ${name}.cpp)
  target_link_libraries(${name} PRIVATE PCCD::PCCD pccd_data pccd_warnings)
  if(ARG_CGAL)
    find_package(CGAL REQUIRED)
    target_link_libraries(${name} PRIVATE CGAL::CGAL)
  endif()
endfunction()
