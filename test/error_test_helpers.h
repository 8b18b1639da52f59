// Checks that an action is rejected with the exact PCCD exception type and a message naming the
// problem (doc/reliability.md): shared by the bad-input catalogue (test/robustness/) and the tests
// of the readers and writers (test/IO/).
#pragma once

#include <PCCD/Error.h>

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace pccd_test {

/// Calls `action` and requires exactly a PCCD::Invalid_input (not a File_error, not another PCCD
/// error, not a standard exception) whose message contains every keyword.
template <class Action>
void require_invalid_input(Action&& action, const std::vector<std::string>& keywords)
{
    try {
        action();
        FAIL("no exception was thrown");
    } catch (const PCCD::File_error& e) {
        FAIL("File_error instead of Invalid_input: " << e.what());
    } catch (const PCCD::Invalid_input& e) {
        const std::string message = e.what();
        INFO("message: " << message);
        for (const std::string& keyword : keywords) CHECK_THAT(message, Catch::Contains(keyword));
    }
}

/// Calls `action` and requires a PCCD::File_error for `path` (File_error::file()) whose message
/// starts with the path and contains every keyword. Any other exception propagates and fails the
/// test.
template <class Action>
void require_file_error(const std::string& path, Action&& action, const std::vector<std::string>& keywords)
{
    INFO("file " << path);
    try {
        action();
        FAIL("no exception was thrown");
    } catch (const PCCD::File_error& e) {
        const std::string message = e.what();
        INFO("message: " << message);
        CHECK(e.file() == path);
        CHECK_THAT(message, Catch::StartsWith(path));
        for (const std::string& keyword : keywords) CHECK_THAT(message, Catch::Contains(keyword));
    }
}

} // namespace pccd_test
