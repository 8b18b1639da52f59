// PCCD/IO/internal/check_xyz.h -- PCCD's strict pass over an XYZ/PWN file before CGAL reads it
// (doc/manual/io.md, the XYZ row of the format table and "Errors"): an optional point count on
// line 1, then 3 or 6 finite numbers per line, the same on every line, '#' comments. Every
// problem is a File_error naming the line. This header does not include CGAL.
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

/// Checks an XYZ/PWN file: an optional point count alone on line 1, then one point per line with
/// 3 (x y z) or 6 (x y z nx ny nz) finite numbers, the same count on every line; '#' comments.
inline Xyz_summary check_xyz(const std::string& path, std::string_view text)
{
    if (is_blank_text(text)) fail(path, "the file is empty (it holds only whitespace)");
    Xyz_summary summary;
    Line_cursor lines(text);
    std::string_view line;
    std::vector<std::string_view> tokens;
    std::optional<std::uint64_t> declared;
    std::size_t first_point_line = 0;
    bool first_content = true;
    while (lines.next(line)) {
        split(strip_comment(line), tokens);
        if (tokens.empty()) continue;
        const std::size_t at = lines.line();
        const std::string hint = first_content ? looks_like(tokens[0]) : std::string();
        first_content = false;
        if (at == 1 && tokens.size() == 1) { // CGAL accepts a point count on the very first line only
            std::int64_t count = 0;
            const Number status = parse_integer(tokens[0], count);
            if (status == Number::ok && count < 0)
                fail(path, concat("bad header: negative point count ", count, " on line 1"));
            if (status == Number::overflow) fail(path, concat("bad header: the point count on line 1 is too large"));
            if (status == Number::ok) {
                declared = static_cast<std::uint64_t>(count);
                continue;
            }
        }
        double values[6] = {};
        for (std::size_t t = 0; t < tokens.size(); ++t) {
            double value = 0;
            const Number status = parse_double(tokens[t], value);
            if (status == Number::malformed)
                fail(path, concat("malformed number ", quote_token(tokens[t]), " on line ", at, hint));
            if (status == Number::overflow)
                fail(path, concat("number ", quote_token(tokens[t]), " on line ", at, " overflows double"));
            if (t < 6) values[t] = value;
        }
        if (tokens.size() != 3 && tokens.size() != 6)
            fail(path, concat("malformed line ", at, ": it has ", tokens.size(),
                              " numbers, expected 3 (x y z) or 6 (x y z nx ny nz)", hint));
        const bool normals = tokens.size() == 6;
        if (summary.points == 0) {
            summary.normals = normals;
            first_point_line = at;
        } else if (normals != summary.normals) {
            fail(path, concat("inconsistent normals: line ", first_point_line, normals ? " has no normal" : " has a normal",
                              " but line ", at, normals ? " has one" : " has none"));
        }
        check_finite(path, values, "point", summary.points, at, "coordinate");
        if (normals) check_finite(path, values + 3, "point", summary.points, at, "normal");
        ++summary.points;
    }
    if (declared && *declared > summary.points)
        fail(path, concat("truncated: line 1 declares ", *declared, " points but the file has only ", summary.points));
    if (declared && *declared < summary.points)
        fail(path, concat("unexpected data: line 1 declares ", *declared, " points but the file has ", summary.points));
    if (summary.points == 0) fail(path, "no points: the file holds no points");
    return summary;
}

} // namespace PCCD::IO::internal
