// Shared helper of the Catch2 tests that need libcgal-demo's meshes (PCCD_DATA_DIR): when the data
// is absent, PCCD_SKIP_TEST prints the marker that pccd_add_test() gives ctest as
// SKIP_REGULAR_EXPRESSION, so that ctest lists the test as skipped (Catch2 2 has no skip of its
// own), and leaves the test case.
#pragma once

#include <catch2/catch.hpp>

#include <iostream>

/// Leaves the current test case, reported to ctest as skipped because of `reason`.
#define PCCD_SKIP_TEST(reason)                                                                     \
    do {                                                                                           \
        std::cout << "PCCD_TEST_SKIPPED: " << reason << std::endl;                                 \
        WARN("skipped: " << reason);                                                               \
        return;                                                                                    \
    } while (false)
