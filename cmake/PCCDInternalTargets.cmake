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

# Precompiled headers of PCCD's own programs (cmake/pch/): the standard library, Eigen, the object
# and the query, parsed once per build directory instead of once per program (measured on a cold
# build: 10-17 s less for each command of the pccd tool and each accuracy program, of 45-80 s).
# Two of them, because CGAL's targets add -frounding-math, which a precompiled header must match.
# The benchmarks, the tool and the test programs reuse them; the examples do not (examples/).
# pccd_use_program_pch(<target> [CGAL]) makes <target> reuse the one that matches it (each is built
# only when a program reuses it).
option(PCCD_PROGRAM_PCH "Precompile the headers shared by the examples, benchmarks and the pccd tool" ON)
if(PCCD_PROGRAM_PCH)
  foreach(variant IN ITEMS "program" "program_cgal;CGAL::CGAL")
    list(POP_FRONT variant stem)
    add_library(pccd_${stem}_pch OBJECT EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/cmake/pch/pch_anchor.cpp)
    target_link_libraries(pccd_${stem}_pch PRIVATE PCCD::PCCD ${variant} pccd_warnings)
    target_precompile_headers(pccd_${stem}_pch PRIVATE ${PROJECT_SOURCE_DIR}/cmake/pch/${stem}_pch.h)
  endforeach()
endif()
function(pccd_use_program_pch target)
  cmake_parse_arguments(ARG "CGAL" "" "" ${ARGN})
  if(NOT PCCD_PROGRAM_PCH)
    return()
  endif()
  if(ARG_CGAL)
    target_precompile_headers(${target} REUSE_FROM pccd_program_cgal_pch)
  else()
    target_precompile_headers(${target} REUSE_FROM pccd_program_pch)
  endif()
endfunction()

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
    pccd_use_program_pch(${name} CGAL)
  else()
    pccd_use_program_pch(${name})
  endif()
endfunction()
