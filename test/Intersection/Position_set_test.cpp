// Tests of PCCD/Intersection/internal/Position_set.h against std::set: insert() reports new
// positions exactly once, and mask(first, count) gives the members among first .. first + count - 1
// for runs inside one 64-block, across two blocks, of length 64 and 0, near 0 and near 2^32 - 1,
// while the table grows from empty to thousands of blocks.
#include <PCCD/Intersection/internal/Position_set.h>
#include <PCCD/Random.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <set>

namespace {

std::uint64_t brute_mask(const std::set<std::uint32_t>& set, std::uint32_t first, std::uint32_t count)
{
    std::uint64_t mask = 0;
    for (std::uint32_t i = 0; i < count; ++i)
        if (set.count(first + i)) mask |= std::uint64_t(1) << i;
    return mask;
}

} // namespace

TEST_CASE("Position_set answers as a std::set does", "[intersection]")
{
    PCCD::Random_engine engine(7);
    for (const std::uint32_t base : {0u, 1000u, 0xffffffffu - 5000u}) {
        PCCD::internal::Position_set set;
        std::set<std::uint32_t> truth;
        CHECK(set.mask(base, 64) == 0); // empty
        std::size_t inserted = 0;
        for (int k = 0; k < 20000; ++k) {
            // Clustered positions (a few leaves' worth) and scattered ones, as a walk produces.
            const std::uint32_t p = base + std::uint32_t(k % 3 == 0 ? PCCD::uniform_index(engine, 4000)
                                                                    : PCCD::uniform_index(engine, 300));
            const bool fresh = truth.insert(p).second;
            CHECK(set.insert(p) == fresh);
            inserted += fresh;
            if (k % 7 == 0) {
                const auto first = base + std::uint32_t(PCCD::uniform_index(engine, 4000));
                const auto count = std::uint32_t(PCCD::uniform_index(engine, 65)); // 0 .. 64
                if (std::uint64_t(first) + count <= 0xffffffffull)
                    CHECK(set.mask(first, count) == brute_mask(truth, first, count));
            }
        }
        CHECK(inserted == truth.size());
        // Every run of 8 (a leaf) and of 64 over the range, aligned or not.
        for (std::uint32_t first = base; first < base + 4000; first += 5) {
            CHECK(set.mask(first, 8) == brute_mask(truth, first, 8));
            CHECK(set.mask(first, 64) == brute_mask(truth, first, 64));
        }
    }
}
