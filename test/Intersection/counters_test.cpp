// for_each_counter (PCCD/Intersection/Intersection_result.h): the one list of the query counters'
// names that the pccd tool (--json) and the Python module (Result.counters) print. Every counter of
// Intersection_counters is visited once, under a distinct name, in a fixed order; a mutable visit
// reaches every field.
#include <PCCD/Intersection/Intersection_result.h>

#include <catch2/catch.hpp>

#include <cstddef>
#include <set>
#include <string>
#include <vector>

TEST_CASE("for_each_counter visits every counter once, by name", "[intersection][counters]")
{
    std::vector<std::string> names;
    PCCD::for_each_counter(PCCD::Intersection_counters{}, [&](const char* name, std::size_t value) {
        names.emplace_back(name);
        CHECK(value == 0);
    });
    // Every field is a std::size_t counter: a counter added to the struct but not to the list
    // changes the size and fails here.
    CHECK(names.size() * sizeof(std::size_t) == sizeof(PCCD::Intersection_counters));
    CHECK(std::set<std::string>(names.begin(), names.end()).size() == names.size());
    CHECK(names.front() == "f_evaluations");
    CHECK(names.back() == "unverified_crossings");

    // Writing through the visitor reaches each field: value k + 1 for counter k.
    PCCD::Intersection_counters counters;
    std::size_t k = 0;
    PCCD::for_each_counter(counters, [&](const char*, std::size_t& value) { value = ++k; });
    CHECK(counters.f_evaluations == 1);
    CHECK(counters.brackets_tried == 2);
    CHECK(counters.unverified_crossings == names.size());
    std::set<std::size_t> seen;
    PCCD::for_each_counter(counters, [&](const char*, std::size_t value) { seen.insert(value); });
    CHECK(seen.size() == names.size());

    // operator+= adds every counter.
    PCCD::Intersection_counters twice = counters;
    twice += counters;
    k = 0;
    PCCD::for_each_counter(twice, [&](const char* name, std::size_t value) {
        ++k;
        CHECK(value == 2 * k);
        INFO(name);
    });
}
