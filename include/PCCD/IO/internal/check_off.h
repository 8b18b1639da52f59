// PCCD/IO/internal/check_off.h -- PCCD's strict pass over an ascii OFF file before CGAL reads it
// (doc/manual/io.md, the OFF row of the format table and "Errors"): keyword (OFF, NOFF, COFF,
// CNOFF), counts, one vertex and one face per line, finite numbers, colors CGAL can convert, face
// indices in range, nothing after the last face. Every problem is a File_error naming the line.
// This header does not include CGAL.
#pragma once

#include <PCCD/IO/internal/finite_checks.h>
#include <PCCD/IO/internal/read_helpers.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace PCCD::IO::internal {

struct Off_summary {
    std::size_t vertices = 0;
    std::size_t faces = 0;
    bool normals = false; // NOFF / CNOFF
    bool colors = false;  // COFF / CNOFF
};

/// Checks the color of a COFF vertex or face, which CGAL converts to bytes without checking: an
/// index into its 149-color map, or r g b [a] as integers in [0, 255] or as fractions in [0, 1].
inline void check_off_color(const std::string& path, const char* what, std::uint64_t index, std::size_t line,
                            const double* color, std::size_t count)
{
    const auto bad = [&](const char* expected) {
        fail(path, concat("malformed color on line ", line, ": the color of ", what, ' ', index, " is out of range (",
                          expected, ')'));
    };
    for (std::size_t c = 0; c < count; ++c)
        if (!is_finite(color[c])) bad("a color holds finite numbers");
    if (count == 1 && !(color[0] >= 0 && color[0] <= 148 && std::floor(color[0]) == color[0]))
        bad("a color index is an integer in [0, 148]");
    if (count >= 3) {
        const bool integers = std::floor(color[0]) == color[0] && std::floor(color[1]) == color[1] &&
                              std::floor(color[2]) == color[2];
        for (std::size_t c = 0; c < 3; ++c)
            if (color[c] < 0 || color[c] > (integers ? 255.0 : 1.0))
                bad("r g b are integers in [0, 255] or fractions in [0, 1]");
    }
}

/// In COFF, either every vertex (face) has a color or none has: the first one decides.
class Off_color_presence {
public:
    explicit Off_color_presence(const char* what) : m_what(what) {}

    /// Records whether item `index` (on line `line`) has a color; throws if the first one differs.
    void check(const std::string& path, std::uint64_t index, std::size_t line, bool colored)
    {
        if (!m_known) {
            m_known = true;
            m_colored = colored;
            m_first = index;
            m_first_line = line;
        } else if (colored != m_colored) {
            fail(path, concat("inconsistent colors: ", m_what, ' ', m_first, " (line ", m_first_line, ") has ",
                              m_colored ? "a color" : "no color", " but ", m_what, ' ', index, " (line ", line,
                              ") has ", colored ? "one" : "none"));
        }
    }

private:
    const char* m_what;
    bool m_known = false, m_colored = false;
    std::uint64_t m_first = 0;
    std::size_t m_first_line = 0;
};

/// Checks the keyword `token` (on line `line`) of an OFF header: OFF, NOFF, COFF or CNOFF (any
/// other keyword of the family CGAL knows is unsupported). Sets `summary.colors` and `.normals`.
inline void check_off_keyword(const std::string& path, std::string_view token, std::size_t line, Off_summary& summary)
{
    std::string_view k = token;
    const bool textures = k.starts_with("ST");
    if (textures) k.remove_prefix(2);
    bool flags[4] = {};
    const char prefixes[4] = {'C', 'N', '4', 'n'};
    for (int p = 0; p < 4; ++p)
        if (!k.empty() && k.front() == prefixes[p]) {
            flags[p] = true;
            k.remove_prefix(1);
        }
    if (k != "OFF" && k != "SKEL")
        fail(path, concat("bad header: line ", line, " starts with ", quote_token(token), ", expected the keyword OFF",
                          looks_like(token)));
    if (textures || flags[2] || flags[3] || k == "SKEL")
        fail(path, concat("unsupported OFF variant ", quote_token(token), " on line ", line,
                          ": PCCD reads OFF, NOFF, COFF and CNOFF"));
    summary.colors = flags[0];
    summary.normals = flags[1];
}

/// A token of an OFF header and its line.
struct Off_header_token {
    std::string_view text;
    std::size_t line;
};

/// Reads the header of an OFF file, `lines` from its start: the keyword and three counts, possibly
/// over several lines, comments allowed where CGAL's header scanner skips them. Sets `keyword`,
/// `summary.colors` and `.normals`. \returns the keyword and the counts as found (fewer than 4
/// tokens when the text ends before).
inline std::vector<Off_header_token> read_off_header(const std::string& path, Line_cursor& lines, std::string& keyword,
                                                     Off_summary& summary)
{
    std::vector<Off_header_token> header;
    std::string_view line;
    std::vector<std::string_view> tokens;
    while (header.size() < 4 && lines.next(line)) {
        const std::string_view content = strip_comment(line);
        split(content, tokens);
        for (const std::string_view token : tokens) {
            if (header.size() == 4)
                fail(path, concat("bad header: unexpected ", quote_token(token), " after the counts on line ", lines.line()));
            header.push_back({token, lines.line()});
            if (header.size() == 1) {
                keyword = std::string(token);
                check_off_keyword(path, token, lines.line(), summary);
            } else if (header.size() == 2 && token == "BINARY") {
                fail(path, "unsupported OFF variant: binary OFF (PCCD reads ascii OFF only)");
            }
        }
        // CGAL's header scanner skips comments before the keyword, after it (not glued to it) and
        // after the edge count only.
        if (content.size() != line.size()) {
            if (header.size() == 1 && !tokens.empty() && tokens.back().data() + tokens.back().size() == line.data() + content.size())
                fail(path, concat("bad header: a comment is glued to the keyword on line ", lines.line(),
                                  " (put a space before '#')"));
            if (header.size() == 2 || header.size() == 3)
                fail(path, concat("bad header: a comment between the vertex, face and edge counts on line ", lines.line(),
                                  " (the three counts must follow each other)"));
        }
    }
    return header;
}

/// The vertex, face and edge counts of a complete OFF header (keyword and counts), checked: digits
/// only, as CGAL reads them, non-negative, at most INT_MAX.
inline std::array<std::uint64_t, 3> off_counts(const std::string& path, const std::vector<Off_header_token>& header)
{
    static constexpr const char* count_names[3] = {"vertex", "face", "edge"};
    if (header.empty()) fail(path, "the file is empty (it holds only comments)");
    if (header.size() < 4)
        fail(path, concat("bad header: the ", count_names[header.size() - 1], " count is missing after ",
                          quote_token(header.back().text), " (line ", header.back().line,
                          "); an OFF header is the keyword followed by the vertex, face and edge counts"));
    std::array<std::uint64_t, 3> counts{};
    for (int c = 0; c < 3; ++c) {
        const Off_header_token& h = header[static_cast<std::size_t>(c) + 1];
        std::int64_t value = 0;
        // CGAL reads the counts as int and takes only digits for the vertex count.
        const bool digits = std::all_of(h.text.begin() + (h.text.front() == '-' ? 1 : 0), h.text.end(),
                                        [](char ch) { return ch >= '0' && ch <= '9'; }) &&
                            h.text != "-";
        const Number status = digits ? parse_integer(h.text, value) : Number::malformed;
        if (status == Number::malformed)
            fail(path, concat("bad header: malformed ", count_names[c], " count ", quote_token(h.text), " on line ", h.line));
        if (status == Number::overflow || value > std::numeric_limits<int>::max())
            fail(path, concat("bad header: the ", count_names[c], " count ", quote_token(h.text), " on line ", h.line,
                              " is too large"));
        if (value < 0)
            fail(path, concat("bad header: negative ", count_names[c], " count ", value, " on line ", h.line));
        counts[static_cast<std::size_t>(c)] = static_cast<std::uint64_t>(value);
    }
    return counts;
}

/// Records are one per line: counts the lines of data after the header (a copy of `lines`) and
/// throws, with a clear message, unless there are exactly `nv` + `nf`.
inline void check_off_line_count(const std::string& path, Line_cursor lines, std::uint64_t nv, std::uint64_t nf)
{
    std::string_view line;
    std::uint64_t data_lines = 0;
    std::size_t first_extra_line = 0;
    while (lines.next_content(line, true))
        if (++data_lines == nv + nf + 1) first_extra_line = lines.line();
    if (data_lines < nv + nf)
        fail(path, concat("truncated: the header declares ", nv, " vertices and ", nf, " faces (", nv + nf,
                          " lines of data) but only ", data_lines, " follow it"));
    if (data_lines > nv + nf)
        fail(path, concat("unexpected data on line ", first_extra_line, " after the last ", nf > 0 ? "face" : "vertex",
                          ": the header declares ", nv, " vertices and ", nf, " faces"));
}

/// Checks the `nv` vertex lines that follow the header (`lines`): x y z, nx ny nz after a NOFF
/// keyword (`keyword`, for messages), a color of 1, 3 or 4 numbers in COFF, all finite.
inline void check_off_vertices(const std::string& path, Line_cursor& lines, const Off_summary& summary,
                               const std::string& keyword, std::uint64_t nv)
{
    std::string_view line;
    std::vector<std::string_view> tokens;
    Off_color_presence colors("vertex");
    const std::size_t base = summary.normals ? 6 : 3;
    const char* const expected = summary.normals ? "6 (x y z nx ny nz)" : "3 (x y z)";
    for (std::uint64_t i = 0; i < nv; ++i) {
        lines.next_content(line, true);
        split(strip_comment(line), tokens);
        const std::size_t at = lines.line();
        double values[10] = {}; // at most 6 + a color of 4
        for (std::size_t t = 0; t < tokens.size(); ++t) {
            double value = 0;
            const Number status = parse_double(tokens[t], value);
            if (status == Number::malformed)
                fail(path, concat("malformed number ", quote_token(tokens[t]), " on line ", at, " (vertex ", i, ')'));
            if (status == Number::overflow)
                fail(path, concat("number ", quote_token(tokens[t]), " on line ", at, " (vertex ", i, ") overflows double"));
            if (t < 10) values[t] = value;
        }
        if (tokens.size() < base) {
            if (summary.normals && tokens.size() == 3)
                fail(path, concat("inconsistent normals: vertex ", i, " on line ", at, " has no normal although the ",
                                  keyword, " header announces normals"));
            fail(path, concat("malformed vertex on line ", at, ": vertex ", i, " has ", tokens.size(),
                              " numbers, expected ", expected));
        }
        const std::size_t extra = tokens.size() - base;
        if (extra != 0 && !(summary.colors && (extra == 1 || extra == 3 || extra == 4)))
            fail(path, concat("malformed vertex on line ", at, ": vertex ", i, " has ", tokens.size(),
                              " numbers, expected ", expected, summary.colors ? " and a color of 1, 3 or 4 numbers" : "",
                              !summary.normals && tokens.size() == 6 ? " (normals need the NOFF keyword)" : ""));
        check_finite(path, values, "vertex", i, at, "coordinate");
        if (summary.normals) check_finite(path, values + 3, "vertex", i, at, "normal");
        // CGAL reads past the numbers of a line without color once a vertex had one.
        if (summary.colors) colors.check(path, i, at, extra != 0);
        if (summary.colors) check_off_color(path, "vertex", i, at, values + base, extra);
    }
}

/// Checks the `nf` face lines that follow the vertices (`lines`): a vertex count of at least 3, as
/// many indices in [0, nv), then an optional color of 1, 3 or 4 numbers (checked in COFF).
inline void check_off_faces(const std::string& path, Line_cursor& lines, const Off_summary& summary,
                            std::uint64_t nv, std::uint64_t nf)
{
    std::string_view line;
    std::vector<std::string_view> tokens;
    Off_color_presence colors("face");
    for (std::uint64_t f = 0; f < nf; ++f) {
        lines.next_content(line, true);
        split(strip_comment(line), tokens);
        const std::size_t at = lines.line();
        std::int64_t size = 0;
        if (parse_integer(tokens[0], size) != Number::ok)
            fail(path, concat("malformed number ", quote_token(tokens[0]), " on line ", at, " (the vertex count of face ", f, ')'));
        if (size < 3)
            fail(path, concat("malformed face on line ", at, ": face ", f, " has ", size,
                              " vertices, a face needs at least 3"));
        if (static_cast<std::uint64_t>(size) > tokens.size() - 1)
            fail(path, concat("malformed face on line ", at, ": face ", f, " declares ", size, " vertices but lists ",
                              tokens.size() - 1));
        for (std::size_t t = 1; t <= static_cast<std::size_t>(size); ++t) {
            std::int64_t index = 0;
            const Number status = parse_integer(tokens[t], index);
            if (status == Number::malformed)
                fail(path, concat("malformed number ", quote_token(tokens[t]), " on line ", at, " (a vertex index of face ", f, ')'));
            if (status == Number::overflow || index < 0 || static_cast<std::uint64_t>(index) >= nv)
                fail(path, concat("face ", f, " on line ", at, " references vertex ", tokens[t],
                                  ", out of range (the file has ", nv, " vertices)"));
        }
        const std::size_t extra = tokens.size() - 1 - static_cast<std::size_t>(size);
        if (extra != 0 && extra != 1 && extra != 3 && extra != 4)
            fail(path, concat("malformed face on line ", at, ": face ", f, " has ", extra, " values after its ", size,
                              " vertex indices (a face color has 1, 3 or 4)"));
        if (summary.colors) colors.check(path, f, at, extra != 0);
        double color[4] = {};
        for (std::size_t t = 1 + static_cast<std::size_t>(size), c = 0; t < tokens.size(); ++t, ++c) {
            if (parse_double(tokens[t], color[c]) != Number::ok || !is_finite(color[c]))
                fail(path, concat("malformed number ", quote_token(tokens[t]), " on line ", at, " (the color of face ", f, ')'));
        }
        if (summary.colors) check_off_color(path, "face", f, at, color, extra);
    }
}

/// Checks an ascii OFF file: keyword (OFF, NOFF, COFF, CNOFF), counts, one vertex per line with
/// finite numbers, one face per line with at least 3 in-range vertex indices, nothing after.
inline Off_summary check_off(const std::string& path, std::string_view text)
{
    if (is_blank_text(text)) fail(path, "the file is empty (it holds only whitespace)");
    Off_summary summary;
    Line_cursor lines(text);
    std::string keyword;
    const std::vector<Off_header_token> header = read_off_header(path, lines, keyword, summary);
    const std::array<std::uint64_t, 3> counts = off_counts(path, header);
    const std::uint64_t nv = counts[0], nf = counts[1];
    if (nv == 0) fail(path, "no points: the header declares 0 vertices");
    check_off_line_count(path, lines, nv, nf);
    check_off_vertices(path, lines, summary, keyword, nv);
    check_off_faces(path, lines, summary, nv, nf);
    summary.vertices = static_cast<std::size_t>(nv);
    summary.faces = static_cast<std::size_t>(nf);
    return summary;
}

} // namespace PCCD::IO::internal
