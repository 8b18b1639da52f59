# run_cli_test.cmake -- one test of the pccd command line, selected by CASE:
#   cmake -DPCCD=<pccd binary> -DWORK=<dir with make_cli_data's files> -DDATA_DIR=<libcgal-demo meshes or "">
#         -DREFERENCE=<distance_reference binary> -DCONTACT_TIME_REFERENCE=<contact_time_reference binary>
#         -DCASE=<name> -P run_cli_test.cmake
# Each case runs pccd, prints the command and what it wrote, then checks the exit code (0, or an
# error exit >= 1 that is not a crash) and regular expressions on stdout + stderr. A case whose data
# is missing prints PCCD_CLI_TEST_SKIPPED (the test's SKIP_REGULAR_EXPRESSION).
cmake_minimum_required(VERSION 3.22)

# pccd_run(OK|FAIL ARGS <pccd arguments>... [MATCH <regex>...] [NO_MATCH <regex>...]
#          [STDOUT_MATCH <regex>...] [STDERR_EMPTY]): MATCH and NO_MATCH look at stdout + stderr,
# STDOUT_MATCH at stdout alone; STDERR_EMPTY requires that nothing was written to stderr.
function(pccd_run expect)
  cmake_parse_arguments(R "STDERR_EMPTY" "" "ARGS;MATCH;NO_MATCH;STDOUT_MATCH" ${ARGN})
  execute_process(COMMAND ${PCCD} ${R_ARGS} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " shown "${R_ARGS}")
  message("$ pccd ${shown}\n[exit ${rc}]\n[stdout]\n${out}[stderr]\n${err}")
  if(expect STREQUAL "OK" AND NOT rc STREQUAL "0")
    message(FATAL_ERROR "expected exit code 0, got ${rc}")
  endif()
  if(expect STREQUAL "FAIL" AND (rc STREQUAL "0" OR NOT rc MATCHES "^[0-9]+$"))
    message(FATAL_ERROR "expected an error exit (a non-zero code, no crash), got ${rc}")
  endif()
  foreach(regex IN LISTS R_MATCH)
    if(NOT "${out}${err}" MATCHES "${regex}")
      message(FATAL_ERROR "output does not match: ${regex}")
    endif()
  endforeach()
  foreach(regex IN LISTS R_STDOUT_MATCH)
    if(NOT "${out}" MATCHES "${regex}")
      message(FATAL_ERROR "stdout does not match: ${regex}")
    endif()
  endforeach()
  foreach(regex IN LISTS R_NO_MATCH)
    if("${out}${err}" MATCHES "${regex}")
      message(FATAL_ERROR "output matches what it must not: ${regex}")
    endif()
  endforeach()
  if(R_STDERR_EMPTY AND NOT "${err}" STREQUAL "")
    message(FATAL_ERROR "stderr is not empty")
  endif()
  set(PCCD_STDOUT "${out}" PARENT_SCOPE)
endfunction()

# pccd_check_png(<file> <width> <height>): the file exists, is a PNG and has that size (IHDR).
function(pccd_check_png file width height)
  if(NOT EXISTS "${WORK}/${file}")
    message(FATAL_ERROR "${file} was not written")
  endif()
  file(READ "${WORK}/${file}" header LIMIT 24 HEX)
  string(SUBSTRING "${header}" 0 16 signature)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${file} is not a PNG file (starts with ${signature})")
  endif()
  string(SUBSTRING "${header}" 32 8 w)
  string(SUBSTRING "${header}" 40 8 h)
  math(EXPR w "0x${w}")
  math(EXPR h "0x${h}")
  if(NOT w EQUAL width OR NOT h EQUAL height)
    message(FATAL_ERROR "${file} is ${w}x${h}, expected ${width}x${height}")
  endif()
endfunction()

# pccd_reference(<distance_reference arguments>...): the C++ API's answer agrees with what pccd
# printed (distance_reference.cpp); fails the test, with its report, otherwise.
function(pccd_reference)
  execute_process(COMMAND ${REFERENCE} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " shown "${ARGN}")
  message("$ distance_reference ${shown}\n[exit ${rc}]\n${out}${err}")
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "pccd distance and the C++ API disagree (or the JSON does not parse)")
  endif()
endfunction()

# pccd_contact_time_reference(<contact_time_reference arguments>...): the same for
# `pccd contact-time` (contact_time_reference.cpp).
function(pccd_contact_time_reference)
  execute_process(COMMAND ${CONTACT_TIME_REFERENCE} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " shown "${ARGN}")
  message("$ contact_time_reference ${shown}\n[exit ${rc}]\n${out}${err}")
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "pccd contact-time and the C++ API disagree (or the JSON does not parse)")
  endif()
endfunction()

# pccd_world_reference(<scene.csv> <pccd world --json output file>): the brute force of
# world_reference.cpp (do_intersect on every pair with the documented pair seed) equals the pairs
# pccd world printed; fails the test, with its report, otherwise (also when no pair intersects).
function(pccd_world_reference scene json)
  execute_process(COMMAND ${WORLD_REFERENCE} ${scene} ${json} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("$ world_reference ${scene} ${json}\n[exit ${rc}]\n${out}${err}")
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "pccd world and the brute force disagree (or no pair intersects, or the JSON does not parse)")
  endif()
endfunction()

# expect_kernels(<A's> <B's>): the kernels of the objects a and b of the last JSON output.
function(expect_kernels expected_a expected_b)
  string(JSON kernel_a GET "${PCCD_STDOUT}" a kernel)
  string(JSON kernel_b GET "${PCCD_STDOUT}" b kernel)
  if(NOT kernel_a STREQUAL expected_a OR NOT kernel_b STREQUAL expected_b)
    message(FATAL_ERROR "expected a ${expected_a} A and a ${expected_b} B, built ${kernel_a} and ${kernel_b}")
  endif()
endfunction()

# pccd_json_number(<out var> <json> <key>): a top-level number of a JSON object.
function(pccd_json_number out json key)
  string(JSON value ERROR_VARIABLE error GET "${json}" ${key})
  if(error)
    message(FATAL_ERROR "the JSON has no ${key}: ${error}")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

# pccd_expect_between(<value> <low> <high> <what>): low <= value <= high (floating point).
function(pccd_expect_between value low high what)
  if(value LESS low OR value GREATER high)
    message(FATAL_ERROR "${what} is ${value}, expected within [${low}, ${high}]")
  endif()
endfunction()

set(identity 1 0 0 0 0 1 0 0 0 0 1 0)
set(shift_1 1 0 0 1 0 1 0 0 0 0 1 0)
set(shift_3 1 0 0 3 0 1 0 0 0 0 1 0)
string(REPLACE ";" "," shift_1_csv "${shift_1}") # one argument, for distance_reference
string(REPLACE ";" "," shift_3_csv "${shift_3}")
set(json_counters "\"f_evaluations\": [0-9]+" "\"brackets_tried\": " "\"search_steps\": " "\"samples\": "
                  "\"candidate_points\": " "\"query_us\": [0-9.e+-]+" "\"preprocess_ms\": [0-9.e+-]+")

if(CASE STREQUAL "kinetic_bench_bunny_contact_json")
  # The summary fields of the deforming contact scene (one regex per line: no backtracking over the
  # per-frame records).
  pccd_run(OK ARGS kinetic-bench --scene bunny-contact --size 800 --frames 4 --json
           STDOUT_MATCH "\n  \"agreement\": [01][.0-9e-]*,\n" "\n  \"frames\": 4,\n"
                        "\n  \"ms_per_frame\": {\n    \"kinetic\": [0-9.e-]+,\n    \"rebuild\": [0-9.e-]+\n"
                        "\n  \"points\": 800,\n" "\"per_frame\": \\[")
elseif(CASE STREQUAL "collide_json")
  pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --json
           MATCH "\"intersects\": true" "\"status\": \"intersecting\"" "\"method\": \"isearch\"" "\"mode\": \"first\""
                 "\"points\": 1," "\"same_object\": true" ${json_counters})
elseif(CASE STREQUAL "collide_volume")
  # Every bounding volume gives the same answers; info names the volume; a bad name is refused.
  foreach(volume box_and_slab box sphere)
    pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --volume ${volume} --json
             MATCH "\"intersects\": true" "\"status\": \"intersecting\"")
    pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b "1,0,0,3, 0,1,0,0, 0,0,1,0" --volume ${volume} --json
             MATCH "\"intersects\": false" "\"status\": \"separate\"")
  endforeach()
  pccd_run(OK ARGS info sphere.xyz --json MATCH "\"volume\": \"box_and_slab\"")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --volume cube MATCH "--volume")
elseif(CASE STREQUAL "object_options")
  # --leaf-size and --surface on the query commands: the JSON names what was built (leaves of 8 and
  # the sphere fit by default, auto keeping 8 below 10^6 points); the sharp-feature surface with
  # leaves of 10 keeps the verdicts on surfaces that overlap by 1 and lie 1 apart, and the distance
  # of the latter (the sphere and the torus of make_cli_data); bad values are refused before any work.
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --json
           MATCH "\"surface_fit\": \"sphere\"" "\"leaf_size\": 8,")
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --json --leaf-size auto
           MATCH "\"leaf_size\": 8,")
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --json --leaf-size 10 --surface sharp
           MATCH "\"surface_fit\": \"imls\"" "\"leaf_size\": 10," "\"status\": \"separate\"")
  pccd_json_number(distance "${PCCD_STDOUT}" distance)
  pccd_expect_between(${distance} 0.97 1.03 "the sharp-feature surfaces' distance of surfaces 1 apart")
  foreach(volume box_and_slab sphere)
    pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --leaf-size 3 --surface sharp
                     --volume ${volume} --json
             MATCH "\"intersects\": true" "\"leaf_size\": 3," "\"surface_fit\": \"imls\"")
  endforeach()
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_3} --leaf-size 16 --json
           MATCH "\"intersects\": false" "\"leaf_size\": 16,")
  pccd_run(OK ARGS world --generate sphere.xyz:4 --scene-seed 3 --leaf-size 5 --surface sharp --json
           MATCH "\"leaf_size\": 5," "\"surface_fit\": \"imls\"")
  pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b 1,0,0,4,0,1,0,0,0,0,1,0 --to-b 1,0,0,-4,0,1,0,0,0,0,1,0
                   --surface sharp --leaf-size 10 --json
           MATCH "\"status\": \"contact\"")
  pccd_json_number(t "${PCCD_STDOUT}" t)
  pccd_expect_between(${t} 0.235 0.265 "the sharp-feature surfaces' contact time of unit spheres meeting at t = 0.25")
  # The unit sphere past a copy of itself, gaps 2 and 0.25: the second pose is the first below 0.6.
  file(WRITE ${WORK}/object_options_path.csv "1,0,0,4,0,1,0,0,0,0,1,0\n1,0,0,2.25,0,1,0,0,0,0,1,0\n")
  pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path object_options_path.csv --margin 0.6 --surface sharp
                   --leaf-size 12 --json
           MATCH "\"poses\": 2," "\"first_below_margin\": 1," "\"leaf_size\": 12," "\"surface_fit\": \"imls\"")
  # --kernel-object: a geodesic moving object beside a lean scene (the same file, built twice).
  pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path object_options_path.csv --margin 0.6 --kernel euclidean
                   --kernel-object geodesic --json
           MATCH "\"poses\": 2," "\"first_below_margin\": 1,")
  string(JSON object_kernel GET "${PCCD_STDOUT}" object kernel)
  string(JSON scene_kernel GET "${PCCD_STDOUT}" scene kernel)
  string(JSON gap GET "${PCCD_STDOUT}" samples 1 clearance)
  if(NOT object_kernel STREQUAL "geodesic" OR NOT scene_kernel STREQUAL "euclidean")
    message(FATAL_ERROR "--kernel-object geodesic --kernel euclidean built ${object_kernel} and ${scene_kernel}")
  endif()
  pccd_expect_between(${gap} 0.21 0.29 "the mixed pair's clearance of spheres 0.25 apart")
  pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path object_options_path.csv --margin 0.6 --kernel-object lean
           MATCH "--kernel-object")
  foreach(command "collide;no_such_cloud.xyz;no_such_cloud.xyz" "distance;no_such_cloud.xyz;no_such_cloud.xyz"
                  "clearance;no_such_cloud.xyz;no_such_cloud.xyz;--path;object_options_path.csv;--margin;1"
                  "world;--generate;no_such_cloud.xyz:2" "contact-time;no_such_cloud.xyz;no_such_cloud.xyz"
                  "bench;no_such_cloud.xyz")
    foreach(bad 0 -1 x 1e3 2.5)
      pccd_run(FAIL ARGS ${command} --leaf-size ${bad} MATCH "--leaf-size" NO_MATCH "no_such_cloud")
    endforeach()
    pccd_run(FAIL ARGS ${command} --surface round MATCH "--surface" NO_MATCH "no_such_cloud")
  endforeach()
elseif(CASE STREQUAL "kernel_option")
  # --kernel on collide, distance and world: the lean object (euclidean) gives the same verdicts and the
  # distance of surfaces 1 apart; auto picks the geodesic object below 10^6 points; a bad name is
  # refused before any work.
  pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --kernel euclidean --json
           MATCH "\"intersects\": true" "\"status\": \"intersecting\"" "\"kernel\": \"euclidean\"")
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_3} --kernel euclidean --json
           MATCH "\"intersects\": false" "\"status\": \"separate\"" "\"kernel\": \"euclidean\"")
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_1} --kernel auto
           STDOUT_MATCH "A: sphere.xyz, 2000 points, geodesic kernel" "B: torus.ply, 2000 points, geodesic kernel"
                        "answer: intersecting")
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --kernel euclidean --json
           MATCH "\"status\": \"separate\"" "\"kernel\": \"euclidean\"")
  pccd_json_number(distance "${PCCD_STDOUT}" distance)
  pccd_expect_between(${distance} 0.97 1.03 "the lean objects' distance of surfaces 1 apart")
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_1} --kernel euclidean --penetration
           STDOUT_MATCH "A: sphere.xyz, 2000 points, euclidean kernel" "\nstatus: intersecting\n")
  # pccd world with lean objects: its pairs equal the brute force over lean objects.
  file(REMOVE "${WORK}/world_lean_scene.csv")
  pccd_run(OK ARGS world --generate sphere.xyz:8 --generate torus.ply:8 --scene-seed 3 --write-scene world_lean_scene.csv
                   --kernel euclidean --json
           MATCH "\"kernel\": \"euclidean\"" "\"instances\": 16" "\"status\": \"intersecting\"")
  file(WRITE ${WORK}/world_lean.json "${PCCD_STDOUT}")
  pccd_world_reference(world_lean_scene.csv world_lean.json)
  foreach(command collide distance world)
    pccd_run(FAIL ARGS ${command} sphere.xyz sphere.xyz --kernel lean
             MATCH "--kernel: lean not in \\{auto,geodesic,euclidean\\}")
  endforeach()
  # --kernel-a / --kernel-b: one object of each kind. The mixed pair answers as both kinds do (the
  # distance of surfaces 1 apart, the verdicts); the same file under two kernels is built twice.
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --kernel-a geodesic --kernel-b euclidean --json
           MATCH "\"status\": \"separate\"" "\"same_object\": false")
  expect_kernels(geodesic euclidean)
  pccd_json_number(distance "${PCCD_STDOUT}" distance)
  pccd_expect_between(${distance} 0.97 1.03 "the mixed pair's distance of surfaces 1 apart")
  pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --kernel-a euclidean --json
           MATCH "\"intersects\": true" "\"same_object\": false")
  expect_kernels(euclidean geodesic) # B: auto, below 10^6 points
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_1} --kernel-b euclidean --method rst
           STDOUT_MATCH "A: sphere.xyz, 2000 points, geodesic kernel" "B: torus.ply, 2000 points, euclidean kernel"
                        "answer: intersecting")
  foreach(command collide distance)
    foreach(option --kernel-a --kernel-b)
      pccd_run(FAIL ARGS ${command} sphere.xyz sphere.xyz ${option} lean
               MATCH "${option}: lean not in \\{auto,geodesic,euclidean\\}")
    endforeach()
  endforeach()
elseif(CASE STREQUAL "prepared_objects")
  # pccd prepare writes an object file of each kind; every query command loads it instead of
  # preprocessing, as that kind, and answers exactly as with the point file (the load is bit for
  # bit); contradicting options are refused with messages naming the file.
  file(REMOVE "${WORK}/sphere.pccdobj" "${WORK}/torus.pccdlean")
  pccd_run(OK ARGS prepare sphere.xyz sphere.pccdobj --json
           MATCH "\"kernel\": \"geodesic\"" "\"points\": 2000," "\"prepared_file\": false" "\"output\": \"sphere.pccdobj\"")
  pccd_json_number(bytes "${PCCD_STDOUT}" bytes)
  file(SIZE "${WORK}/sphere.pccdobj" size)
  if(NOT bytes EQUAL size)
    message(FATAL_ERROR "pccd prepare reported ${bytes} bytes, the file has ${size}")
  endif()
  pccd_run(OK ARGS prepare torus.ply torus.pccdlean --kernel euclidean
           STDOUT_MATCH "object: torus.ply, 2000 points, euclidean kernel" "wrote torus.pccdlean: [0-9]+ bytes")
  # pccd info tells the kind and gives the loaded object's figures.
  pccd_run(OK ARGS info sphere.pccdobj
           STDOUT_MATCH "sphere.pccdobj \\(a prepared geodesic object file, format version [0-9]+, ${size} bytes\\)"
                        "points +2000" "time load")
  pccd_run(OK ARGS info torus.pccdlean --json MATCH "\"kernel\": \"euclidean\"" "\"points\": 2000")
  # The same answers from the files as from the points (the distance to the last digit).
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --kernel-b euclidean --json
           MATCH "\"status\": \"separate\"")
  string(JSON from_points GET "${PCCD_STDOUT}" distance)
  pccd_run(OK ARGS distance sphere.pccdobj torus.pccdlean --transform-b ${shift_3} --json
           MATCH "\"status\": \"separate\"" "\"prepared_file\": true")
  string(JSON from_files GET "${PCCD_STDOUT}" distance)
  expect_kernels(geodesic euclidean)
  if(NOT from_points STREQUAL from_files)
    message(FATAL_ERROR "distance from the prepared files ${from_files}, from the points ${from_points}")
  endif()
  pccd_expect_between(${from_files} 0.97 1.03 "the distance of surfaces 1 apart, from prepared files")
  pccd_run(OK ARGS collide sphere.pccdobj torus.pccdlean --transform-b ${shift_1}
           STDOUT_MATCH "A: sphere.pccdobj, 2000 points, geodesic kernel, r\\(P\\) [0-9.]+, loaded from a prepared object file in"
                        "B: torus.pccdlean, 2000 points, euclidean kernel" "answer: intersecting")
  pccd_run(OK ARGS collide sphere.pccdobj sphere.pccdobj --transform-b ${shift_1} --json
           MATCH "\"intersects\": true" "\"same_object\": true")
  # --leaf-size rebuilds the loaded object's hierarchy; auto keeps the stored one.
  pccd_run(OK ARGS collide sphere.pccdobj torus.ply --transform-b ${shift_3} --leaf-size 4 --json
           MATCH "\"intersects\": false" "\"leaf_size\": 4,")
  file(WRITE ${WORK}/prepared_path.csv "1,0,0,4,0,1,0,0,0,0,1,0\n1,0,0,2.25,0,1,0,0,0,0,1,0\n")
  pccd_run(OK ARGS clearance sphere.pccdobj torus.pccdlean --path prepared_path.csv --margin 0.6 --json
           MATCH "\"poses\": 2," "\"prepared_file\": true")
  pccd_run(OK ARGS contact-time sphere.pccdobj torus.pccdlean --from-b 1,0,0,5,0,1,0,0,0,0,1,0
                   --to-b 1,0,0,-5,0,1,0,0,0,0,1,0 --json
           MATCH "\"status\": \"contact\"" "\"kernel\": \"euclidean\"" "\"prepared_file\": true")
  pccd_run(OK ARGS render sphere.pccdobj torus.pccdlean --transform-b ${shift_1} --intersect --out prepared.png
           STDOUT_MATCH "intersection_points: intersecting" "A sphere.pccdobj \\(2000 points, blue\\), B torus.pccdlean")
  # A world takes prepared files (their kind decides its one kernel) beside point files.
  pccd_run(OK ARGS world --generate torus.pccdlean:4 --generate sphere.xyz:4 --scene-seed 3 --json
           MATCH "\"kernel\": \"euclidean\"" "\"instances\": 8")
  pccd_run(FAIL ARGS world --generate torus.pccdlean:2 --generate sphere.pccdobj:2
           MATCH "a world holds objects of one kernel")
  # Refused: another kernel, normalizing, another surface, preparing a prepared file or over the input.
  pccd_run(FAIL ARGS collide sphere.pccdobj torus.ply --kernel euclidean
           MATCH "sphere.pccdobj: a prepared object file of the geodesic kernel, asked for as euclidean")
  pccd_run(FAIL ARGS distance sphere.xyz torus.pccdlean --kernel-b geodesic MATCH "asked for as geodesic")
  pccd_run(FAIL ARGS collide sphere.pccdobj torus.ply --normalize MATCH "cannot be normalized")
  pccd_run(FAIL ARGS collide sphere.pccdobj torus.ply --surface sharp MATCH "keeps its surface")
  pccd_run(FAIL ARGS prepare sphere.pccdobj again.pccdobj MATCH "already a prepared object file")
  pccd_run(FAIL ARGS bench torus.pccdlean --rotations 1
           MATCH "torus.pccdlean: a prepared object file \\(euclidean kernel\\); pccd bench normalizes")
  pccd_run(FAIL ARGS prepare sphere.xyz sphere.xyz MATCH "is the input file")
  execute_process(COMMAND head -c 1000 sphere.pccdobj OUTPUT_FILE cut.pccdobj WORKING_DIRECTORY ${WORK})
  pccd_run(FAIL ARGS collide cut.pccdobj torus.ply MATCH "cut.pccdobj: .*(truncated|checksum)")
elseif(CASE STREQUAL "collide_text")
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-a ${identity} --transform-b ${shift_1}
           MATCH "A: sphere.xyz, 2000 points" "B: torus.ply, 2000 points" "answer: intersecting"
                 "query: [0-9.]+ us, [0-9]+ f evaluations")
elseif(CASE STREQUAL "collide_rst_separate")
  # The transform as one quoted argument, with commas.
  pccd_run(OK ARGS collide sphere.xyz sphere.xyz --method rst --transform-b "1,0,0,3, 0,1,0,0, 0,0,1,0" --json
           MATCH "\"intersects\": false" "\"status\": \"separate\"" "\"method\": \"rst\"" "\"points\": 0,"
                 ${json_counters})
elseif(CASE STREQUAL "collide_all_out")
  file(REMOVE ${WORK}/curve.ply)
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_1} --mode all --out curve.ply --json
           MATCH "\"intersects\": true" "\"mode\": \"all\"" "\"points\": [1-9][0-9]*," "\"out\": \"curve.ply\"")
  string(REGEX MATCH "\n  \"points\": ([0-9]+)," _ "${PCCD_STDOUT}") # top level, not an object's
  set(count ${CMAKE_MATCH_1})
  if(NOT EXISTS ${WORK}/curve.ply)
    message(FATAL_ERROR "curve.ply was not written")
  endif()
  pccd_run(OK ARGS info curve.ply --json MATCH "\"points\": ${count},")
  # No intersection: nothing to write, said so, exit 0.
  file(REMOVE ${WORK}/none.ply)
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_3} --mode all --out none.ply
           MATCH "no intersection points; none.ply not written")
  if(EXISTS ${WORK}/none.ply)
    message(FATAL_ERROR "none.ply was written for an empty result")
  endif()
elseif(CASE STREQUAL "collide_normalize_mesh")
  # An OFF mesh gives its vertices; both objects are scaled into [-1, 1]^3 (the torus mesh spans
  # [-1, 1] in x and y already, the sphere too): d = 1.5 keeps them touching, d = 3 apart.
  pccd_run(OK ARGS collide torus_mesh.off sphere.xyz --normalize --transform-b 1 0 0 1.5 0 1 0 0 0 0 1 0 --json
           MATCH "\"intersects\": true" "\"normalize\": true" "\"points\": 512")
  pccd_run(OK ARGS collide torus_mesh.off sphere.xyz --normalize --transform-b 1 0 0 3 0 1 0 0 0 0 1 0 --json
           MATCH "\"intersects\": false")
elseif(CASE STREQUAL "collide_cases" OR CASE STREQUAL "collide_cases_rst")
  # Header, a blank line, a comment; rows: touching, apart, and B rotated 90 degrees about z.
  file(WRITE ${WORK}/cases.csv
"a00,a01,a02,a03,a10,a11,a12,a13,a20,a21,a22,a23,b00,b01,b02,b03,b10,b11,b12,b13,b20,b21,b22,b23
1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1,0

# far apart
1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,3,0,1,0,0,0,0,1,0
1,0,0,0,0,1,0,0,0,0,1,0,0,-1,0,0.5,1,0,0,0,0,0,1,0
")
  set(method isearch)
  if(CASE STREQUAL "collide_cases_rst")
    set(method rst)
  endif()
  pccd_run(OK ARGS collide sphere.xyz torus.ply --cases cases.csv --method ${method}
           STDOUT_MATCH "^case,intersects,f_evaluations,query_us,points\n1,1,[0-9]+,[0-9.]+,1\n2,0,[0-9]+,[0-9.]+,0\n3,1,[0-9]+,[0-9.]+,1\n$"
           MATCH "3 cases, ${method}")
elseif(CASE STREQUAL "bad_transform")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --transform-b 2 0 0 0 0 1 0 0 0 0 1 0
           MATCH "--transform-b: rigid transform: the rotation part scales")
elseif(CASE STREQUAL "bad_transform_count")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --transform-a 1 0 0 0 0 1
           MATCH "--transform-a expects 12 numbers")
elseif(CASE STREQUAL "bad_cases_row")
  file(WRITE ${WORK}/bad_row.csv "1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1,0\n\n1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1\n")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --cases bad_row.csv
           MATCH "bad_row.csv:3: expected 24 numbers \\(T_A then T_B, 3x4 row-major each\\), got 23 fields"
           NO_MATCH "case,intersects")
elseif(CASE STREQUAL "bad_cases_field")
  file(WRITE ${WORK}/bad_field.csv "header\n1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1,x0\n")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --cases bad_field.csv
           MATCH "bad_field.csv:2: T_B: \"x0\" \\(number 12\\) is not a number")
elseif(CASE STREQUAL "bad_cases_rigid")
  file(WRITE ${WORK}/bad_rigid.csv "1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1,0\n1,0,0,0,0,1,0,0,0,0,-1,0,1,0,0,1,0,1,0,0,0,0,1,0\n")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --cases bad_rigid.csv
           MATCH "bad_rigid.csv:2: T_A: rigid transform: the rotation part is a reflection")
elseif(CASE STREQUAL "missing_file")
  pccd_run(FAIL ARGS collide no_such_cloud.xyz sphere.xyz MATCH "no_such_cloud.xyz: .*missing file")
  pccd_run(FAIL ARGS bench no_such_mesh.off MATCH "no_such_mesh.off: .*missing file")
elseif(CASE STREQUAL "missing_cases_file")
  pccd_run(FAIL ARGS collide sphere.xyz sphere.xyz --cases no_such_cases.csv
           MATCH "no_such_cases.csv: cannot open the cases file: it does not exist")
elseif(CASE STREQUAL "bench_mesh")
  file(REMOVE ${WORK}/bench.csv)
  pccd_run(OK ARGS bench torus_mesh.off --points 2000 --rotations 2 --distances 0:3:1.5 --csv bench.csv
           MATCH "mesh, 1024 triangles, 2000 points sampled" "distance +poses +colliding +mean_us +median_us +mean_f_evals"
                 "\n +0.000 +2 +[0-2] " "\n +1.500 +2 +[0-2] " "\n +3.000 +2 +0 ")
  file(STRINGS ${WORK}/bench.csv rows)
  list(LENGTH rows n)
  list(GET rows 0 header)
  if(NOT n EQUAL 7 OR NOT header MATCHES "^distance,rotation,intersects,status,query_us,f_evaluations,brackets_tried,")
    message(FATAL_ERROR "bench.csv: expected a header and 6 rows, got ${n} lines starting with ${header}")
  endif()
elseif(CASE STREQUAL "bench_cloud_rst")
  pccd_run(OK ARGS bench torus.ply --method rst --rotations 1 --distances 0,2.5
           MATCH "point cloud, 2000 points" "method rst" "\n +2.500 +1 +0 ")
elseif(CASE STREQUAL "bench_bad_distances")
  pccd_run(FAIL ARGS bench torus.ply --distances 3:0:0.5 MATCH "--distances \"3:0:0.5\": expected step > 0 and stop >= start")
elseif(CASE STREQUAL "render_intersect")
  file(REMOVE "${WORK}/render.png")
  pccd_run(OK ARGS render sphere.xyz torus.ply --transform-b ${shift_1} --intersect --out render.png --size 320x240
           MATCH "intersection_points: intersecting, [1-9][0-9]* points"
                 "wrote [^\n]*render.png \\(320x240, view [-0-9.]+,[-0-9.]+\\): A sphere.xyz \\(2000 points, blue\\), B torus.ply \\(2000 points, gold\\), [1-9][0-9]* intersection points \\(red\\)")
  pccd_check_png(render.png 320 240)
elseif(CASE STREQUAL "render_points")
  # The points written by collide --mode all, drawn over one object from a named view.
  file(REMOVE "${WORK}/render_curve.xyz" "${WORK}/render_points.png")
  pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --mode all --out render_curve.xyz)
  pccd_run(OK ARGS render sphere.xyz --points render_curve.xyz --view top --out render_points.png --size 200x100
           MATCH "view 0,90\\): A sphere.xyz \\(2000 points, blue\\), [1-9][0-9]* intersection points")
  pccd_check_png(render_points.png 200 100)
elseif(CASE STREQUAL "render_bad_input")
  pccd_run(FAIL ARGS render sphere.xyz --view sideways MATCH "pccd: error: view \"sideways\": expected AZIMUTH,ELEVATION")
  pccd_run(FAIL ARGS render sphere.xyz --size 10x10 MATCH "pccd: error: size \"10x10\": width and height")
  pccd_run(FAIL ARGS render sphere.xyz --intersect MATCH "pccd: error: --intersect needs two objects")
  pccd_run(FAIL ARGS render sphere.xyz --out no/such/dir/x.png MATCH "pccd: error: no/such/dir/x.png: cannot write the PNG file")
elseif(CASE STREQUAL "collide_png")
  file(REMOVE "${WORK}/collide.png")
  pccd_run(OK ARGS collide sphere.xyz sphere.xyz --transform-b ${shift_1} --mode all --png collide.png
           MATCH "answer: intersecting" "wrote [^\n]*collide.png: A blue, B gold, [1-9][0-9]* intersection points red")
  pccd_check_png(collide.png 800 600)
elseif(CASE STREQUAL "demo_pictures")
  # The demo on a small sample: its picture always, its plot of times when gnuplot is installed.
  file(REMOVE "${WORK}/demo.png" "${WORK}/demo-times.png")
  find_program(GNUPLOT gnuplot)
  if(GNUPLOT)
    set(plot_line "plot of the query times: [^\n]*demo-times.png")
  else()
    set(plot_line "plot of the query times not written: gnuplot is not installed")
  endif()
  pccd_run(OK ARGS demo --points 4000 --png demo.png --times-png demo-times.png
           MATCH "picture: [^\n]*demo.png \\(A blue, B gold, the intersection curve red\\)" "${plot_line}")
  pccd_check_png(demo.png 800 600)
  if(GNUPLOT)
    pccd_check_png(demo-times.png 800 480)
  endif()
elseif(CASE STREQUAL "distance_json")
  # Two unit spheres 3 apart along x, and the unit sphere and the torus (radii 0.7 and 0.3, outer
  # radius 1) 3 apart: the gap between the surfaces is 1 in both. The JSON parses, carries every
  # field of Distance_result, and equals the C++ API's answer bit for bit.
  set(result_fields "\"status\": \"separate\"" "\"distance\": [0-9.e+-]+," "\"lower_bound\": " "\"upper_bound\": "
                    "\"point_a\": .\n" "\"point_b\": .\n" "\"normal_a\": .\n" "\"normal_b\": .\n"
                    "\"depth\": null" "\"depth_a\": null" "\"depth_b\": null" "\"contact_normal\": .\n"
                    "\"counters\": {" "\"node_pairs\": [0-9]+" "\"f_evaluations\": [0-9]+" "\"query_us\": [0-9.e+-]+")
  foreach(b sphere.xyz torus.ply)
    pccd_run(OK ARGS distance sphere.xyz ${b} --transform-b ${shift_3} --seed 5 --json MATCH ${result_fields})
    file(WRITE ${WORK}/distance_${b}.json "${PCCD_STDOUT}")
    pccd_json_number(distance "${PCCD_STDOUT}" distance)
    pccd_json_number(lower "${PCCD_STDOUT}" lower_bound)
    pccd_json_number(upper "${PCCD_STDOUT}" upper_bound)
    pccd_expect_between(${distance} 0.97 1.03 "the distance of surfaces 1 apart")
    pccd_expect_between(${lower} 0 ${distance} "lower_bound")
    pccd_expect_between(${upper} ${distance} 2 "upper_bound")
    pccd_reference(json sphere.xyz ${b} ${shift_3_csv} distance_${b}.json --seed 5)
  endforeach()
elseif(CASE STREQUAL "distance_text")
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3}
           STDOUT_MATCH "A: sphere.xyz, 2000 points" "B: torus.ply, 2000 points" "query distance, seed 24301"
                        "\nstatus: separate\n" "\ndistance: (0\\.9[789]|1\\.0[0-2])[0-9]*\n" "\nlower_bound: "
                        "\nupper_bound: " "\npoint_a: .[-0-9.e]+, [-0-9.e]+, [-0-9.e]+.\n" "\npoint_b: ."
                        "\nnormal_a: ." "\nnormal_b: ." "\ndepth: nan\n" "\ndepth_a: nan\n" "\ndepth_b: nan\n"
                        "\ncontact_normal: ." "\ncounters: node_pairs [0-9]+ leaf_pairs [0-9]+"
                        "\nintersection counters: f_evaluations [0-9]+ " "\nquery_us: [0-9.]+\n")
elseif(CASE STREQUAL "distance_penetration")
  # Two unit spheres 1 apart intersect: distance 0; with --penetration the depths are measured
  # (numbers, not null), without it they are not (null).
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_1} --json
           MATCH "\"status\": \"intersecting\"" "\"distance\": 0(\\.0)?," "\"depth\": null" "\"intersection_points\": .\n")
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_1} --penetration --json
           MATCH "\"status\": \"intersecting\"" "\"penetration\": true" "\"depth\": [0-9]" "\"depth_a\": [0-9]"
                 "\"depth_b\": [0-9]" "\"contact_normal\": .\n")
  file(WRITE ${WORK}/distance_penetration.json "${PCCD_STDOUT}")
  pccd_reference(json sphere.xyz sphere.xyz ${shift_1_csv} distance_penetration.json --penetration)
  # Centres 1.5 apart: A's point (1, 0, 0) lies 0.5 from B's centre, 0.5 deep inside B, and no
  # point of either sphere lies deeper in the other: depth 0.5; B leaves A along +x.
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b 1 0 0 1.5 0 1 0 0 0 0 1 0 --penetration --json
           MATCH "\"status\": \"intersecting\"")
  pccd_json_number(depth "${PCCD_STDOUT}" depth)
  pccd_expect_between(${depth} 0.475 0.525 "the penetration depth of unit spheres 1.5 apart")
  string(JSON normal_x GET "${PCCD_STDOUT}" contact_normal 0)
  pccd_expect_between(${normal_x} 0.95 1.0 "the contact normal's x")
elseif(CASE STREQUAL "distance_max_distance")
  # 1 apart: beyond --max-distance 0.5 only "farther than" is reported (distance inf: null in the
  # JSON, "inf" in the text), with a lower bound above the limit; within 2 the distance is measured.
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --max-distance 0.5 --json
           MATCH "\"status\": \"separate\"" "\"max_distance\": 0.5" "\"distance\": null" "\"point_a\": null")
  file(WRITE ${WORK}/distance_max.json "${PCCD_STDOUT}")
  pccd_json_number(lower "${PCCD_STDOUT}" lower_bound)
  pccd_expect_between(${lower} 0.5 1.1 "lower_bound beyond --max-distance 0.5")
  pccd_reference(json sphere.xyz sphere.xyz ${shift_3_csv} distance_max.json --max-distance 0.5)
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --max-distance 0.5
           STDOUT_MATCH "\ndistance: inf\n")
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --max-distance 2 --json
           MATCH "\"distance\": (0\\.9[789]|1\\.0[0-2])[0-9]*,")
  # A budget of node pairs: the interval stays honest about the gap 1 (and narrows as it grows);
  # --tolerance reaches the refinement. Both as the C++ API answers.
  foreach(budget 1 8)
    pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --max-node-pairs ${budget} --json
             MATCH "\"status\": \"separate\"")
    file(WRITE ${WORK}/distance_budget.json "${PCCD_STDOUT}")
    pccd_json_number(lower "${PCCD_STDOUT}" lower_bound)
    pccd_expect_between(${lower} 0 1.03 "lower_bound with --max-node-pairs ${budget}")
    pccd_reference(json sphere.xyz sphere.xyz ${shift_3_csv} distance_budget.json --max-node-pairs ${budget})
  endforeach()
  # The certified lower bound (the points' domain radii instead of r(P) + 2 sigma): still below the
  # gap 1, and as the C++ API answers.
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --certified-lower-bound --json
           MATCH "\"certified_lower_bound\": true" "\"status\": \"separate\"")
  file(WRITE ${WORK}/distance_certified.json "${PCCD_STDOUT}")
  pccd_json_number(lower "${PCCD_STDOUT}" lower_bound)
  pccd_expect_between(${lower} 0 1.0 "lower_bound with --certified-lower-bound")
  pccd_reference(json sphere.xyz sphere.xyz ${shift_3_csv} distance_certified.json --certified-lower-bound)
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --tolerance 0.0005 --json
           MATCH "\"absolute_tolerance\": 0.0005")
  file(WRITE ${WORK}/distance_tolerance.json "${PCCD_STDOUT}")
  pccd_json_number(distance "${PCCD_STDOUT}" distance)
  pccd_expect_between(${distance} 0.97 1.03 "the distance with --tolerance 0.0005")
  pccd_reference(json sphere.xyz sphere.xyz ${shift_3_csv} distance_tolerance.json --tolerance 0.0005)
elseif(CASE STREQUAL "distance_margin")
  # within_distance: surfaces 1 apart are within 1.5, not within 0.5.
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --margin 1.5 --json
           MATCH "\"query\": \"within_distance\"" "\"within\": true" "\"status\": \"separate\"" "\"margin\": 1.5")
  file(WRITE ${WORK}/distance_within.json "${PCCD_STDOUT}")
  pccd_reference(json sphere.xyz sphere.xyz ${shift_3_csv} distance_within.json --margin 1.5)
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --margin 0.5 --json
           MATCH "\"within\": false" "\"margin\": 0.5")
  file(WRITE ${WORK}/distance_not_within.json "${PCCD_STDOUT}")
  pccd_reference(json sphere.xyz sphere.xyz ${shift_3_csv} distance_not_within.json --margin 0.5)
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_1} --margin 0 STDOUT_MATCH "\nwithin: yes\n")
elseif(CASE STREQUAL "distance_contacts")
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_1} --contacts --json
           MATCH "\"query\": \"contacts\"" "\"status\": \"intersecting\"" "\"contacts\": .\n +{"
                 "\"position\": .\n" "\"normal\": .\n" "\"points_inside\": [0-9]+" "\"regions\": [1-9]")
  pccd_run(OK ARGS distance sphere.xyz sphere.xyz --transform-b ${shift_3} --contacts --json
           MATCH "\"status\": \"separate\"" "\"contacts\": ..," "\"regions\": 0")
elseif(CASE STREQUAL "distance_cases")
  # The --cases file of pccd collide: a header, a blank line, a comment; rows touching, 1 apart,
  # and B turned 90 degrees about z. One CSV row per pose pair, each the C++ API's answer.
  file(WRITE ${WORK}/distance_cases.csv
"a00,a01,a02,a03,a10,a11,a12,a13,a20,a21,a22,a23,b00,b01,b02,b03,b10,b11,b12,b13,b20,b21,b22,b23
1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1,0

# 1 apart
1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,3,0,1,0,0,0,0,1,0
1,0,0,0,0,1,0,0,0,0,1,0,0,-1,0,0.5,1,0,0,0,0,0,1,0
")
  set(number "[-0-9.e+infa]+")
  pccd_run(OK ARGS distance sphere.xyz torus.ply --cases distance_cases.csv
           STDOUT_MATCH "^case,status,distance,lower_bound,upper_bound,query_us\n1,intersecting,0,0,0,[0-9.]+\n2,separate,(0\\.9[789]|1\\.0[0-2])[0-9]*,${number},${number},[0-9.]+\n3,intersecting,0,0,0,[0-9.]+\n$"
           MATCH "3 cases")
  string(REGEX MATCHALL "\n" lines "${PCCD_STDOUT}")
  list(LENGTH lines n)
  if(NOT n EQUAL 4)
    message(FATAL_ERROR "expected a header and 3 rows, got ${n} lines")
  endif()
  file(WRITE ${WORK}/distance_cases_out.csv "${PCCD_STDOUT}")
  # The reference reads plain rows: the same poses without the blank line and the comment.
  file(WRITE ${WORK}/distance_cases_plain.csv
"header
1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1,0,1,0,0,0,0,1,0
1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,3,0,1,0,0,0,0,1,0
1,0,0,0,0,1,0,0,0,0,1,0,0,-1,0,0.5,1,0,0,0,0,0,1,0
")
  pccd_reference(cases sphere.xyz torus.ply distance_cases_plain.csv distance_cases_out.csv)
  # The rows the collide reader refuses are refused here too, naming the file and line.
  file(WRITE ${WORK}/distance_bad_row.csv "1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,nan,0,1,0,0,0,0,1,0\n")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --cases distance_bad_row.csv
           MATCH "pccd: error: distance_bad_row.csv:1: T_B: rigid transform: translation entry \\(0, 3\\) is nan"
           NO_MATCH "case,status")
elseif(CASE STREQUAL "distance_png")
  file(REMOVE "${WORK}/distance.png")
  pccd_run(OK ARGS distance sphere.xyz torus.ply --transform-b ${shift_3} --png distance.png
           MATCH "status: separate" "wrote [^\n]*distance.png: A blue, B gold, the witness segment red")
  pccd_check_png(distance.png 800 600)
elseif(CASE STREQUAL "distance_bad_arguments")
  # Each refused before any preprocessing, with "pccd: error: " and the option's name; never a crash.
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --margin -1 MATCH "pccd: error: --margin -1: must be >= 0")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --margin nan MATCH "pccd: error: --margin: \"nan\" is not a finite number")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --tolerance -0.1 MATCH "pccd: error: --tolerance -0.1: must be > 0")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --tolerance 0 MATCH "pccd: error: --tolerance 0: must be > 0")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --relative-tolerance -1 MATCH "pccd: error: --relative-tolerance -1: must be >= 0")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --max-distance -1 MATCH "pccd: error: --max-distance -1: must be >= 0")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --max-distance inf MATCH "pccd: error: --max-distance: \"inf\" is not a finite number")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --budget-us -5 MATCH "pccd: error: --budget-us -5: must be >= 0")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --contacts --max-contacts 0 MATCH "pccd: error: --max-contacts 0: must be >= 1")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --transform-b 1 0 0 nan 0 1 0 0 0 0 1 0
           MATCH "pccd: error: --transform-b: rigid transform: translation entry \\(0, 3\\) is nan")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --transform-a 2 0 0 0 0 1 0 0 0 0 1 0
           MATCH "pccd: error: --transform-a: rigid transform: the rotation part scales")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --transform-b 1 0 0 0 0 1 0 0 0 0 -1 0
           MATCH "pccd: error: --transform-b: rigid transform: the rotation part is a reflection")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --transform-b 1 0 0 MATCH "--transform-b expects 12 numbers")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --margin 1 --contacts MATCH "excludes")
  pccd_run(FAIL ARGS distance sphere.xyz sphere.xyz --cases distance_cases.csv --json MATCH "excludes")
  pccd_run(FAIL ARGS distance no_such_cloud.xyz sphere.xyz MATCH "no_such_cloud.xyz: .*missing file")
elseif(CASE MATCHES "^clearance_")
  # pccd clearance: make_cli_data's unit sphere (2000 points, mean spacing about 0.08) moved along x
  # past a copy of itself at the origin, centres 4 to 2.25 apart: analytic clearances (the surface
  # gap) 2, 1.75, ..., 0.25. With margin 0.6 the first pose below it is pose 6 (gap 0.5) and the
  # minimum is pose 7 (gap 0.25): both 0.1 or more from the margin, beyond the distance's accuracy
  # (half a spacing, test/Proximity/distance_test.cpp). Every clearance case writes the same file,
  # and ctest may run them at once: each writes a file of its own and renames it into place (atomic),
  # so that no case reads the path while another one rewrites it.
  file(WRITE ${WORK}/clearance_path.csv.${CASE}
"r00,r01,r02,t0,r10,r11,r12,t1,r20,r21,r22,t2
1,0,0,4,0,1,0,0,0,0,1,0
1,0,0,3.75,0,1,0,0,0,0,1,0
# turned 90 degrees about z: the same sphere
0,-1,0,3.5,1,0,0,0,0,0,1,0

1,0,0,3.25,0,1,0,0,0,0,1,0
1,0,0,3,0,1,0,0,0,0,1,0
1,0,0,2.75,0,1,0,0,0,0,1,0
1,0,0,2.5,0,1,0,0,0,0,1,0
1,0,0,2.25,0,1,0,0,0,0,1,0
")
  file(RENAME ${WORK}/clearance_path.csv.${CASE} ${WORK}/clearance_path.csv)
  set(number "[-0-9.e+infa]+")
  if(CASE STREQUAL "clearance_text")
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6
             STDOUT_MATCH "object: sphere.xyz, 2000 points" "scene: the same object"
                          "path: clearance_path.csv, 8 poses, margin 0.6, max_distance none, seed 24301"
                          "\npose,status,clearance,lower_bound,upper_bound\n0,clear,(1\\.9[6-9]|2\\.0[0-4])[0-9]*,${number},${number}\n"
                          "\n5,clear,0\\.7[0-9]*,${number},${number}\n6,below_margin,0\\.[45][0-9]*,${number},${number}\n7,below_margin,0\\.2[0-9]*,"
                          "\nfirst_below_margin: 6 \\(below_margin, clearance 0\\.[45][0-9]*\\)\n"
                          "\nfirst_point_object: \\[1\\.[45][0-9]*, ${number}, ${number}\\]\n"
                          "\nfirst_point_scene: \\[(1\\.0|0\\.9)[0-9]*, ${number}, ${number}\\]\n"
                          "\nminimum: 7, minimum_clearance 0\\.2[0-9]*\n"
                          "\nposes: clear 6, below_margin 2, intersecting 0, beyond_cap 0, undecided 0\n"
                          "\nall_clear: no\n" "\ncounters: node_pairs [0-9]+ " "\nquery_ms: [0-9.]+\n")
    # Far enough everywhere: nothing below the margin.
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.1
             STDOUT_MATCH "\nfirst_below_margin: none\n" "\nall_clear: yes\n")
    # The torus (outer radius 1) as the scene: the same gaps.
    pccd_run(OK ARGS clearance sphere.xyz torus.ply --path clearance_path.csv --margin 0.6 --threads 1
             STDOUT_MATCH "\nfirst_below_margin: 6 " "\nminimum: 7, ")
    # The lean object (--kernel euclidean; auto picks it from 10^6 points): the same gaps, the same
    # first pose below the margin; the geodesic object by default at 2000 points.
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --kernel euclidean
             STDOUT_MATCH "object: sphere.xyz, 2000 points, euclidean kernel"
                          "\npose,status,clearance,lower_bound,upper_bound\n0,clear,(1\.9[6-9]|2\.0[0-4])[0-9]*,"
                          "\n5,clear,0\.7[0-9]*," "\n6,below_margin,0\.[45][0-9]*," "\nfirst_below_margin: 6 " "\nminimum: 7, ")
    pccd_run(OK ARGS clearance sphere.xyz torus.ply --path clearance_path.csv --margin 0.6 --kernel auto
             STDOUT_MATCH "object: sphere.xyz, 2000 points, geodesic kernel" "\nfirst_below_margin: 6 ")
  elseif(CASE STREQUAL "clearance_json")
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --seed 5 --threads 2 --json
             MATCH "\"poses\": 8," "\"margin\": 0.6," "\"max_distance\": null," "\"samples\": .\n"
                   "\"status\": \"below_margin\"" "\"point_object\": .\n" "\"point_scene\": .\n" "\"depth\": null"
                   "\"first_below_margin\": 6," "\"first_point_object\": .\n" "\"minimum\": 7,"
                   "\"first_undecided\": null," "\"all_clear\": false," "\"counters\": {\n +\"clear\": 6,"
                   "\"below_margin\": 2," "\"work\": {\n +\"node_pairs\": [0-9]+" "\"intersection_f_evaluations\": [0-9]+"
                   "\"query_ms\": [0-9.e+-]+" "\"kernel\": \"geodesic\"")
    file(WRITE ${WORK}/clearance.json "${PCCD_STDOUT}")
    string(JSON n LENGTH "${PCCD_STDOUT}" samples)
    if(NOT n EQUAL 8)
      message(FATAL_ERROR "expected 8 samples, got ${n}")
    endif()
    # Each clearance within half a spacing (0.04) of its gap, the interval around it.
    set(lows 1.96 1.71 1.46 1.21 0.96 0.71 0.46 0.21)
    set(highs 2.04 1.79 1.54 1.29 1.04 0.79 0.54 0.29)
    foreach(i RANGE 7)
      list(GET lows ${i} low)
      list(GET highs ${i} high)
      string(JSON index GET "${PCCD_STDOUT}" samples ${i} index)
      string(JSON c GET "${PCCD_STDOUT}" samples ${i} clearance)
      string(JSON lower GET "${PCCD_STDOUT}" samples ${i} lower_bound)
      string(JSON upper GET "${PCCD_STDOUT}" samples ${i} upper_bound)
      if(NOT index EQUAL i)
        message(FATAL_ERROR "sample ${i} has index ${index}")
      endif()
      pccd_expect_between(${c} ${low} ${high} "the clearance of pose ${i}")
      pccd_expect_between(${lower} 0 ${c} "lower_bound of pose ${i}")
      pccd_expect_between(${upper} ${c} 3 "upper_bound of pose ${i}")
    endforeach()
    pccd_json_number(minimum "${PCCD_STDOUT}" minimum_clearance)
    pccd_expect_between(${minimum} 0.21 0.29 "the minimum clearance (gap 0.25)")
    # The same answer for one thread (bit for bit: the same JSON but for the timings and threads).
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --seed 5 --threads 1 --json)
    file(READ ${WORK}/clearance.json two)
    foreach(text two PCCD_STDOUT)
      string(JSON ${text}_samples GET "${${text}}" samples)
      string(JSON ${text}_counters GET "${${text}}" counters)
    endforeach()
    if(NOT two_samples STREQUAL PCCD_STDOUT_samples OR NOT two_counters STREQUAL PCCD_STDOUT_counters)
      message(FATAL_ERROR "the samples or counters differ between --threads 1 and --threads 2")
    endif()
  elseif(CASE STREQUAL "clearance_cap")
    # A cap of 1.1: the poses of gaps 2 to 1.25 are beyond it (clearance null in the JSON, inf in the
    # text), the others measured.
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --max-distance 1.1
             STDOUT_MATCH "\n0,beyond_cap,inf,${number},${number}\n1,beyond_cap,inf," "\n3,beyond_cap,inf," "\n4,clear,(0\\.9[6-9]|1\\.0[0-4])[0-9]*,"
                          "\n5,clear,0\\.7[0-9]*," "\nfirst_below_margin: 6 " "\nminimum: 7, ")
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --max-distance 1.1 --json
             MATCH "\"max_distance\": 1.1," "\"status\": \"beyond_cap\",\n +\"clearance\": null" "\"beyond_cap\": 4,")
  elseif(CASE STREQUAL "clearance_png")
    file(REMOVE "${WORK}/clearance.png")
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --max-distance 1.5 --png clearance.png
             MATCH "wrote [^\n]*clearance.png: clearance per pose blue")
    pccd_check_png(clearance.png 800 480)
    pccd_run(OK ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --png clearance.png --json
             MATCH "\"png\": \"[^\"]*clearance.png\"")
  elseif(CASE STREQUAL "clearance_bad_arguments")
    # Each refused before any preprocessing, with "pccd: error: " naming the option, the file, the
    # line and the pose; never a crash.
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin -1
             MATCH "pccd: error: --margin -1: must be >= 0")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin nan
             MATCH "pccd: error: --margin: \"nan\" is not a finite number")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv MATCH "--margin is required")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --kernel lean
             MATCH "--kernel: lean not in \\{auto,geodesic,euclidean\\}")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --margin 0.5 MATCH "--path is required")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --max-distance 0.5
             MATCH "pccd: error: --max-distance 0.5: must be >= the margin 0.6")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --tolerance 0
             MATCH "pccd: error: --tolerance 0: must be > 0")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_path.csv --margin 0.6 --threads 100000
             MATCH "pccd: error: --threads 100000: must be at most")
    file(WRITE ${WORK}/clearance_nan.csv "1,0,0,4,0,1,0,0,0,0,1,0\n1,0,0,nan,0,1,0,0,0,0,1,0\n")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_nan.csv --margin 0.6
             MATCH "pccd: error: clearance_nan.csv:2: pose 1: rigid transform: translation entry \\(0, 3\\) is nan")
    file(WRITE ${WORK}/clearance_scaled.csv "# a scaling\n2,0,0,4,0,1,0,0,0,0,1,0\n")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_scaled.csv --margin 0.6
             MATCH "pccd: error: clearance_scaled.csv:2: pose 0: rigid transform: the rotation part scales")
    file(WRITE ${WORK}/clearance_short.csv "1,0,0,4,0,1,0,0,0,0,1\n")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_short.csv --margin 0.6
             MATCH "pccd: error: clearance_short.csv:1: pose 0: expected 12 numbers .*, got 11 fields")
    file(WRITE ${WORK}/clearance_empty.csv "# nothing\n")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path clearance_empty.csv --margin 0.6
             MATCH "pccd: error: clearance_empty.csv: no poses")
    pccd_run(FAIL ARGS clearance sphere.xyz sphere.xyz --path no_such_path.csv --margin 0.6
             MATCH "no_such_path.csv: .*missing file")
    pccd_run(FAIL ARGS clearance no_such_cloud.xyz sphere.xyz --path clearance_path.csv --margin 0.6
             MATCH "no_such_cloud.xyz: .*missing file")
  else()
    message(FATAL_ERROR "unknown case ${CASE}")
  endif()
elseif(CASE MATCHES "^contact_time_")
  # pccd contact-time on make_cli_data's unit sphere (2000 points, mean spacing about 0.08) and
  # torus (radii 0.7 and 0.3 about z): analytic first contact times, every JSON field and every
  # --cases row the C++ API's answer bit for bit (contact_time_reference.cpp).
  set(x_4 1 0 0 4 0 1 0 0 0 0 1 0)
  set(x_m4 1 0 0 -4 0 1 0 0 0 0 1 0)
  string(REPLACE ";" "," x_4_csv "${x_4}")
  string(REPLACE ";" "," x_m4_csv "${x_m4}")
  set(ct_fields "\"status\": \"contact\"" "\"t\": [0-9.e-]+," "\"t_low\": [0-9.e-]+," "\"t_high\": [0-9.e-]+,"
                "\"point\": .\n" "\"normal\": .\n" "\"counters\": {" "\"advancement_steps\": [0-9]+"
                "\"near_checks\": [0-9]+" "\"bisection_steps\": [0-9]+" "\"node_pairs\": [0-9]+"
                "\"f_evaluations\": [0-9]+" "\"query_us\": [0-9.e+-]+" "\"motion\": \"linear\"")
  if(CASE STREQUAL "contact_time_json")
    # B from x = 4 to x = -4 through A at rest: the unit spheres touch when their centres are 2
    # apart, at t = 0.25 (a path of length 8: one spacing is 0.01 of time). The contact point is
    # near (1, 0, 0), the normal (the way B leaves A) near +x.
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b ${x_4} --to-b ${x_m4} --json MATCH ${ct_fields}
             "\"from_a\": \\[\n +1\\.0,")
    file(WRITE ${WORK}/contact_time.json "${PCCD_STDOUT}")
    pccd_json_number(t "${PCCD_STDOUT}" t)
    pccd_json_number(t_low "${PCCD_STDOUT}" t_low)
    pccd_json_number(t_high "${PCCD_STDOUT}" t_high)
    pccd_expect_between(${t} 0.235 0.265 "the contact time of unit spheres meeting at t = 0.25")
    pccd_expect_between(${t_low} 0.2 ${t} "t_low")
    pccd_expect_between(${t_high} ${t} ${t} "t_high")
    string(JSON point_x GET "${PCCD_STDOUT}" point 0)
    string(JSON normal_x GET "${PCCD_STDOUT}" normal 0)
    pccd_expect_between(${point_x} 0.9 1.1 "the contact point's x")
    pccd_expect_between(${normal_x} 0.9 1.0 "the contact normal's x")
    pccd_contact_time_reference(json sphere.xyz sphere.xyz contact_time.json --from-b ${x_4_csv} --to-b ${x_m4_csv})
    # The torus (outer radius 1) turning a quarter about z while the sphere comes in along -x and
    # A's centre of the linear motion is off its origin: the C++ answer, whatever the time.
    pccd_run(OK ARGS contact-time torus.ply sphere.xyz --from-a 1 0 0 0 0 1 0 0 0 0 1 0 --to-a 0 -1 0 0.2 1 0 0 0 0 0 1 0
             --centre-a 0.1,0,0 --from-b ${x_4} --to-b ${x_m4} --seed 9 --json MATCH ${ct_fields})
    file(WRITE ${WORK}/contact_time_torus.json "${PCCD_STDOUT}")
    pccd_json_number(t "${PCCD_STDOUT}" t)
    pccd_expect_between(${t} 0.2 0.3 "the sphere reaching the turning torus")
    pccd_contact_time_reference(json torus.ply sphere.xyz contact_time_torus.json --to-a 0,-1,0,0.2,1,0,0,0,0,0,1,0
                                --centre-a 0.1,0,0 --from-b ${x_4_csv} --to-b ${x_m4_csv} --seed 9)
  elseif(CASE STREQUAL "contact_time_text")
    pccd_run(OK ARGS contact-time sphere.xyz torus.ply --from-b ${x_4} --to-b ${x_m4}
             STDOUT_MATCH "A: sphere.xyz, 2000 points" "B: torus.ply, 2000 points" "motion linear, tolerance 0, seed 24301"
                          "\nstatus: contact\n" "\nt: 0\\.2[3-6][0-9]*\n" "\nt_low: 0\\.2[0-9]*\n" "\nt_high: 0\\.2[0-9]*\n"
                          "\npoint: .[-0-9.e]+, [-0-9.e]+, [-0-9.e]+.\n" "\nnormal: ."
                          "\ncounters: advancement_steps [0-9]+ near_checks [0-9]+ bisection_steps [0-9]+ node_pairs [0-9]+ f_evaluations [0-9]+\n"
                          "\nquery_us: [0-9.]+\n")
    # Passing at a gap of 0.5: no contact, t and t_high nan, t_low 1.
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b 1 0 0 4 0 1 0 2.5 0 0 1 0 --to-b 1 0 0 -4 0 1 0 2.5 0 0 1 0
             STDOUT_MATCH "B: the same object as A" "\nstatus: no_contact\n" "\nt: nan\n" "\nt_low: 1\n" "\nt_high: nan\n"
                          "\npoint: none\n" "\nnormal: none\n")
    # A budget of one step: undecided, where it got (t_low 0) and nothing else.
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b ${x_4} --to-b ${x_m4} --max-steps 1 --json
             MATCH "\"status\": \"undecided\"" "\"t\": null" "\"t_low\": 0" "\"t_high\": null" "\"point\": null"
                   "\"max_steps\": 1")
    file(WRITE ${WORK}/contact_time_undecided.json "${PCCD_STDOUT}")
    pccd_contact_time_reference(json sphere.xyz sphere.xyz contact_time_undecided.json --from-b ${x_4_csv} --to-b ${x_m4_csv}
                                --max-steps 1)
  elseif(CASE STREQUAL "contact_time_screw")
    # B screws a quarter turn about z from (3, 0, 0) to (0, 3, 0) towards A resting at (0, 3, 0):
    # the centres are 2 apart when the angle is 2 asin(1/3), at t = asin(7/9) / (pi / 2) = 0.5672
    # (B's centre runs 3 pi / 2 = 4.7 along its arc: a spacing is 0.02 of time).
    set(at_y3 1 0 0 0 0 1 0 3 0 0 1 0)
    string(REPLACE ";" "," at_y3_csv "${at_y3}")
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --motion screw --from-a ${at_y3} --to-a ${at_y3}
             --from-b 1 0 0 3 0 1 0 0 0 0 1 0 --to-b 0 -1 0 0 1 0 0 3 0 0 1 0 --json
             MATCH "\"status\": \"contact\"" "\"motion\": \"screw\"" "\"centre_a\": null")
    file(WRITE ${WORK}/contact_time_screw.json "${PCCD_STDOUT}")
    pccd_json_number(t "${PCCD_STDOUT}" t)
    pccd_expect_between(${t} 0.547 0.587 "the contact time of the screwed sphere")
    pccd_contact_time_reference(json sphere.xyz sphere.xyz contact_time_screw.json --motion screw --from-a ${at_y3_csv}
                                --to-a ${at_y3_csv} --from-b 1,0,0,3,0,1,0,0,0,0,1,0 --to-b 0,-1,0,0,1,0,0,3,0,0,1,0)
    # The same end poses moved linearly: B's centre cuts the corner and meets A earlier (the
    # straight path from (3, 0, 0) to (0, 3, 0) comes within 2 of (0, 3, 0) at t = 0.5286).
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-a ${at_y3} --to-a ${at_y3}
             --from-b 1 0 0 3 0 1 0 0 0 0 1 0 --to-b 0 -1 0 0 1 0 0 3 0 0 1 0 --json MATCH "\"status\": \"contact\"")
    pccd_json_number(t "${PCCD_STDOUT}" t)
    pccd_expect_between(${t} 0.508 0.548 "the contact time of the linearly moved sphere")
  elseif(CASE STREQUAL "contact_time_tolerance")
    # --tolerance 0.4: contact when the gap closes to 0.4, at t = (4 - 2.4) / 8 = 0.2; passing at
    # a gap of 0.5 is no contact for 0.4 but contact for 0.6.
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b ${x_4} --to-b ${x_m4} --tolerance 0.4 --json
             MATCH "\"status\": \"contact\"" "\"tolerance\": 0.4")
    file(WRITE ${WORK}/contact_time_tolerance.json "${PCCD_STDOUT}")
    pccd_json_number(t "${PCCD_STDOUT}" t)
    pccd_expect_between(${t} 0.185 0.215 "the contact time with --tolerance 0.4")
    pccd_contact_time_reference(json sphere.xyz sphere.xyz contact_time_tolerance.json --from-b ${x_4_csv} --to-b ${x_m4_csv}
                                --tolerance 0.4)
    set(past_from 1 0 0 4 0 1 0 2.5 0 0 1 0)
    set(past_to 1 0 0 -4 0 1 0 2.5 0 0 1 0)
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b ${past_from} --to-b ${past_to} --tolerance 0.4 --json
             MATCH "\"status\": \"no_contact\"" "\"t\": null" "\"t_low\": 1")
    pccd_run(OK ARGS contact-time sphere.xyz sphere.xyz --from-b ${past_from} --to-b ${past_to} --tolerance 0.6
             --time-accuracy 0.001 --near-step 0.25 --json
             MATCH "\"status\": \"contact\"" "\"time_accuracy\": 0.001" "\"near_step\": 0.25")
    file(WRITE ${WORK}/contact_time_graze.json "${PCCD_STDOUT}")
    pccd_contact_time_reference(json sphere.xyz sphere.xyz contact_time_graze.json --from-b 1,0,0,4,0,1,0,2.5,0,0,1,0
                                --to-b 1,0,0,-4,0,1,0,2.5,0,0,1,0 --tolerance 0.6 --time-accuracy 0.001 --near-step 0.25)
  elseif(CASE STREQUAL "contact_time_cases")
    # Rows of 48 numbers (A at 0, A at 1, B at 0, B at 1): a header, a comment, a blank line; the
    # sphere through the torus (contact near t = 0.25), passing it at y = 2.5 (no contact), and
    # starting inside it (contact at t = 0).
    set(id "1,0,0,0,0,1,0,0,0,0,1,0")
    set(rows "${id},${id},${x_4_csv},${x_m4_csv}
${id},${id},1,0,0,4,0,1,0,2.5,0,0,1,0,1,0,0,-4,0,1,0,2.5,0,0,1,0
${id},${id},1,0,0,0.5,0,1,0,0,0,0,1,0,1,0,0,5,0,1,0,0,0,0,1,0
")
    file(WRITE ${WORK}/contact_time_cases.csv "a_from,...\n# three motions\n\n${rows}")
    pccd_run(OK ARGS contact-time sphere.xyz torus.ply --cases contact_time_cases.csv
             STDOUT_MATCH "^case,status,t,t_low,t_high,query_us\n1,contact,0\\.2[3-6][0-9]*,0\\.2[0-9]*,0\\.2[0-9]*,[0-9.]+\n2,no_contact,nan,1,nan,[0-9.]+\n3,contact,0,0,0,[0-9.]+\n$"
             MATCH "3 cases")
    file(WRITE ${WORK}/contact_time_cases_out.csv "${PCCD_STDOUT}")
    file(WRITE ${WORK}/contact_time_cases_plain.csv "header\n${rows}")
    pccd_contact_time_reference(cases sphere.xyz torus.ply contact_time_cases_plain.csv contact_time_cases_out.csv)
    # Screw motions over the same rows: the C++ answer too.
    pccd_run(OK ARGS contact-time sphere.xyz torus.ply --cases contact_time_cases.csv --motion screw --seed 3)
    file(WRITE ${WORK}/contact_time_cases_screw.csv "${PCCD_STDOUT}")
    pccd_contact_time_reference(cases sphere.xyz torus.ply contact_time_cases_plain.csv contact_time_cases_screw.csv
                                --motion screw --seed 3)
    # Bad rows stop the command before any query, naming the file and line.
    file(WRITE ${WORK}/contact_time_short_row.csv "${id},${id},${id}\n")
    pccd_run(FAIL ARGS contact-time sphere.xyz sphere.xyz --cases contact_time_short_row.csv
             MATCH "pccd: error: contact_time_short_row.csv:1: expected 48 numbers .*got 36 fields" NO_MATCH "case,status")
    file(WRITE ${WORK}/contact_time_bad_row.csv "${id},${id},${id},1,0,0,nan,0,1,0,0,0,0,1,0\n")
    pccd_run(FAIL ARGS contact-time sphere.xyz sphere.xyz --cases contact_time_bad_row.csv
             MATCH "pccd: error: contact_time_bad_row.csv:1: B at t = 1: rigid transform: translation entry \\(0, 3\\) is nan"
             NO_MATCH "case,status")
  elseif(CASE STREQUAL "contact_time_png")
    file(REMOVE "${WORK}/contact_time.png" "${WORK}/contact_time_start.png")
    pccd_run(OK ARGS contact-time sphere.xyz torus.ply --from-b ${x_4} --to-b ${x_m4} --png contact_time.png
             MATCH "status: contact" "wrote [^\n]*contact_time.png: A blue, B gold at t = 0\\.2[0-9]*, their paths darker, the contact point red")
    pccd_check_png(contact_time.png 800 600)
    pccd_run(OK ARGS contact-time sphere.xyz torus.ply --from-b ${x_4} --to-b ${x_m4} --png contact_time_start.png
             --png-time 0 --json MATCH "\"png_time\": 0(\\.0)?\n")
    pccd_check_png(contact_time_start.png 800 600)
  elseif(CASE STREQUAL "contact_time_bad_arguments")
    # Each refused before any preprocessing with "pccd: error: " and the option's name; never a
    # crash. The last, a motion too fast for any bound, is refused by the library's check.
    set(s sphere.xyz sphere.xyz)
    pccd_run(FAIL ARGS contact-time ${s} --motion spin MATCH "pccd: error: --motion must be linear or screw, not \"spin\"")
    pccd_run(FAIL ARGS contact-time ${s} --motion screw --centre-b 0,0,0
             MATCH "pccd: error: --centre-b applies to --motion linear only")
    pccd_run(FAIL ARGS contact-time ${s} --centre-a 1,2 MATCH "pccd: error: --centre-a expects 3 numbers")
    pccd_run(FAIL ARGS contact-time ${s} --centre-b nan,0,0 MATCH "pccd: error: --centre-b: \"nan\" is not a finite number")
    pccd_run(FAIL ARGS contact-time ${s} --tolerance -1 MATCH "pccd: error: --tolerance -1: must be >= 0")
    pccd_run(FAIL ARGS contact-time ${s} --tolerance inf MATCH "pccd: error: --tolerance: \"inf\" is not a finite number")
    pccd_run(FAIL ARGS contact-time ${s} --time-accuracy 0 MATCH "pccd: error: --time-accuracy 0: must be > 0")
    pccd_run(FAIL ARGS contact-time ${s} --near-step 5 MATCH "pccd: error: --near-step 5: must be in \\(0, 4\\]")
    pccd_run(FAIL ARGS contact-time ${s} --max-steps 0 MATCH "pccd: error: --max-steps 0: must be >= 1")
    pccd_run(FAIL ARGS contact-time ${s} --from-b 1 0 0 nan 0 1 0 0 0 0 1 0
             MATCH "pccd: error: --from-b: rigid transform: translation entry \\(0, 3\\) is nan")
    pccd_run(FAIL ARGS contact-time ${s} --to-a 2 0 0 0 0 1 0 0 0 0 1 0
             MATCH "pccd: error: --to-a: rigid transform: the rotation part scales")
    pccd_run(FAIL ARGS contact-time ${s} --to-b 1 0 0 0 0 1 0 0 0 0 -1 0
             MATCH "pccd: error: --to-b: rigid transform: the rotation part is a reflection")
    pccd_run(FAIL ARGS contact-time ${s} --from-a 1 0 0 MATCH "pccd: error: --from-a expects 12 numbers")
    pccd_run(FAIL ARGS contact-time ${s} --png x.png --png-time 1.5
             MATCH "pccd: error: --png-time 1.5: the time must be in \\[0, 1\\]")
    pccd_run(FAIL ARGS contact-time ${s} --png x.png --png-time -0.25
             MATCH "pccd: error: --png-time -0.25: the time must be in \\[0, 1\\]")
    pccd_run(FAIL ARGS contact-time ${s} --png x.png --png-time nan MATCH "pccd: error: --png-time: \"nan\" is not a finite number")
    pccd_run(FAIL ARGS contact-time ${s} --png-time 0.5 MATCH "--png-time requires --png")
    pccd_run(FAIL ARGS contact-time ${s} --cases contact_time_cases.csv --json MATCH "excludes")
    pccd_run(FAIL ARGS contact-time ${s} --cases no_such_cases.csv MATCH "no_such_cases.csv: .*missing file")
    pccd_run(FAIL ARGS contact-time ${s} --from-b 1 0 0 -1e308 0 1 0 0 0 0 1 0 --to-b 1 0 0 1e308 0 1 0 0 0 0 1 0
             MATCH "pccd: error: time_of_contact: the motions' speed bound inf is not finite")
  else()
    message(FATAL_ERROR "unknown CASE '${CASE}'")
  endif()
elseif(CASE STREQUAL "progress_not_a_terminal")
  # stderr is a pipe here: the preprocessing progress stays off, stderr stays empty.
  pccd_run(OK ARGS info sphere.xyz STDERR_EMPTY)
  pccd_run(OK ARGS collide sphere.xyz torus.ply --transform-b ${shift_1} STDERR_EMPTY)
  pccd_run(OK ARGS bench torus.ply --rotations 1 --distances 0,2.5 STDERR_EMPTY)
elseif(CASE STREQUAL "progress_terminal")
  # The same command on a pseudo-terminal (util-linux's script): every stage is named while it runs.
  find_program(SCRIPT script)
  if(NOT SCRIPT)
    message("PCCD_CLI_TEST_SKIPPED: util-linux's script (a pseudo-terminal) not found")
    return()
  endif()
  execute_process(COMMAND ${SCRIPT} -qec "'${PCCD}' info sphere.xyz" /dev/null WORKING_DIRECTORY ${WORK}
                  INPUT_FILE /dev/null RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("$ script -qec 'pccd info sphere.xyz' /dev/null\n[exit ${rc}]\n${out}${err}")
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "expected exit code 0, got ${rc}")
  endif()
  foreach(stage "kd-tree" "proximity graph" "sampling radius" "CPSP map" "normals" "orientation" "domain" "hierarchy")
    if(NOT out MATCHES "pccd: sphere.xyz \\(2000 points\\): ${stage} \\.\\.\\.")
      message(FATAL_ERROR "the progress does not name the stage ${stage}")
    endif()
  endforeach()
elseif(CASE STREQUAL "world_json")
  # 10 spheres and 10 tori at seeded random poses: the JSON's pairs equal the brute force, and the
  # scene written by --write-scene, read back with one thread, gives the same pairs (and text).
  file(REMOVE "${WORK}/world_scene.csv")
  pccd_run(OK ARGS world --generate sphere.xyz:10 --generate torus.ply:10 --scene-seed 3 --write-scene world_scene.csv
                   --threads 2 --json
           MATCH "\"instances\": 20" "\"pairs\": .\n" "\"status\": \"intersecting\"" "\"narrow_phase_queries\": [1-9]"
                 "\"memory_bytes\": [1-9]" "\"scene\": \"world_scene.csv\"")
  file(WRITE ${WORK}/world.json "${PCCD_STDOUT}")
  string(JSON generated_pairs GET "${PCCD_STDOUT}" pairs)
  pccd_world_reference(world_scene.csv world.json)
  pccd_run(OK ARGS world world_scene.csv --threads 1 --json STDERR_EMPTY)
  string(JSON read_pairs GET "${PCCD_STDOUT}" pairs)
  if(NOT read_pairs STREQUAL generated_pairs)
    message(FATAL_ERROR "the scene read back gives other pairs than the generated one")
  endif()
  string(JSON pair_count LENGTH "${PCCD_STDOUT}" pairs)
  pccd_run(OK ARGS world world_scene.csv
           MATCH "world: 20 instances of 2 objects: sphere.xyz \\(2000 points\\), torus.ply \\(2000 points\\)"
                 "intersecting pairs: ${pair_count} \\(" "\n  [0-9]+ [0-9]+ intersecting at ")
  # Filters: every sphere in group 2, ignoring group 2 -- sphere-sphere pairs disappear.
  file(STRINGS ${WORK}/world_scene.csv lines)
  set(filtered "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^sphere.xyz,")
      string(APPEND filtered "${line},2,0xFFFFFFFD\n")
    else()
      string(APPEND filtered "${line}\n")
    endif()
  endforeach()
  file(WRITE ${WORK}/world_filtered.csv "${filtered}")
  pccd_run(OK ARGS world world_filtered.csv --json)
  file(WRITE ${WORK}/world_filtered.json "${PCCD_STDOUT}")
  pccd_world_reference(world_filtered.csv world_filtered.json)
elseif(CASE STREQUAL "world_png")
  file(REMOVE "${WORK}/world.png")
  pccd_run(OK ARGS world --generate sphere.xyz:6 --generate torus.ply:6 --png world.png --size 320x240
           MATCH "wrote [^\n]*world.png: touching instances red, the others grey")
  pccd_check_png(world.png 320 240)
elseif(CASE STREQUAL "world_bad_input")
  set(row "1,0,0,0,0,1,0,0,0,0,1,0")
  file(WRITE ${WORK}/world_fields.csv "sphere.xyz,${row}\n\nsphere.xyz,1,0,0,0,0,1,0,0,0,0,1\n")
  pccd_run(FAIL ARGS world world_fields.csv
           MATCH "pccd: error: world_fields.csv:3: expected a file and 12 numbers .*got 12 fields")
  file(WRITE ${WORK}/world_nan.csv "file,r00,r01,r02,t0,r10,r11,r12,t1,r20,r21,r22,t2\nsphere.xyz,${row}\nsphere.xyz,1,0,0,nan,0,1,0,0,0,0,1,0\n")
  pccd_run(FAIL ARGS world world_nan.csv MATCH "pccd: error: world_nan.csv:3: pose: .*(NaN|nan|not finite)")
  file(WRITE ${WORK}/world_word.csv "sphere.xyz,1,0,0,0,0,1,0,0,0,0,1,x0\n")
  pccd_run(FAIL ARGS world world_word.csv MATCH "pccd: error: world_word.csv:1: pose: \"x0\" \\(number 12\\) is not a number")
  file(WRITE ${WORK}/world_scaled.csv "sphere.xyz,2,0,0,0,0,2,0,0,0,0,2,0\n")
  pccd_run(FAIL ARGS world world_scaled.csv MATCH "pccd: error: world_scaled.csv:1: pose: rigid transform")
  file(WRITE ${WORK}/world_group.csv "sphere.xyz,${row},-1,1\n")
  pccd_run(FAIL ARGS world world_group.csv MATCH "pccd: error: world_group.csv:1: group \"-1\" is not an integer in \\[0, 2\\^32\\)")
  file(WRITE ${WORK}/world_missing.csv "sphere.xyz,${row}\nno_such_cloud.xyz,${row}\n")
  pccd_run(FAIL ARGS world world_missing.csv MATCH "no_such_cloud.xyz: .*missing file")
  file(WRITE ${WORK}/world_empty.csv "# nothing\n")
  pccd_run(FAIL ARGS world world_empty.csv MATCH "pccd: error: world_empty.csv: no instances")
  pccd_run(FAIL ARGS world no_such_scene.csv MATCH "pccd: error: .*no_such_scene.csv.*does not exist")
  pccd_run(FAIL ARGS world MATCH "pccd: error: give either a scene file")
  pccd_run(FAIL ARGS world world_fields.csv --generate sphere.xyz:3 MATCH "pccd: error: give either a scene file")
  pccd_run(FAIL ARGS world --generate sphere.xyz MATCH "pccd: error: --generate sphere.xyz: expected FILE:COUNT")
  pccd_run(FAIL ARGS world --generate sphere.xyz:0 MATCH "expected FILE:COUNT with COUNT an integer from 1")
elseif(CASE STREQUAL "collide_bunny")
  if(DEFINED ENV{PCCD_DATA_DIR} AND NOT "$ENV{PCCD_DATA_DIR}" STREQUAL "")
    set(DATA_DIR "$ENV{PCCD_DATA_DIR}")
  endif()
  if(DATA_DIR STREQUAL "" OR NOT EXISTS "${DATA_DIR}/bunny00.off")
    message("PCCD_CLI_TEST_SKIPPED: bunny00.off not found (install libcgal-demo or set PCCD_DATA_DIR)")
    return()
  endif()
  pccd_run(OK ARGS collide ${DATA_DIR}/bunny00.off ${DATA_DIR}/bunny00.off --normalize --transform-b 0 -1 0 0.5 1 0 0 0 0 0 1 0 --json
           MATCH "\"intersects\": true" "\"same_object\": true" "\"points\": 1,")
else()
  message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
