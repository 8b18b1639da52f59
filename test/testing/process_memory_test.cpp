// Tests of PCCD/testing/process_memory.h: the resident set and its peak read from
// /proc/self/status follow a block of memory the test touches and frees, and the peak resets.
#include <PCCD/testing/process_memory.h>

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstring>
#include <memory>

TEST_CASE("process memory: the peak follows a touched block and resets", "[testing]")
{
    const long long before = PCCD::testing::status_bytes("VmRSS");
    REQUIRE(before > 0);
    CHECK(PCCD::testing::status_bytes("NoSuchField") == 0);
    REQUIRE(PCCD::testing::reset_peak(true));
    const long long peak0 = PCCD::testing::status_bytes("VmHWM");
    constexpr std::size_t size = std::size_t(64) << 20; // 64 MiB
    {
        const std::unique_ptr<char[]> block(new char[size]);
        std::memset(block.get(), 1, size); // touch every page
        CHECK(PCCD::testing::status_bytes("VmRSS") >= before + (60ll << 20));
        CHECK(block[size - 1] == 1);
    }
    // The block is freed (large blocks go back to the system at once), the peak keeps it.
    const long long peak1 = PCCD::testing::status_bytes("VmHWM");
    CHECK(peak1 >= peak0 + (60ll << 20));
    REQUIRE(PCCD::testing::reset_peak(true));
    CHECK(PCCD::testing::status_bytes("VmHWM") < peak1 - (32ll << 20));
}
