// PCCD/IO/internal/File_checks.h -- PCCD's own strict pass over a point or mesh file.
//
// CGAL's readers return `false` without saying why, accept some broken files silently (an OFF
// vertex line with a bad token is skipped, missing PLY properties read as 0, a PLY header may
// declare negative counts) and can allocate or loop on the counts a header declares. So every
// reader of PCCD first loads the file into memory and runs the check of its format here, which
// throws PCCD::File_error naming the problem (and the line, vertex or face where it is) for every
// unusable file. Only a file that passed is handed to CGAL's reader, whose result is then checked
// against the counts found here.
//
// This header does not include CGAL. Lines are numbered from 1, vertices, points and faces from 0.
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
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

// --- Text scanning -------------------------------------------------------------------------------

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

/// True for the keywords of the OFF family CGAL knows: [ST][C][N][4][n]OFF and SKEL.
inline bool is_off_keyword(std::string_view k) noexcept
{
    if (k.starts_with("ST")) k.remove_prefix(2);
    for (const char prefix : {'C', 'N', '4', 'n'})
        if (!k.empty() && k.front() == prefix) k.remove_prefix(1);
    return k == "OFF" || k == "SKEL";
}

/// A hint naming the format a file seems to be in, from its first token ("" when unsure).
inline std::string looks_like(std::string_view first_token)
{
    if (first_token == "ply") return " (this looks like a PLY file)";
    if (is_off_keyword(first_token)) return " (this looks like an OFF file)";
    double value;
    if (parse_double(first_token, value) == Number::ok) return " (this looks like an XYZ file)";
    return "";
}

/// " (line L)", or "" for binary data (L == 0).
inline std::string at_line(std::size_t line)
{
    return line == 0 ? std::string() : concat(" (line ", line, ')');
}

/// Finiteness and NaN tests on the bits, which raise no floating-point exception even for a
/// signaling NaN (PCCD's Debug tests trap floating-point exceptions).
inline bool is_finite(double x) noexcept
{
    return (std::bit_cast<std::uint64_t>(x) & 0x7FF0000000000000u) != 0x7FF0000000000000u;
}
inline bool is_nan(double x) noexcept
{
    return !is_finite(x) && (std::bit_cast<std::uint64_t>(x) & 0x000FFFFFFFFFFFFFu) != 0;
}
/// True when the three coordinates of `v` (anything with `v[0]`, `v[1]`, `v[2]`) are finite.
template <class Vector3>
bool is_finite(const Vector3& v) noexcept
{
    return is_finite(static_cast<double>(v[0])) && is_finite(static_cast<double>(v[1])) &&
           is_finite(static_cast<double>(v[2]));
}

/// Throws when one of the three values is NaN or infinite: "<what> <index> (line L) has a NaN <kind>".
inline void check_finite(const std::string& path, const double* xyz, const char* what, std::uint64_t index,
                         std::size_t line, const char* kind)
{
    for (int k = 0; k < 3; ++k) {
        if (is_nan(xyz[k])) fail(path, concat(what, ' ', index, at_line(line), " has a NaN ", kind));
        if (!is_finite(xyz[k])) fail(path, concat(what, ' ', index, at_line(line), " has an infinite ", kind));
    }
}

// --- Files ---------------------------------------------------------------------------------------

/// The whole content of the file `path`. Throws File_error if it is missing, a directory,
/// unreadable or empty.
inline std::string load_file(const std::string& path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found)
        fail(path, "cannot open the file: it does not exist (missing file)");
    if (status.type() == fs::file_type::directory) fail(path, "cannot open the file: it is a directory");
    errno = 0;
    std::ifstream in(path, std::ios::in | std::ios::binary);
    if (!in) {
        const int error = errno;
        fail(path, concat("cannot open the file for reading",
                          error != 0 ? concat(" (", std::strerror(error), ')') : std::string()));
    }
    std::string data;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) data.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (in.bad()) fail(path, "cannot read the file (input error)");
    if (data.empty()) fail(path, "the file is empty");
    return data;
}

/// The format to read `path` in, from its extension; `mesh`: for read_triangle_mesh (no XYZ).
inline Format format_for_reading(const std::string& path, bool mesh)
{
    const std::optional<Format> format = format_from_extension(path);
    const std::string ext = std::filesystem::path(path).extension().string();
    const char* const expected = mesh ? ".off and .ply" : ".ply, .off, .xyz and .pwn";
    if (!format || (mesh && *format == Format::xyz))
        fail(path, concat("unknown extension ", ext.empty() ? std::string("(none)") : quote_token(ext), " for a ",
                          mesh ? "triangle mesh" : "point", " file: PCCD reads ", expected, " files"));
    return *format;
}

/// Makes a checked ascii file easy on CGAL's line readers: every blank character becomes a space
/// (CGAL's XYZ reader trims spaces only) and the text ends with a newline (CGAL's OFF reader fails
/// on a last vertex line without one). Token and line structure are unchanged.
inline void prepare_ascii_for_cgal(std::string& text)
{
    for (char& c : text)
        if (c == '\t' || c == '\r' || c == '\v' || c == '\f') c = ' ';
    if (text.empty() || text.back() != '\n') text += '\n';
}

/// CGAL's reader failed or disagreed with the checks on a file that passed them.
[[noreturn]] inline void cgal_disagrees(const std::string& path, Format format, const std::string& detail)
{
    fail(path, concat("CGAL's ", format_name(format), " reader rejected the file although it passed PCCD's checks (",
                      detail, "); please report this as a PCCD bug"));
}

// --- Writing -------------------------------------------------------------------------------------

/// The format to write `path` in, from its extension.
inline Format format_for_writing(const std::string& path, bool mesh)
{
    const std::optional<Format> format = format_from_extension(path);
    const std::string ext = std::filesystem::path(path).extension().string();
    if (!format || (mesh && *format == Format::xyz))
        fail(path, concat("unknown extension ", ext.empty() ? std::string("(none)") : quote_token(ext), " for a ",
                          mesh ? "triangle mesh" : "point", " file: PCCD writes ",
                          mesh ? ".off and .ply" : ".ply, .off, .xyz and .pwn", " files"));
    return *format;
}

/// Throws Invalid_input for options `function` cannot honour.
inline void check_write_options(const char* function, const std::string& path, Format format,
                                const Write_options& options)
{
    if (options.precision < 1 || options.precision > 17)
        throw Invalid_input(concat(function, "(", path, "): precision ", options.precision, " is outside [1, 17]"));
    if (options.binary && format != Format::ply)
        throw Invalid_input(concat(function, "(", path, "): binary output is available for PLY only, not for ",
                                   format_name(format)));
    if (options.binary && std::endian::native != std::endian::little)
        throw Invalid_input(concat(function, "(", path, "): binary PLY output needs a little-endian machine"));
}

/// `path` opened for writing (truncated). Throws File_error if it cannot be.
inline std::ofstream open_for_writing(const std::string& path, bool binary)
{
    errno = 0;
    std::ofstream out(path, binary ? std::ios::out | std::ios::trunc | std::ios::binary : std::ios::out | std::ios::trunc);
    if (!out) {
        const int error = errno;
        fail(path, concat("cannot open the file for writing",
                          error != 0 ? concat(" (", std::strerror(error), ')') : std::string()));
    }
    return out;
}

/// Flushes and closes `out`; throws File_error if the writer (`ok`) or the stream failed.
inline void finish_writing(const std::string& path, std::ofstream& out, bool ok)
{
    if (ok) out.flush();
    if (ok && out) out.close();
    if (!ok || out.fail()) fail(path, "write error: the file could not be written completely");
}

// --- OFF -----------------------------------------------------------------------------------------

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

/// Checks an ascii OFF file: keyword (OFF, NOFF, COFF, CNOFF), counts, one vertex per line with
/// finite numbers, one face per line with at least 3 in-range vertex indices, nothing after.
inline Off_summary check_off(const std::string& path, std::string_view text)
{
    if (is_blank_text(text)) fail(path, "the file is empty (it holds only whitespace)");
    Off_summary summary;
    Line_cursor lines(text);
    std::string_view line;
    std::vector<std::string_view> tokens;

    // The header: the keyword and three counts, possibly over several lines, comments allowed.
    struct Header_token {
        std::string_view text;
        std::size_t line;
    };
    std::vector<Header_token> header;
    std::string keyword;
    while (header.size() < 4 && lines.next(line)) {
        const std::string_view content = strip_comment(line);
        split(content, tokens);
        for (const std::string_view token : tokens) {
            if (header.size() == 4)
                fail(path, concat("bad header: unexpected ", quote_token(token), " after the counts on line ", lines.line()));
            header.push_back({token, lines.line()});
            if (header.size() == 1) {
                keyword = std::string(token);
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
                    fail(path, concat("bad header: line ", lines.line(), " starts with ", quote_token(token),
                                      ", expected the keyword OFF", looks_like(token)));
                if (textures || flags[2] || flags[3] || k == "SKEL")
                    fail(path, concat("unsupported OFF variant ", quote_token(token), " on line ", lines.line(),
                                      ": PCCD reads OFF, NOFF, COFF and CNOFF"));
                summary.colors = flags[0];
                summary.normals = flags[1];
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
    static constexpr const char* count_names[3] = {"vertex", "face", "edge"};
    if (header.empty()) fail(path, "the file is empty (it holds only comments)");
    if (header.size() < 4)
        fail(path, concat("bad header: the ", count_names[header.size() - 1], " count is missing after ",
                          quote_token(header.back().text), " (line ", header.back().line,
                          "); an OFF header is the keyword followed by the vertex, face and edge counts"));
    std::uint64_t counts[3];
    for (int c = 0; c < 3; ++c) {
        const Header_token& h = header[static_cast<std::size_t>(c) + 1];
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
        counts[c] = static_cast<std::uint64_t>(value);
    }
    const std::uint64_t nv = counts[0], nf = counts[1];
    if (nv == 0) fail(path, "no points: the header declares 0 vertices");

    // Records are one per line: count the lines of data first, for a clear truncation message.
    const Line_cursor data_start = lines;
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

    lines = data_start;
    // In COFF, either every vertex (face) has a color or none has: the first one decides.
    struct Colors {
        bool known = false, colored = false;
        std::uint64_t first = 0;
        std::size_t first_line = 0;
    } vertex_colors, face_colors;
    const auto check_colors = [&](const char* what, std::uint64_t index, std::size_t line, bool colored,
                                  Colors& state) {
        if (!state.known) {
            state = {true, colored, index, line};
        } else if (colored != state.colored) {
            fail(path, concat("inconsistent colors: ", what, ' ', state.first, " (line ", state.first_line, ") has ",
                              state.colored ? "a color" : "no color", " but ", what, ' ', index, " (line ", line,
                              ") has ", colored ? "one" : "none"));
        }
    };
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
        if (summary.colors) check_colors("vertex", i, at, extra != 0, vertex_colors);
        if (summary.colors) check_off_color(path, "vertex", i, at, values + base, extra);
    }
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
        if (summary.colors) check_colors("face", f, at, extra != 0, face_colors);
        double color[4] = {};
        for (std::size_t t = 1 + static_cast<std::size_t>(size), c = 0; t < tokens.size(); ++t, ++c) {
            if (parse_double(tokens[t], color[c]) != Number::ok || !is_finite(color[c]))
                fail(path, concat("malformed number ", quote_token(tokens[t]), " on line ", at, " (the color of face ", f, ')'));
        }
        if (summary.colors) check_off_color(path, "face", f, at, color, extra);
    }
    summary.vertices = static_cast<std::size_t>(nv);
    summary.faces = static_cast<std::size_t>(nf);
    return summary;
}

// --- XYZ -----------------------------------------------------------------------------------------

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

// --- PLY -----------------------------------------------------------------------------------------

enum class Ply_type : unsigned char { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline std::optional<Ply_type> ply_type(std::string_view name) noexcept
{
    if (name == "char" || name == "int8") return Ply_type::int8;
    if (name == "uchar" || name == "uint8") return Ply_type::uint8;
    if (name == "short" || name == "int16") return Ply_type::int16;
    if (name == "ushort" || name == "uint16") return Ply_type::uint16;
    if (name == "int" || name == "int32") return Ply_type::int32;
    if (name == "uint" || name == "uint32") return Ply_type::uint32;
    if (name == "float" || name == "float32") return Ply_type::float32;
    if (name == "double" || name == "float64") return Ply_type::float64;
    return std::nullopt;
}

inline const char* ply_type_name(Ply_type type) noexcept
{
    static constexpr const char* names[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
    return names[static_cast<int>(type)];
}

inline std::size_t ply_size(Ply_type type) noexcept
{
    static constexpr std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    return sizes[static_cast<int>(type)];
}

inline bool ply_is_float(Ply_type type) noexcept { return type == Ply_type::float32 || type == Ply_type::float64; }

struct Ply_property {
    enum Role { other, coordinate, normal, face_indices };
    std::string name;
    Ply_type type = Ply_type::float64; // the item type of a list
    bool is_list = false;
    Ply_type count_type = Ply_type::uint8;
    Role role = other;
    int axis = 0; // 0, 1, 2 for x, y, z (or nx, ny, nz)
};

struct Ply_element {
    enum Kind { other, vertex, face };
    std::string name;
    std::uint64_t count = 0;
    std::size_t line = 0;
    std::vector<Ply_property> properties;
    Kind kind = other;
};

struct Ply_summary {
    std::size_t vertices = 0;
    std::size_t faces = 0;    // items of the face element (0 without one)
    bool normals = false;     // the vertex element has nx, ny, nz
    bool binary = false;
    bool face_indices = false; // the face element has a vertex_indices list CGAL reads (int or uint)
};

/// Reads the binary values of a PLY body, in either byte order.
class Ply_bytes {
public:
    Ply_bytes(std::string_view data, bool big_endian)
        : m_data(data), m_swap(big_endian != (std::endian::native == std::endian::big))
    {
    }
    std::size_t remaining() const noexcept { return m_data.size() - m_position; }
    void skip(std::size_t n) noexcept { m_position += n; }

    /// The next value of type `type` as a double (exact for every PLY type).
    double read(Ply_type type) noexcept
    {
        switch (type) {
        case Ply_type::int8: return static_cast<std::int8_t>(raw<std::uint8_t>());
        case Ply_type::uint8: return raw<std::uint8_t>();
        case Ply_type::int16: return static_cast<std::int16_t>(raw<std::uint16_t>());
        case Ply_type::uint16: return raw<std::uint16_t>();
        case Ply_type::int32: return static_cast<std::int32_t>(raw<std::uint32_t>());
        case Ply_type::uint32: return raw<std::uint32_t>();
        case Ply_type::float32: { // a NaN becomes a quiet NaN without a floating-point operation
            const std::uint32_t bits = raw<std::uint32_t>();
            if ((bits & 0x7F800000u) == 0x7F800000u && (bits & 0x007FFFFFu) != 0)
                return std::numeric_limits<double>::quiet_NaN();
            return std::bit_cast<float>(bits);
        }
        case Ply_type::float64: {
            const std::uint64_t bits = raw<std::uint64_t>();
            if ((bits & 0x7FF0000000000000u) == 0x7FF0000000000000u && (bits & 0x000FFFFFFFFFFFFFu) != 0)
                return std::numeric_limits<double>::quiet_NaN();
            return std::bit_cast<double>(bits);
        }
        }
        return 0;
    }

private:
    template <class U>
    U raw() noexcept
    {
        U value;
        std::memcpy(&value, m_data.data() + m_position, sizeof(U));
        m_position += sizeof(U);
        if (m_swap) {
            U swapped = 0;
            for (std::size_t b = 0; b < sizeof(U); ++b) swapped = static_cast<U>((swapped << 8) | ((value >> (8 * b)) & 0xFF));
            value = swapped;
        }
        return value;
    }

    std::string_view m_data;
    std::size_t m_position = 0;
    bool m_swap;
};

inline void ply_check_item(const std::string& path, const Ply_element& e, std::uint64_t j, std::size_t line,
                           const double* coordinates, const double* normal, bool has_normals)
{
    if (e.kind != Ply_element::vertex) return;
    check_finite(path, coordinates, "vertex", j, line, "coordinate");
    if (has_normals) check_finite(path, normal, "vertex", j, line, "normal");
}

inline void ply_check_face_size(const std::string& path, const Ply_element& e, std::uint64_t j, std::size_t line,
                                const Ply_property& p, double count)
{
    if (count < 0)
        fail(path, concat(e.name, ' ', j, at_line(line), " has a negative count ", static_cast<long long>(count),
                          " in list '", p.name, '\''));
    if (p.role == Ply_property::face_indices && count < 3)
        fail(path, concat("malformed face: face ", j, at_line(line), " has ", static_cast<long long>(count),
                          " vertices, a face needs at least 3"));
}

inline void ply_check_index(const std::string& path, std::uint64_t j, std::size_t line, double index,
                            std::uint64_t vertices)
{
    if (index < 0 || index >= static_cast<double>(vertices))
        fail(path, concat("face ", j, at_line(line), " references vertex ", static_cast<long long>(index),
                          ", out of range (the file has ", vertices, " vertices)"));
}

/// One ascii value of type `type` from `tokens[t++]`, with its range checked.
inline double ply_ascii_value(const std::string& path, const std::vector<std::string_view>& tokens, std::size_t& t,
                              Ply_type type, const Ply_element& e, std::uint64_t j, const Ply_property& p,
                              std::size_t line)
{
    if (t >= tokens.size())
        fail(path, concat("malformed line ", line, ": ", e.name, ' ', j, " ends before the end of its property '",
                          p.name, "' (too few values)"));
    const std::string_view token = tokens[t++];
    const auto where = [&] { return concat(" on line ", line, " (", e.name, ' ', j, ", property '", p.name, "')"); };
    if (!ply_is_float(type)) {
        std::int64_t value = 0;
        const Number status = parse_integer(token, value);
        if (status == Number::malformed)
            fail(path, concat("malformed number ", quote_token(token), where(), ": expected an integer of type ", ply_type_name(type)));
        static constexpr std::int64_t lows[] = {-128, 0, -32768, 0, std::numeric_limits<std::int32_t>::min(), 0};
        static constexpr std::int64_t highs[] = {127, 255, 32767, 65535, std::numeric_limits<std::int32_t>::max(),
                                                 std::numeric_limits<std::uint32_t>::max()};
        const int k = static_cast<int>(type);
        if (status == Number::overflow || value < lows[k] || value > highs[k])
            fail(path, concat("value ", quote_token(token), where(), " is out of range for ", ply_type_name(type)));
        return static_cast<double>(value);
    }
    double value = 0;
    const Number status = parse_double(token, value);
    if (status == Number::malformed) fail(path, concat("malformed number ", quote_token(token), where()));
    // The smallest double that rounds to an infinite float: FLT_MAX plus half its ulp.
    constexpr double float_overflow = 0x1.ffffffp+127;
    if (status == Number::overflow ||
        (type == Ply_type::float32 && is_finite(value) && std::fabs(value) >= float_overflow))
        fail(path, concat("number ", quote_token(token), where(), " overflows ", ply_type_name(type)));
    if (!is_finite(value) && p.role == Ply_property::other) // CGAL cannot read "nan" or "inf" in ascii
        fail(path, concat(e.name, ' ', j, " (line ", line, ") has a ", is_nan(value) ? "NaN" : "infinite",
                          " value in property '", p.name, '\''));
    return value;
}

/// Checks a PLY file: header (magic, format, elements with non-negative counts, known property
/// types, a vertex element with float/double x, y, z and optionally nx, ny, nz), then the body,
/// ascii (one element item per line) or binary (size, truncation), values finite and in range, face
/// indices in range, nothing after the last element. `need_faces`: the file must hold faces that
/// CGAL's mesh reader can read.
inline Ply_summary check_ply(const std::string& path, std::string_view text, bool need_faces)
{
    if (is_blank_text(text)) fail(path, "the file is empty (it holds only whitespace)");
    Ply_summary summary;
    Line_cursor lines(text);
    std::string_view line;
    std::vector<std::string_view> tokens;

    lines.next(line);
    split(line, tokens);
    if (tokens.size() != 1 || tokens[0] != "ply")
        fail(path, concat("bad header: the first line is ", quote_token(tokens.empty() ? std::string_view() : tokens[0]),
                          ", expected 'ply'", tokens.empty() ? std::string() : looks_like(tokens[0])));
    if (!lines.next(line)) fail(path, "bad header: the format line is missing after 'ply'");
    split(line, tokens);
    if (tokens.size() != 3 || tokens[0] != "format")
        fail(path, concat("bad header: line 2 is ", quote_token(line), ", expected 'format <ascii|binary_little_endian|",
                          "binary_big_endian> 1.0'"));
    bool big_endian = false;
    if (tokens[1] == "ascii") {
    } else if (tokens[1] == "binary_little_endian") {
        summary.binary = true;
    } else if (tokens[1] == "binary_big_endian") {
        summary.binary = big_endian = true;
    } else {
        fail(path, concat("bad header: unknown PLY format ", quote_token(tokens[1]), " on line 2"));
    }
    // 1.0 is the only PLY version there is; a reader cannot know the layout of any other.
    if (tokens[2] != "1.0" && tokens[2] != "1")
        fail(path, concat("bad header: PLY format version ", quote_token(tokens[2]), " on line 2, this reader knows 1.0"));

    std::vector<Ply_element> elements;
    bool ended = false;
    while (!ended && lines.next(line)) {
        split(line, tokens);
        const std::size_t at = lines.line();
        if (tokens.empty()) fail(path, concat("bad header: empty line ", at, " in the header"));
        const std::string_view keyword = tokens[0];
        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "end_header") {
            if (tokens.size() != 1) fail(path, concat("bad header: unexpected ", quote_token(tokens[1]), " after end_header"));
            ended = true;
        } else if (keyword == "element") {
            if (tokens.size() != 3) fail(path, concat("bad header: line ", at, " should be 'element <name> <count>'"));
            const std::string name(tokens[1]);
            std::int64_t count = 0;
            const Number status = parse_integer(tokens[2], count);
            if (status == Number::malformed)
                fail(path, concat("bad header: malformed count ", quote_token(tokens[2]), " of element '", name, "' on line ", at));
            if (status == Number::overflow)
                fail(path, concat("bad header: the count of element '", name, "' on line ", at, " is too large"));
            if (count < 0) fail(path, concat("bad header: negative count ", count, " of element '", name, "' on line ", at));
            Ply_element element;
            element.name = name;
            element.count = static_cast<std::uint64_t>(count);
            element.line = at;
            elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (elements.empty()) fail(path, concat("bad header: property before any element on line ", at));
            Ply_property p;
            if (tokens.size() >= 2 && tokens[1] == "list") {
                if (tokens.size() != 5)
                    fail(path, concat("bad header: line ", at, " should be 'property list <count type> <item type> <name>'"));
                const auto count_type = ply_type(tokens[2]);
                const auto item_type = ply_type(tokens[3]);
                if (!count_type || !item_type)
                    fail(path, concat("bad header: unknown property type ", quote_token(count_type ? tokens[3] : tokens[2]),
                                      " on line ", at));
                if (ply_is_float(*count_type))
                    fail(path, concat("bad header: the count type of list '", tokens[4], "' on line ", at, " is ",
                                      tokens[2], ", it must be an integer type"));
                p.is_list = true;
                p.count_type = *count_type;
                p.type = *item_type;
                p.name = std::string(tokens[4]);
            } else {
                if (tokens.size() != 3) fail(path, concat("bad header: line ", at, " should be 'property <type> <name>'"));
                const auto type = ply_type(tokens[1]);
                if (!type) fail(path, concat("bad header: unknown property type ", quote_token(tokens[1]), " on line ", at));
                p.type = *type;
                p.name = std::string(tokens[2]);
            }
            for (const Ply_property& q : elements.back().properties)
                if (q.name == p.name)
                    fail(path, concat("bad header: duplicate property '", p.name, "' in element '", elements.back().name,
                                      "' on line ", at));
            elements.back().properties.push_back(std::move(p));
        } else {
            fail(path, concat("bad header: unknown keyword ", quote_token(keyword), " on line ", at));
        }
    }
    if (!ended) fail(path, "bad header: the header has no 'end_header' line");

    Ply_element* vertex = nullptr;
    Ply_element* face = nullptr;
    for (Ply_element& e : elements) {
        if (e.count > 0 && e.properties.empty())
            fail(path, concat("bad header: element '", e.name, "' on line ", e.line, " declares ", e.count,
                              " items but no property"));
        Ply_element** slot = nullptr;
        if (e.name == "vertex" || e.name == "vertices") {
            slot = &vertex;
            e.kind = Ply_element::vertex;
        } else if (e.name == "face" || e.name == "faces") {
            slot = &face;
            e.kind = Ply_element::face;
        }
        if (slot && *slot) fail(path, concat("bad header: a second '", e.name, "' element on line ", e.line));
        if (slot) *slot = &e;
    }
    if (!vertex) fail(path, "bad header: there is no 'vertex' element");
    static constexpr const char* axes[3] = {"x", "y", "z"};
    static constexpr const char* normal_axes[3] = {"nx", "ny", "nz"};
    bool has[2][3] = {};
    for (Ply_property& p : vertex->properties)
        for (int k = 0; k < 3; ++k)
            for (int n = 0; n < 2; ++n)
                if (p.name == (n == 0 ? axes[k] : normal_axes[k])) {
                    if (p.is_list || !ply_is_float(p.type))
                        fail(path, concat("unsupported vertex property: '", p.name, "' is ", p.is_list ? "a list of " : "",
                                          ply_type_name(p.type), ", PCCD reads coordinates and normals stored as float or double"));
                    p.role = n == 0 ? Ply_property::coordinate : Ply_property::normal;
                    p.axis = k;
                    has[n][k] = true;
                }
    for (int k = 0; k < 3; ++k)
        if (!has[0][k]) fail(path, concat("bad header: the vertex element has no '", axes[k], "' property"));
    const int normal_count = has[1][0] + has[1][1] + has[1][2];
    if (normal_count != 0 && normal_count != 3) {
        std::string present, missing;
        for (int k = 0; k < 3; ++k) (has[1][k] ? present : missing) += concat(" '", normal_axes[k], '\'');
        fail(path, concat("inconsistent normals: the vertex element has", present, " but not", missing));
    }
    summary.normals = normal_count == 3;
    if (vertex->count == 0) fail(path, "no points: the header declares 0 vertices");
    if (face) {
        // The list CGAL's mesh reader takes: vertex_indices, else vertex_index, of int or uint.
        for (const char* name : {"vertex_indices", "vertex_index"}) {
            for (Ply_property& p : face->properties)
                if (!summary.face_indices && p.name == name && p.is_list &&
                    (p.type == Ply_type::int32 || p.type == Ply_type::uint32)) {
                    p.role = Ply_property::face_indices;
                    summary.face_indices = true;
                }
        }
    }
    if (need_faces) {
        // CGAL's mesh reader takes these properties when their names are present and assumes their
        // types (reading another type is undefined behaviour in a release build): require them.
        for (const Ply_element& e : elements)
            for (const Ply_property& p : e.properties) {
                const bool color = e.kind != Ply_element::other &&
                                   (p.name == "red" || p.name == "green" || p.name == "blue" || p.name == "r" ||
                                    p.name == "g" || p.name == "b");
                const bool halfedge = e.name == "halfedge" && (p.name == "source" || p.name == "target");
                const Ply_type needed = color ? Ply_type::uint8 : Ply_type::uint32;
                if ((color || halfedge) && (p.is_list || p.type != needed))
                    fail(path, concat("unsupported ", e.name, " property: '", p.name, "' is ", p.is_list ? "a list of " : "",
                                      ply_type_name(p.type), ", the mesh reader (CGAL's) needs ", ply_type_name(needed)));
            }
    }
    const std::uint64_t nv = vertex->count;

    if (!summary.binary) {
        for (const Ply_element& e : elements) {
            for (std::uint64_t j = 0; j < e.count; ++j) {
                if (!lines.next_content(line, false))
                    fail(path, concat("truncated: the file ends before ", e.name, ' ', j, " of the ", e.count,
                                      " declared in the header"));
                split(line, tokens);
                const std::size_t at = lines.line();
                std::size_t t = 0;
                double coordinates[3] = {}, normal[3] = {};
                for (const Ply_property& p : e.properties) {
                    if (!p.is_list) {
                        const double value = ply_ascii_value(path, tokens, t, p.type, e, j, p, at);
                        if (p.role == Ply_property::coordinate) coordinates[p.axis] = value;
                        if (p.role == Ply_property::normal) normal[p.axis] = value;
                        continue;
                    }
                    const double count = ply_ascii_value(path, tokens, t, p.count_type, e, j, p, at);
                    ply_check_face_size(path, e, j, at, p, count);
                    if (count > static_cast<double>(tokens.size() - t))
                        fail(path, concat("malformed line ", at, ": the list '", p.name, "' of ", e.name, ' ', j,
                                          " declares ", static_cast<long long>(count), " values but the line has ", tokens.size() - t, " left"));
                    for (std::uint64_t c = 0; c < static_cast<std::uint64_t>(count); ++c) {
                        const double value = ply_ascii_value(path, tokens, t, p.type, e, j, p, at);
                        if (p.role == Ply_property::face_indices) ply_check_index(path, j, at, value, nv);
                    }
                }
                if (t != tokens.size())
                    fail(path, concat("malformed line ", at, ": ", e.name, ' ', j, " has ", tokens.size() - t,
                                      " extra value(s) after its properties"));
                ply_check_item(path, e, j, at, coordinates, normal, summary.normals);
            }
        }
        if (lines.next_content(line, false))
            fail(path, concat("unexpected data on line ", lines.line(),
                              " after the last element (do the header's counts match the data?)"));
    } else {
        Ply_bytes in(text.substr(lines.offset()), big_endian);
        for (const Ply_element& e : elements) {
            const auto truncated = [&](std::uint64_t j) {
                fail(path, concat("truncated binary body: the file ends in ", e.name, ' ', j, " of the ", e.count,
                                  " declared in the header"));
            };
            const bool fixed_size = std::none_of(e.properties.begin(), e.properties.end(),
                                                 [](const Ply_property& p) { return p.is_list; });
            if (fixed_size && e.count > 0) { // fail at once on a count larger than the data
                std::size_t item = 0;
                for (const Ply_property& p : e.properties) item += ply_size(p.type);
                if (e.count > in.remaining() / item) truncated(in.remaining() / item);
            }
            for (std::uint64_t j = 0; j < e.count; ++j) {
                double coordinates[3] = {}, normal[3] = {};
                for (const Ply_property& p : e.properties) {
                    if (!p.is_list) {
                        if (in.remaining() < ply_size(p.type)) truncated(j);
                        const double value = in.read(p.type);
                        if (p.role == Ply_property::coordinate) coordinates[p.axis] = value;
                        if (p.role == Ply_property::normal) normal[p.axis] = value;
                        continue;
                    }
                    if (in.remaining() < ply_size(p.count_type)) truncated(j);
                    const double count = in.read(p.count_type);
                    ply_check_face_size(path, e, j, 0, p, count);
                    if (count > static_cast<double>(in.remaining() / ply_size(p.type))) truncated(j);
                    if (p.role != Ply_property::face_indices) {
                        in.skip(static_cast<std::size_t>(count) * ply_size(p.type));
                        continue;
                    }
                    for (std::uint64_t c = 0; c < static_cast<std::uint64_t>(count); ++c)
                        ply_check_index(path, j, 0, in.read(p.type), nv);
                }
                ply_check_item(path, e, j, 0, coordinates, normal, summary.normals);
            }
        }
        if (in.remaining() != 0)
            fail(path, concat("unexpected data: ", in.remaining(),
                              " bytes after the last element (do the header's counts match the data?)"));
    }
    // Checked last, so that a broken body is reported as such by both readers.
    if (need_faces) {
        if (!face || face->count == 0)
            fail(path, concat("no faces: the file ", face ? "declares 0 faces" : "has no 'face' element",
                              " (a point cloud? read it with PCCD::IO::read_points)"));
        if (!summary.face_indices)
            fail(path, "unsupported face element: it has no 'vertex_indices' list of int or uint");
    }
    summary.vertices = static_cast<std::size_t>(nv);
    summary.faces = face ? static_cast<std::size_t>(face->count) : 0;
    return summary;
}

} // namespace PCCD::IO::internal
