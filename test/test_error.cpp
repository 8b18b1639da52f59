// The exception hierarchy and the check macros.
#include <PCCD/Error.h>
#include <PCCD/Random.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

TEST_CASE("PCCD exceptions derive from the standard ones and from PCCD::Error", "[error]")
{
    CHECK_THROWS_AS(throw PCCD::Invalid_input("x"), std::invalid_argument);
    CHECK_THROWS_AS(throw PCCD::Invalid_input("x"), PCCD::Error);
    CHECK_THROWS_AS(throw PCCD::File_error("a.ply", "truncated"), PCCD::Invalid_input);
    CHECK_THROWS_AS(throw PCCD::Precondition_failure("x"), std::logic_error);
    CHECK_THROWS_AS(throw PCCD::Assertion_failure("x"), PCCD::Error);
    try {
        throw PCCD::File_error("scan.ply", "vertex 3 has a NaN coordinate");
    } catch (const PCCD::Error& e) {
        CHECK(std::string(e.what()) == "scan.ply: vertex 3 has a NaN coordinate");
        CHECK(dynamic_cast<const PCCD::File_error&>(e).file() == "scan.ply");
    }
}

TEST_CASE("check macros throw with the expression and the message", "[error]")
{
    const int n = 0;
    CHECK_NOTHROW(PCCD_precondition(n == 0));
    CHECK_THROWS_AS(PCCD_precondition(n > 0), PCCD::Precondition_failure);
    CHECK_THROWS_WITH(PCCD_precondition_msg(n > 0, "n must be positive"),
                      Catch::Contains("n > 0") && Catch::Contains("n must be positive"));
    CHECK_THROWS_AS(PCCD_assertion(n == 1), PCCD::Assertion_failure);
}

TEST_CASE("random numbers are reproducible and correctly distributed", "[error][random]")
{
    PCCD::Random_engine a(7), b(7);
    for (int i = 0; i < 100; ++i) REQUIRE(PCCD::uniform_01(a) == PCCD::uniform_01(b));

    // The first outputs of mt19937_64 are fixed by the C++ standard, so these values hold on every
    // platform: the 10000th output for the default seed is 9981545732273789042.
    PCCD::Random_engine std_check;
    std_check.discard(9999);
    CHECK(std_check() == 9981545732273789042ULL);

    PCCD::Random_engine e(42);
    const int n = 200000;
    double sum = 0, sum2 = 0;
    int below_half = 0;
    int counts[7] = {};
    for (int i = 0; i < n; ++i) {
        const double u = PCCD::uniform_01(e);
        REQUIRE(u >= 0.0);
        REQUIRE(u < 1.0);
        below_half += u < 0.5;
        const double z = PCCD::standard_normal(e);
        sum += z;
        sum2 += z * z;
        ++counts[PCCD::uniform_index(e, 7)];
    }
    // Tolerances are 5 standard errors (fixed seed: the test is deterministic).
    CHECK(std::abs(below_half / double(n) - 0.5) < 5 * 0.5 / std::sqrt(n));
    CHECK(std::abs(sum / n) < 5 / std::sqrt(n));
    CHECK(std::abs(sum2 / n - 1.0) < 5 * std::sqrt(2.0 / n));
    for (int c : counts) CHECK(std::abs(c / double(n) - 1.0 / 7) < 5 * std::sqrt((1.0 / 7) * (6.0 / 7) / n));
    CHECK_THROWS_AS(PCCD::uniform_index(e, 0), PCCD::Precondition_failure);
}
