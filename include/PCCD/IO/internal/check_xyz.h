// PCCD/IO/internal/check_xyz.h -- PCCD's strict check of an XYZ/PWN file, line by line as
// read_xyz.h reads it (doc/manual/io.md, the XYZ row of the format table and "Errors"): an
// optional point count on line 1, then 3 or 6 finite numbers per line, the same on every line,
// '#' comments. Every problem is a File_error naming the line. This header does not include CGAL.
#pragma once

#include <PCCD/IO/internal/finite_checks.h>
#include <PCCD/IO/internal/read_helpers.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace PCCD::IO::internal {

struct Xyz_summary {
    std::size_t points = 0;
    bool normals = false;
};

/// PCCD's check of an XYZ/PWN file, fed one line at a time (read_xyz.h feeds it the lines of a
/// file read in chunks): an optional point count alone on line 1, then one point per line with 3
/// (x y z) or 6 (x y z nx ny nz) finite numbers, the same count on every line; '#' comments.
class Xyz_check {
public:
    explicit Xyz_check(const std::string& path) : m_path(path) {}

    /// Checks line number `at` (from 1, lines in order, without their '\n'). \returns whether it
    /// holds a point; if so, `values` receives its 3 or 6 numbers.
    bool line(std::string_view line, std::size_t at, double* values)
    {
        if (!m_content && !is_blank_text(line)) m_content = true;
        split(strip_comment(line), m_tokens);
        if (m_tokens.empty()) return false;
        const std::string hint = m_first_content ? looks_like(m_tokens[0]) : std::string();
        m_first_content = false;
        if (at == 1 && m_tokens.size() == 1) { // CGAL accepts a point count on the very first line only
            std::int64_t count = 0;
            const Number status = parse_integer(m_tokens[0], count);
            if (status == Number::ok && count < 0)
                fail(m_path, concat("bad header: negative point count ", count, " on line 1"));
            if (status == Number::overflow) fail(m_path, concat("bad header: the point count on line 1 is too large"));
            if (status == Number::ok) {
                m_declared = static_cast<std::uint64_t>(count);
                return false;
            }
        }
        for (std::size_t t = 0; t < m_tokens.size(); ++t) {
            double value = 0;
            const Number status = parse_double(m_tokens[t], value);
            if (status == Number::malformed)
                fail(m_path, concat("malformed number ", quote_token(m_tokens[t]), " on line ", at, hint));
            if (status == Number::overflow)
                fail(m_path, concat("number ", quote_token(m_tokens[t]), " on line ", at, " overflows double"));
            if (t < 6) values[t] = value;
        }
        if (m_tokens.size() != 3 && m_tokens.size() != 6)
            fail(m_path, concat("malformed line ", at, ": it has ", m_tokens.size(),
                                " numbers, expected 3 (x y z) or 6 (x y z nx ny nz)", hint));
        const bool normals = m_tokens.size() == 6;
        if (m_summary.points == 0) {
            m_summary.normals = normals;
            m_first_point_line = at;
        } else if (normals != m_summary.normals) {
            fail(m_path, concat("inconsistent normals: line ", m_first_point_line,
                                normals ? " has no normal" : " has a normal", " but line ", at,
                                normals ? " has one" : " has none"));
        }
        check_finite(m_path, values, "point", m_summary.points, at, "coordinate");
        if (normals) check_finite(m_path, values + 3, "point", m_summary.points, at, "normal");
        ++m_summary.points;
        return true;
    }

    /// Whether the points have normals (6 numbers a line), once line() returned a point.
    bool normals() const noexcept { return m_summary.normals; }

    /// The point count on line 1, if the file has one.
    std::optional<std::uint64_t> declared() const noexcept { return m_declared; }

    /// After the last line: checks the file as a whole (not blank, as many points as line 1
    /// declares, at least one) and returns what it holds.
    Xyz_summary finish() const
    {
        if (!m_content) fail(m_path, "the file is empty (it holds only whitespace)");
        if (m_declared && *m_declared > m_summary.points)
            fail(m_path, concat("truncated: line 1 declares ", *m_declared, " points but the file has only ",
                                m_summary.points));
        if (m_declared && *m_declared < m_summary.points)
            fail(m_path, concat("unexpected data: line 1 declares ", *m_declared, " points but the file has ",
                                m_summary.points));
        if (m_summary.points == 0) fail(m_path, "no points: the file holds no points");
        return m_summary;
    }

private:
    const std::string& m_path;
    std::vector<std::string_view> m_tokens;
    Xyz_summary m_summary;
    std::optional<std::uint64_t> m_declared;
    std::size_t m_first_point_line = 0;
    bool m_first_content = true;
    bool m_content = false;
};

} // namespace PCCD::IO::internal
