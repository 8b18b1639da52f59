# run_doxygen.cmake -- runs Doxygen with the generated Doxyfile and fails when it warns:
#   cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<Doxyfile> -DOUTPUT=<output dir> -P run_doxygen.cmake
# Used by the `doc` target and by the ctest test `doc_reference`.
file(REMOVE_RECURSE "${OUTPUT}/html")
file(MAKE_DIRECTORY "${OUTPUT}")
file(WRITE "${OUTPUT}/warnings.txt" "")
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ "${OUTPUT}/warnings.txt" warnings)
string(STRIP "${warnings}${err}" problems)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "doxygen failed (${rc}):\n${problems}")
endif()
if(NOT problems STREQUAL "")
  message(FATAL_ERROR "doxygen warned:\n${problems}")
endif()
if(NOT EXISTS "${OUTPUT}/html/index.html" OR NOT EXISTS "${OUTPUT}/html/page_concepts.html")
  message(FATAL_ERROR "doxygen wrote no index.html or no page_concepts.html (the concept pages) in ${OUTPUT}/html")
endif()
message("API reference without warnings: ${OUTPUT}/html/index.html")
