# Build settings of PCCD's own programs (tests, examples, benchmarks, tools), never exported:
# pccd_warnings carries the warning flags and the optional sanitizers (PCCD_SANITIZE);
# pccd_add_program() adds an example or benchmark executable. The test data (shapes, poses, scenes)
# and the benchmark helpers are the target PCCD::testing of testing/CMakeLists.txt.
add_library(pccd_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(pccd_warnings INTERFACE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endif()
if(PCCD_SANITIZE)
  target_compile_options(pccd_warnings INTERFACE -fsanitize=${PCCD_SANITIZE} -fno-omit-frame-pointer
                         -fno-sanitize-recover=all)
  target_link_options(pccd_warnings INTERFACE -fsanitize=${PCCD_SANITIZE})
endif()

# CGAL for the programs that read meshes (PCCD/IO/read_*.h), among them the scenes of
# testing/PCCD/testing/scenes/.
find_package(CGAL REQUIRED)

# pccd_add_program(<name> [CGAL] [TESTING]) -- an executable from <name>.cpp in the current
# directory, linked with PCCD, the data location and the options above; CGAL: also CGAL::CGAL;
# TESTING: also PCCD::testing (test shapes, poses, scenes, timing). Used by examples/ and benchmark/.
function(pccd_add_program name)
  cmake_parse_arguments(ARG "CGAL;TESTING" "" "" ${ARGN})
  add_executable(${name} ${name}.cpp)
  target_link_libraries(${name} PRIVATE PCCD::PCCD pccd_data pccd_warnings)
  if(ARG_TESTING)
    target_link_libraries(${name} PRIVATE PCCD::testing)
  endif()
  if(ARG_CGAL)
    find_package(CGAL REQUIRED)
    target_link_libraries(${name} PRIVATE CGAL::CGAL)
  endif()
endfunction()
