# Warning flags for PCCD's own targets (tests, examples, benchmarks, tools): not exported.
add_library(pccd_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(pccd_warnings INTERFACE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endif()
