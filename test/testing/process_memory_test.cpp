// Tests of PCCD/testing/process_memory.h: the resident set and its peak read from
// /proc/self/status follow a block of memory the test touches, and a reset brings the peak down
// to the resident set.
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
    // The block is freed; the peak keeps it (whether the allocator gave the pages back or not: a
    // sanitizer's allocator keeps them in quarantine).
    const long long peak1 = PCCD::testing::status_bytes("VmHWM");
    CHECK(peak1 >= peak0 + (60ll << 20));
    // A reset brings the peak down to the resident set as it is now.
    REQUIRE(PCCD::testing::reset_peak(true));
    const long long peak2 = PCCD::testing::status_bytes("VmHWM");
    const long long resident = PCCD::testing::status_bytes("VmRSS");
    CHECK(peak2 <= resident + (8ll << 20));
    CHECK(peak2 >= resident - (8ll << 20));
}
