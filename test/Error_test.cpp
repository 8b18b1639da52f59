// The exception hierarchy and the check macros.
#include <PCCD/Error.h>

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
