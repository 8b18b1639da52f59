// The Catch2 v2 main shared by every PCCD test executable. In Debug builds
// (PCCD_TEST_FP_TRAPS) invalid operations, divisions by zero and overflows trap, so a NaN or an
// infinity is caught where it is born instead of leaking into a result.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#if defined(PCCD_TEST_FP_TRAPS) && defined(__GLIBC__)
#include <fenv.h>
namespace {
const int fp_traps_enabled = feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}
#endif
