# Compile options for PCCD's own targets (tests, examples, benchmarks, tools): warnings, optional
# sanitizers (PCCD_SANITIZE) and, in Debug test builds, floating-point traps. Not exported.
add_library(pccd_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(pccd_warnings INTERFACE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endif()
if(PCCD_SANITIZE)
  target_compile_options(pccd_warnings INTERFACE -fsanitize=${PCCD_SANITIZE} -fno-omit-frame-pointer
                         -fno-sanitize-recover=all)
  target_link_options(pccd_warnings INTERFACE -fsanitize=${PCCD_SANITIZE})
endif()
