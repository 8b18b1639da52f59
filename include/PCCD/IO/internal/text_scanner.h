// PCCD/IO/internal/text_scanner.h -- the text scanning under PCCD's checks of ascii point and mesh
// files (doc/manual/io.md, "How it works" and "Errors"): the File_error every check throws, tokens
// quoted for messages, lines walked with their numbers, whitespace and '#' comments, and strict
// parsing of decimal numbers that reports malformed and overflowing tokens instead of guessing.
// Lines are numbered from 1. This header does not include CGAL.
#pragma once

#include <PCCD/Error.h>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace PCCD::IO::internal {

using PCCD::internal::concat;

[[noreturn]] inline void fail(const std::string& path, const std::string& problem)
{
    throw File_error(path, problem);
}

/// `token` between quotes for a message: at most 24 characters, non-printable bytes shown as '?'.
inline std::string quote_token(std::string_view token)
{
    std::string out = "'";
    const std::size_t n = std::min<std::size_t>(token.size(), 24);
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
    }
    if (token.size() > n) out += "...";
    out += '\'';
    return out;
}

inline bool is_blank(char c) noexcept
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n';
}

inline bool is_blank_text(std::string_view text) noexcept
{
    return std::all_of(text.begin(), text.end(), is_blank);
}

/// `line` up to its first '#' (OFF and XYZ comments).
inline std::string_view strip_comment(std::string_view line) noexcept
{
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// The whitespace-separated tokens of `line`, into `out` (cleared first).
inline void split(std::string_view line, std::vector<std::string_view>& out)
{
    out.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
}

/// Walks the lines of a text; line numbers start at 1. A copy keeps its position.
class Line_cursor {
public:
    explicit Line_cursor(std::string_view text) : m_text(text) {}

    /// The next line, without its '\n'; false at the end of the text.
    bool next(std::string_view& line)
    {
        if (m_position >= m_text.size()) return false;
        std::size_t end = m_text.find('\n', m_position);
        if (end == std::string_view::npos) end = m_text.size();
        line = m_text.substr(m_position, end - m_position);
        m_position = std::min(end + 1, m_text.size());
        ++m_line;
        return true;
    }

    /// The next line that holds something besides whitespace and comments (if `comments`).
    bool next_content(std::string_view& line, bool comments)
    {
        while (next(line))
            if (!is_blank_text(comments ? strip_comment(line) : line)) return true;
        return false;
    }

    /// The number of the line last returned (0 before the first).
    std::size_t line() const noexcept { return m_line; }
    /// The offset of the first character not returned yet.
    std::size_t offset() const noexcept { return m_position; }

private:
    std::string_view m_text;
    std::size_t m_position = 0;
    std::size_t m_line = 0;
};

enum class Number { ok, malformed, overflow };

/// The power of ten of the first significant digit of a well-formed decimal number (1 for "12.5",
/// -3 for "0.00125e0", 400 for "1e400"); 0 for a zero.
inline long long decimal_magnitude(std::string_view token) noexcept
{
    if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
    const std::size_t e = token.find_first_of("eE");
    const std::string_view mantissa = token.substr(0, e);
    long long exponent = 0;
    if (e != std::string_view::npos) {
        std::string_view digits = token.substr(e + 1);
        const bool negative = !digits.empty() && digits[0] == '-';
        if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
        if (std::from_chars(digits.data(), digits.data() + digits.size(), exponent).ec != std::errc())
            exponent = std::numeric_limits<long long>::max() / 4; // more digits than any exponent needs
        if (negative) exponent = -exponent;
    }
    const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
    const std::size_t first = mantissa.find_first_of("123456789");
    if (first == std::string_view::npos) return 0;
    const long long shift = first < point ? static_cast<long long>(point - first) - 1
                                          : -static_cast<long long>(first - point);
    return exponent + shift;
}

/// Parses the whole of `token` as a double (an optional '+' is accepted; "nan" and "inf" parse and
/// are reported by the callers). A value below the smallest subnormal reads as 0, as with strtod.
/// Raises no floating-point exception (PCCD's Debug tests trap them).
inline Number parse_double(std::string_view token, double& value)
{
    if (!token.empty() && token[0] == '+') {
        token.remove_prefix(1);
        if (token.empty() || token[0] == '+' || token[0] == '-') return Number::malformed;
    }
    const char* const first = token.data();
    const char* const last = first + token.size();
    const auto [end, ec] = std::from_chars(first, last, value);
    if (end != last || token.empty()) return Number::malformed;
    if (ec == std::errc::result_out_of_range) { // too large, or too small even for a subnormal
        if (decimal_magnitude(token) > 0) return Number::overflow;
        value = token[0] == '-' ? -0.0 : 0.0;
        return Number::ok;
    }
    return ec == std::errc() ? Number::ok : Number::malformed;
}

/// Parses the whole of `token` as a decimal integer with an optional sign.
inline Number parse_integer(std::string_view token, std::int64_t& value)
{
    if (!token.empty() && token[0] == '+') {
        token.remove_prefix(1);
        if (token.empty() || token[0] == '-') return Number::malformed;
    }
    const char* const first = token.data();
    const char* const last = first + token.size();
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::result_out_of_range) return Number::overflow;
    if (ec != std::errc() || end != last || token.empty()) return Number::malformed;
    return Number::ok;
}

/// " (line L)", or "" for binary data (L == 0).
inline std::string at_line(std::size_t line)
{
    return line == 0 ? std::string() : concat(" (line ", line, ')');
}

} // namespace PCCD::IO::internal
