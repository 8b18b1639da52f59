// PCCD/IO/internal/ply_header.h -- the header half of PCCD's PLY check (doc/manual/io.md, the PLY
// row of the format table and the "bad header" and "unsupported" cases of "Errors"): the 'ply' and
// 'format' lines, the element and property declarations up to 'end_header', then what PCCD and
// CGAL need of them: a vertex element with float or double x, y, z (and all three of nx, ny, nz or
// none), the face list CGAL's mesh reader takes, and the property types that reader assumes. Every
// problem is a File_error naming the line. This header does not include CGAL.
#pragma once

#include <PCCD/IO/internal/ply_types.h>
#include <PCCD/IO/internal/read_helpers.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace PCCD::IO::internal {

/// Reads the first two lines of the header, 'ply' and 'format <ascii|binary_little_endian|
/// binary_big_endian> 1.0', and sets `summary.binary`. \returns whether the body is big endian.
inline bool read_ply_format(const std::string& path, Line_cursor& lines, Ply_summary& summary)
{
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
    return big_endian;
}

/// The element of an 'element <name> <count>' line (`tokens`, line `at`).
inline Ply_element read_ply_element_line(const std::string& path, const std::vector<std::string_view>& tokens,
                                         std::size_t at)
{
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
    return element;
}

/// Adds the property of a 'property <type> <name>' or 'property list <count type> <item type>
/// <name>' line (`tokens`, line `at`) to the last of `elements`.
inline void read_ply_property_line(const std::string& path, const std::vector<std::string_view>& tokens,
                                   std::size_t at, std::vector<Ply_element>& elements)
{
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
            fail(path, concat("bad header: the count type of list '", tokens[4], "' on line ", at, " is ", tokens[2],
                              ", it must be an integer type"));
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
}

/// The elements the header declares, from the line after 'format' to 'end_header' (comment and
/// obj_info lines skipped); `lines` is left on the 'end_header' line.
inline std::vector<Ply_element> read_ply_elements(const std::string& path, Line_cursor& lines)
{
    std::string_view line;
    std::vector<std::string_view> tokens;
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
            elements.push_back(read_ply_element_line(path, tokens, at));
        } else if (keyword == "property") {
            read_ply_property_line(path, tokens, at, elements);
        } else {
            fail(path, concat("bad header: unknown keyword ", quote_token(keyword), " on line ", at));
        }
    }
    if (!ended) fail(path, "bad header: the header has no 'end_header' line");
    return elements;
}

/// The vertex and the face element of a header (either may be null).
struct Ply_vertex_and_face {
    Ply_element* vertex = nullptr;
    Ply_element* face = nullptr;
};

/// Finds the vertex ('vertex' or 'vertices') and face ('face' or 'faces') elements and sets their
/// kinds; refuses an element with items but no property, and a second vertex or face element.
inline Ply_vertex_and_face find_ply_vertex_and_face(const std::string& path, std::vector<Ply_element>& elements)
{
    Ply_vertex_and_face found;
    for (Ply_element& e : elements) {
        if (e.count > 0 && e.properties.empty())
            fail(path, concat("bad header: element '", e.name, "' on line ", e.line, " declares ", e.count,
                              " items but no property"));
        Ply_element** slot = nullptr;
        if (e.name == "vertex" || e.name == "vertices") {
            slot = &found.vertex;
            e.kind = Ply_element::vertex;
        } else if (e.name == "face" || e.name == "faces") {
            slot = &found.face;
            e.kind = Ply_element::face;
        }
        if (slot && *slot) fail(path, concat("bad header: a second '", e.name, "' element on line ", e.line));
        if (slot) *slot = &e;
    }
    return found;
}

/// Marks the coordinate and normal properties of the vertex element and checks them: x, y, z
/// present, all of float or double type, nx, ny, nz all present or all absent. Sets
/// `summary.normals`.
inline void check_ply_vertex_properties(const std::string& path, Ply_element& vertex, Ply_summary& summary)
{
    static constexpr const char* axes[3] = {"x", "y", "z"};
    static constexpr const char* normal_axes[3] = {"nx", "ny", "nz"};
    bool has[2][3] = {};
    for (Ply_property& p : vertex.properties)
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
}

/// Marks the list CGAL's mesh reader takes as the faces' vertex indices: vertex_indices, else
/// vertex_index, of int or uint. Sets `summary.face_indices`.
inline void mark_ply_face_indices(Ply_element& face, Ply_summary& summary)
{
    for (const char* name : {"vertex_indices", "vertex_index"}) {
        for (Ply_property& p : face.properties)
            if (!summary.face_indices && p.name == name && p.is_list &&
                (p.type == Ply_type::int32 || p.type == Ply_type::uint32)) {
                p.role = Ply_property::face_indices;
                summary.face_indices = true;
            }
    }
}

/// CGAL's mesh reader takes these properties when their names are present and assumes their types
/// (reading another type is undefined behaviour in a release build): requires them.
inline void check_ply_mesh_property_types(const std::string& path, const std::vector<Ply_element>& elements)
{
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

} // namespace PCCD::IO::internal
