# run_points_3_test.cmake -- `pccd info` and `pccd collide` on one point file of libcgal-demo's
# data/points_3 (the real scans and odd files CGAL ships), or a check that every file there has a
# test:
#   cmake -DPCCD=<pccd binary> -DPOINTS_DIR=<data/points_3 or ""> -DFILE=<name>
#         [-DINFO_ERROR=<regex>] [-DCOLLIDE_ERROR=<regex>] [-DANSWERS=ON] [-DSKIP=<reason>]
#         [-DTIMEOUT=<seconds per run>] -P run_points_3_test.cmake
#   cmake -DPOINTS_DIR=<...> -DLISTED=<every file name with a test> -P run_points_3_test.cmake
# Every run must either succeed (exit 0) or fail with one line "pccd: error: ..." and exit 1; an
# empty INFO_ERROR / COLLIDE_ERROR means success is expected, else the error line must match it.
# A crash (signal), a sanitizer report, an uncaught exception ("pccd: unexpected error", exit 2),
# or a run longer than TIMEOUT seconds (default 600) fails the test. collide runs twice, on the
# file with itself, both normalized into [-1, 1]^3: B translated by 3 along x (1 apart) and B
# rotated 90 degrees about z and translated by 0.5 (overlapping); ANSWERS=ON (closed scans) also
# requires "no" and "yes" for these two poses. Without the data, or with a SKIP reason, the output
# says PCCD_CLI_TEST_SKIPPED (the test's SKIP_REGULAR_EXPRESSION).
cmake_minimum_required(VERSION 3.22)

if(NOT DEFINED TIMEOUT)
  set(TIMEOUT 600)
endif()
if("${POINTS_DIR}" STREQUAL "" OR NOT IS_DIRECTORY "${POINTS_DIR}")
  message("PCCD_CLI_TEST_SKIPPED: libcgal-demo's data/points_3 not found (install libcgal-demo and reconfigure)")
  return()
endif()

if(DEFINED LISTED)
  file(GLOB present RELATIVE "${POINTS_DIR}" "${POINTS_DIR}/*")
  set(untested "")
  foreach(name IN LISTS present)
    if(NOT name IN_LIST LISTED)
      list(APPEND untested "${name}")
    endif()
  endforeach()
  list(LENGTH present count)
  if(untested)
    message(FATAL_ERROR "files of ${POINTS_DIR} without a test (add them to test/cli/CMakeLists.txt): ${untested}")
  endif()
  message("all ${count} files of ${POINTS_DIR} have a test")
  return()
endif()

if(NOT "${SKIP}" STREQUAL "")
  message("PCCD_CLI_TEST_SKIPPED: ${FILE}: ${SKIP}")
  return()
endif()
if(NOT EXISTS "${POINTS_DIR}/${FILE}")
  message("PCCD_CLI_TEST_SKIPPED: ${POINTS_DIR}/${FILE} not found (another version of libcgal-demo?)")
  return()
endif()

# pccd_scan_run(<expected error regex or "">, <pccd arguments>...): runs pccd in POINTS_DIR and
# checks the outcome as described above; leaves stdout in PCCD_STDOUT.
function(pccd_scan_run expected_error)
  execute_process(COMMAND ${PCCD} ${ARGN} WORKING_DIRECTORY ${POINTS_DIR} TIMEOUT ${TIMEOUT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " shown "${ARGN}")
  string(LENGTH "${out}" out_length)
  if(out_length GREATER 2000)
    string(SUBSTRING "${out}" 0 2000 out)
    string(APPEND out "...\n")
  endif()
  message("$ pccd ${shown}\n[exit ${rc}]\n[stdout]\n${out}[stderr]\n${err}")
  if(NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "pccd did not exit normally: ${rc}")
  endif()
  foreach(bad "Sanitizer" "runtime error" "terminate called" "unexpected error" "Assertion")
    if(err MATCHES "${bad}")
      message(FATAL_ERROR "stderr contains \"${bad}\"")
    endif()
  endforeach()
  if("${expected_error}" STREQUAL "")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "expected success, got exit code ${rc}")
    endif()
  else()
    if(NOT rc EQUAL 1)
      message(FATAL_ERROR "expected the error handler's exit code 1, got ${rc}")
    endif()
    if(NOT err MATCHES "^pccd: error: [^\n]+\n$")
      message(FATAL_ERROR "expected exactly one line \"pccd: error: ...\" on stderr")
    endif()
    if(NOT err MATCHES "${expected_error}")
      message(FATAL_ERROR "the error does not match: ${expected_error}")
    endif()
  endif()
  set(PCCD_STDOUT "${out}" PARENT_SCOPE)
endfunction()

# info: the file is described; when it has normals, each point's is a hint, used or ignored (the
# points left out as isolated outliers carry none).
pccd_scan_run("${INFO_ERROR}" info ${FILE} --json)
if("${INFO_ERROR}" STREQUAL "")
  string(JSON points GET "${PCCD_STDOUT}" points)
  string(JSON from_file GET "${PCCD_STDOUT}" normals from_file)
  if(points LESS 2)
    message(FATAL_ERROR "info: ${points} points")
  endif()
  string(JSON hints_used GET "${PCCD_STDOUT}" normals hints_used)
  string(JSON hints_ignored GET "${PCCD_STDOUT}" normals hints_ignored)
  string(JSON outliers GET "${PCCD_STDOUT}" outliers count)
  math(EXPR hints "${hints_used} + ${hints_ignored}")
  math(EXPR accounted "${hints} + ${outliers}")
  if(from_file AND NOT accounted EQUAL points)
    message(FATAL_ERROR "info: ${hints_used} hints used + ${hints_ignored} ignored + ${outliers} outliers for ${points} points with normals")
  endif()
  if(NOT from_file AND NOT hints EQUAL 0)
    message(FATAL_ERROR "info: hints counted for a file without normals")
  endif()
endif()

# collide: apart, then overlapping.
set(apart 1 0 0 3 0 1 0 0 0 0 1 0)
set(overlapping 0 -1 0 0.5 1 0 0 0 0 0 1 0)
foreach(pose apart overlapping)
  pccd_scan_run("${COLLIDE_ERROR}" collide ${FILE} ${FILE} --normalize --transform-b ${${pose}} --json)
  if("${COLLIDE_ERROR}" STREQUAL "")
    string(JSON intersects GET "${PCCD_STDOUT}" intersects)
    string(JSON same GET "${PCCD_STDOUT}" same_object)
    if(NOT same)
      message(FATAL_ERROR "collide: the file was not recognized as the same object")
    endif()
    if(ANSWERS AND pose STREQUAL "apart" AND intersects)
      message(FATAL_ERROR "collide: a closed scan 1 apart from its copy intersects it")
    endif()
    if(ANSWERS AND pose STREQUAL "overlapping" AND NOT intersects)
      message(FATAL_ERROR "collide: a closed scan overlapping its rotated copy does not intersect it")
    endif()
  endif()
endforeach()
