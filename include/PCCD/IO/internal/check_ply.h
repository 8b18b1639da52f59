// PCCD/IO/internal/check_ply.h -- PCCD's strict pass over a PLY file before CGAL reads it
// (doc/manual/io.md, the PLY row of the format table and "Errors"): the header (magic, format,
// elements, property types, the vertex and face properties PCCD and CGAL need), then the ascii or
// binary body (counts, truncation, finite values in range, face indices in range, nothing after the
// last element). Every problem is a File_error naming the line or the element item. This header
// does not include CGAL.
#pragma once

#include <PCCD/IO/internal/finite_checks.h>
#include <PCCD/IO/internal/read_helpers.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace PCCD::IO::internal {

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
