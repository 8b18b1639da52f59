// PCCD/IO/internal/check_ply.h -- PCCD's strict pass over a PLY file before CGAL reads it
// (doc/manual/io.md, the PLY row of the format table and "Errors"): the header (ply_header.h),
// then the body, ascii (one element item per line) or binary (either byte order): every item
// complete, values finite and in range of their type, face lists of at least 3 in-range vertex
// indices, nothing after the last element. Every problem is a File_error naming the line (ascii)
// or the element item. This header does not include CGAL.
#pragma once

#include <PCCD/IO/internal/finite_checks.h>
#include <PCCD/IO/internal/ply_header.h>
#include <PCCD/IO/internal/ply_types.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace PCCD::IO::internal {

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

/// Checks item `j` of element `e`, the ascii line `at` split into `tokens`; `nv`: the vertex count.
inline void check_ply_ascii_item(const std::string& path, const Ply_element& e, std::uint64_t j,
                                 const std::vector<std::string_view>& tokens, std::size_t at, std::uint64_t nv,
                                 bool has_normals)
{
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
            fail(path, concat("malformed line ", at, ": the list '", p.name, "' of ", e.name, ' ', j, " declares ",
                              static_cast<long long>(count), " values but the line has ", tokens.size() - t, " left"));
        for (std::uint64_t c = 0; c < static_cast<std::uint64_t>(count); ++c) {
            const double value = ply_ascii_value(path, tokens, t, p.type, e, j, p, at);
            if (p.role == Ply_property::face_indices) ply_check_index(path, j, at, value, nv);
        }
    }
    if (t != tokens.size())
        fail(path, concat("malformed line ", at, ": ", e.name, ' ', j, " has ", tokens.size() - t,
                          " extra value(s) after its properties"));
    ply_check_item(path, e, j, at, coordinates, normal, has_normals);
}

/// Checks an ascii body, `lines` from the 'end_header' line: one item per non-blank line, nothing after.
inline void check_ply_ascii_body(const std::string& path, Line_cursor& lines, const std::vector<Ply_element>& elements,
                                 std::uint64_t nv, bool has_normals)
{
    std::string_view line;
    std::vector<std::string_view> tokens;
    for (const Ply_element& e : elements) {
        for (std::uint64_t j = 0; j < e.count; ++j) {
            if (!lines.next_content(line, false))
                fail(path, concat("truncated: the file ends before ", e.name, ' ', j, " of the ", e.count,
                                  " declared in the header"));
            split(line, tokens);
            check_ply_ascii_item(path, e, j, tokens, lines.line(), nv, has_normals);
        }
    }
    if (lines.next_content(line, false))
        fail(path, concat("unexpected data on line ", lines.line(),
                          " after the last element (do the header's counts match the data?)"));
}

[[noreturn]] inline void ply_binary_truncated(const std::string& path, const Ply_element& e, std::uint64_t j)
{
    fail(path, concat("truncated binary body: the file ends in ", e.name, ' ', j, " of the ", e.count,
                      " declared in the header"));
}

/// Checks item `j` of element `e`, read from `in` (Ply_bytes, or the chunked Ply_stream of
/// read_ply_binary.h); `nv`: the vertex count. `values`, if not null, receives the coordinates and
/// then the normal of a vertex (6 values).
template <class Bytes>
void check_ply_binary_item(const std::string& path, Bytes& in, const Ply_element& e, std::uint64_t j,
                           std::uint64_t nv, bool has_normals, double* values = nullptr)
{
    double coordinates[3] = {}, normal[3] = {};
    for (const Ply_property& p : e.properties) {
        if (!p.is_list) {
            if (in.remaining() < ply_size(p.type)) ply_binary_truncated(path, e, j);
            const double value = in.read(p.type);
            if (p.role == Ply_property::coordinate) coordinates[p.axis] = value;
            if (p.role == Ply_property::normal) normal[p.axis] = value;
            continue;
        }
        if (in.remaining() < ply_size(p.count_type)) ply_binary_truncated(path, e, j);
        const double count = in.read(p.count_type);
        ply_check_face_size(path, e, j, 0, p, count);
        if (count > static_cast<double>(in.remaining() / ply_size(p.type))) ply_binary_truncated(path, e, j);
        if (p.role != Ply_property::face_indices) {
            in.skip(static_cast<std::size_t>(count) * ply_size(p.type));
            continue;
        }
        for (std::uint64_t c = 0; c < static_cast<std::uint64_t>(count); ++c)
            ply_check_index(path, j, 0, in.read(p.type), nv);
    }
    ply_check_item(path, e, j, 0, coordinates, normal, has_normals);
    if (values)
        for (int k = 0; k < 3; ++k) {
            values[k] = coordinates[k];
            values[3 + k] = normal[k];
        }
}

/// Checks a binary body (`body`: the bytes after the header): every item complete, nothing after.
inline void check_ply_binary_body(const std::string& path, std::string_view body, bool big_endian,
                                  const std::vector<Ply_element>& elements, std::uint64_t nv, bool has_normals)
{
    Ply_bytes in(body, big_endian);
    for (const Ply_element& e : elements) {
        const bool fixed_size = std::none_of(e.properties.begin(), e.properties.end(),
                                             [](const Ply_property& p) { return p.is_list; });
        if (fixed_size && e.count > 0) { // fail at once on a count larger than the data
            std::size_t item = 0;
            for (const Ply_property& p : e.properties) item += ply_size(p.type);
            if (e.count > in.remaining() / item) ply_binary_truncated(path, e, in.remaining() / item);
        }
        for (std::uint64_t j = 0; j < e.count; ++j) check_ply_binary_item(path, in, e, j, nv, has_normals);
    }
    if (in.remaining() != 0)
        fail(path, concat("unexpected data: ", in.remaining(),
                          " bytes after the last element (do the header's counts match the data?)"));
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
    const bool big_endian = read_ply_format(path, lines, summary);
    std::vector<Ply_element> elements = read_ply_elements(path, lines);
    const Ply_vertex_and_face found = find_ply_vertex_and_face(path, elements);
    if (!found.vertex) fail(path, "bad header: there is no 'vertex' element");
    check_ply_vertex_properties(path, *found.vertex, summary);
    if (found.vertex->count == 0) fail(path, "no points: the header declares 0 vertices");
    if (found.face) mark_ply_face_indices(*found.face, summary);
    if (need_faces) check_ply_mesh_property_types(path, elements);
    const std::uint64_t nv = found.vertex->count;

    if (!summary.binary)
        check_ply_ascii_body(path, lines, elements, nv, summary.normals);
    else
        check_ply_binary_body(path, text.substr(lines.offset()), big_endian, elements, nv, summary.normals);
    // Checked last, so that a broken body is reported as such by both readers.
    const Ply_element* face = found.face;
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
