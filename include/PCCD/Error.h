// PCCD/Error.h -- the exception hierarchy of PCCD and the check macros that throw it.
//
// Every exception PCCD throws derives both from a standard exception (so generic handlers work)
// and from the tag base PCCD::Error (so `catch (const PCCD::Error&)` catches exactly PCCD's):
//
//   PCCD::Error (abstract tag: what())
//   ├── Invalid_input        : std::invalid_argument   bad data or options given by the caller
//   │   └── File_error       : Invalid_input           unreadable, empty, truncated or malformed file
//   ├── Precondition_failure : std::logic_error        a documented precondition was violated
//   └── Assertion_failure    : std::logic_error        an internal invariant failed (a PCCD bug)
//
// The library never calls assert(), abort() or exit(): a failed check throws.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace PCCD {

/// Tag base of every exception thrown by PCCD. Catch it to handle PCCD's errors only.
class Error {
public:
    virtual ~Error() = default;
    /// The message, the same as the standard base's `what()`.
    virtual const char* what() const noexcept = 0;
};

/// Invalid data or options passed by the caller: empty or non-finite clouds, bad options, ...
/// The message names the problem (which point, which option, which value).
class Invalid_input : public std::invalid_argument, public Error {
public:
    explicit Invalid_input(const std::string& message) : std::invalid_argument(message) {}
    const char* what() const noexcept override { return std::invalid_argument::what(); }
};

/// A file that cannot be used: missing, empty, truncated, malformed or carrying NaN/Inf.
/// The message starts with the file name; `file()` returns it alone.
class File_error : public Invalid_input {
public:
    File_error(std::string file, const std::string& problem)
        : Invalid_input(file + ": " + problem), m_file(std::move(file)) {}
    const std::string& file() const noexcept { return m_file; }

private:
    std::string m_file;
};

/// A documented precondition of a PCCD function was violated by the caller.
class Precondition_failure : public std::logic_error, public Error {
public:
    explicit Precondition_failure(const std::string& message) : std::logic_error(message) {}
    const char* what() const noexcept override { return std::logic_error::what(); }
};

/// An internal invariant of PCCD failed: please report it as a bug.
class Assertion_failure : public std::logic_error, public Error {
public:
    explicit Assertion_failure(const std::string& message) : std::logic_error(message) {}
    const char* what() const noexcept override { return std::logic_error::what(); }
};

namespace internal {

template <class Exception>
[[noreturn]] inline void throw_check_failure(const char* kind, const char* expression, const char* file, int line,
                                             const std::string& message)
{
    std::ostringstream out;
    out << "PCCD " << kind << " violated: " << expression;
    if (!message.empty()) out << " (" << message << ")";
    out << " at " << file << ':' << line;
    throw Exception(out.str());
}

/// Concatenates any streamable arguments into a string (for error messages).
template <class... Args>
std::string concat(const Args&... args)
{
    std::ostringstream out;
    (out << ... << args);
    return out.str();
}

} // namespace internal
} // namespace PCCD

/// \name Check macros
/// `PCCD_precondition(e)` throws PCCD::Precondition_failure when `e` is false; `PCCD_assertion(e)`
/// throws PCCD::Assertion_failure. The `_msg` forms add a message. The `PCCD_debug_*` forms are
/// compiled only without NDEBUG (use them inside hot loops); the `PCCD_expensive_*` forms only when
/// PCCD_CHECK_EXPENSIVE is defined.
/// @{
#define PCCD_precondition_msg(EXPR, MSG)                                                                        \
    ((EXPR) ? static_cast<void>(0)                                                                              \
            : ::PCCD::internal::throw_check_failure<::PCCD::Precondition_failure>("precondition", #EXPR,        \
                                                                                  __FILE__, __LINE__, (MSG)))
#define PCCD_precondition(EXPR) PCCD_precondition_msg(EXPR, "")
#define PCCD_assertion_msg(EXPR, MSG)                                                                           \
    ((EXPR) ? static_cast<void>(0)                                                                              \
            : ::PCCD::internal::throw_check_failure<::PCCD::Assertion_failure>("assertion", #EXPR, __FILE__,    \
                                                                               __LINE__, (MSG)))
#define PCCD_assertion(EXPR) PCCD_assertion_msg(EXPR, "")

#ifndef NDEBUG
#define PCCD_debug_precondition(EXPR) PCCD_precondition(EXPR)
#define PCCD_debug_assertion(EXPR) PCCD_assertion(EXPR)
#else
#define PCCD_debug_precondition(EXPR) static_cast<void>(0)
#define PCCD_debug_assertion(EXPR) static_cast<void>(0)
#endif

#ifdef PCCD_CHECK_EXPENSIVE
#define PCCD_expensive_precondition(EXPR) PCCD_precondition(EXPR)
#define PCCD_expensive_assertion(EXPR) PCCD_assertion(EXPR)
#else
#define PCCD_expensive_precondition(EXPR) static_cast<void>(0)
#define PCCD_expensive_assertion(EXPR) static_cast<void>(0)
#endif
/// @}
