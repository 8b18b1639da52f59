// PCCD/IO/internal/read_ply_binary.h -- PCCD's reader of binary PLY point files, either byte order
// (doc/manual/io.md, the PLY row of the format table, "Errors" and "How it works"): the header is
// read and checked first (ply_header.h), the file size compared with what the header declares,
// then the body is read in chunks of about 1 MiB straight into the Point_data, with the checks of
// check_ply.h (every item complete, coordinates and normals finite, face lists and indices valid,
// nothing after the last element). Memory holds the result and one chunk, never the whole file.
// An ascii PLY is left to the caller (read_points.h reads it whole). This header does not include
// CGAL.
#pragma once

#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/internal/check_ply.h>
#include <PCCD/IO/internal/ply_header.h>
#include <PCCD/IO/internal/ply_types.h>
#include <PCCD/IO/internal/read_helpers.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace PCCD::IO::internal {

/// The bytes of a binary PLY body, read from a file in chunks; the interface of Ply_bytes
/// (remaining, skip, read), plus need/consume for a run of fixed-size items.
class Ply_stream {
public:
    /// `first`: the bytes of the body already read with the header; `body_size`: the size of the
    /// whole body (the file size minus the header).
    Ply_stream(const std::string& path, std::ifstream& in, std::string_view first, std::uint64_t body_size,
               bool big_endian)
        : m_path(path), m_in(in), m_buffer(first.begin(), first.end()), m_end(first.size()),
          m_unread(body_size - first.size()), m_remaining(body_size), m_big_endian(big_endian)
    {
    }

    /// The bytes of the body not consumed yet.
    std::uint64_t remaining() const noexcept { return m_remaining; }

    /// At least `n` bytes of the body (n <= remaining()), from the current position.
    const char* need(std::size_t n)
    {
        if (m_end - m_begin < n) fill(n);
        return m_buffer.data() + m_begin;
    }
    void consume(std::size_t n) noexcept
    {
        m_begin += n;
        m_remaining -= n;
    }

    /// Skips `n` bytes (n <= remaining()).
    void skip(std::size_t n)
    {
        while (n > 0) {
            const std::size_t step = std::min<std::size_t>(n, chunk);
            need(step);
            consume(step);
            n -= step;
        }
    }

    /// The next value of type `type` as a double (see Ply_bytes::read).
    double read(Ply_type type)
    {
        const std::size_t size = ply_size(type);
        Ply_bytes value(std::string_view(need(size), size), m_big_endian);
        consume(size);
        return value.read(type);
    }

    static constexpr std::size_t chunk = std::size_t(1) << 20;

private:
    void fill(std::size_t n)
    {
        std::memmove(m_buffer.data(), m_buffer.data() + m_begin, m_end - m_begin);
        m_end -= m_begin;
        m_begin = 0;
        if (m_buffer.size() < std::max(n, chunk)) m_buffer.resize(std::max(n, chunk));
        const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(m_buffer.size() - m_end, m_unread));
        const std::size_t got = read_some(m_path, m_in, m_buffer.data() + m_end, want);
        m_end += got;
        m_unread -= got;
        if (got < want || m_end < n) fail(m_path, "cannot read the file: it became shorter while it was read");
    }

    const std::string& m_path;
    std::ifstream& m_in;
    std::vector<char> m_buffer;
    std::size_t m_begin = 0, m_end;
    std::uint64_t m_unread, m_remaining;
    bool m_big_endian;
};

/// The header of a PLY file: its text (with the first bytes of the body), the checked elements.
struct Ply_head {
    std::string text;
    std::size_t body_offset = 0;
    bool big_endian = false;
    Ply_summary summary;
    std::vector<Ply_element> elements;
};

/// True when `text` holds, on a line ending in '\n', the first token 'end_header' (or a non-blank
/// first line that is not 'ply': a header that will fail at once).
inline bool ply_header_complete(std::string_view text)
{
    std::vector<std::string_view> tokens;
    std::size_t start = 0, number = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string_view::npos; start = end + 1) {
        split(text.substr(start, end - start), tokens);
        if (++number == 1 && !tokens.empty() && !(tokens.size() == 1 && tokens[0] == "ply")) return true;
        if (!tokens.empty() && tokens[0] == "end_header") return true;
    }
    return false;
}

/// Reads and checks the header of the PLY file `in` of `size` bytes (ply_header.h, as check_ply
/// does for point files), reading 64 KiB at a time until the 'end_header' line.
inline Ply_head read_ply_head(const std::string& path, std::ifstream& in, std::uint64_t size)
{
    Ply_head head;
    std::size_t want = std::size_t(1) << 16;
    for (;;) {
        const std::size_t have = head.text.size();
        const std::size_t step = static_cast<std::size_t>(std::min<std::uint64_t>(want - have, size - have));
        head.text.resize(have + step);
        head.text.resize(have + read_some(path, in, head.text.data() + have, step));
        if (head.text.size() < have + step) fail(path, "cannot read the file: it became shorter while it was read");
        if (head.text.size() == size || ply_header_complete(head.text)) break;
        want *= 2;
    }
    if (head.text.empty()) fail(path, "the file is empty");
    if (head.text.size() == size && is_blank_text(head.text)) fail(path, "the file is empty (it holds only whitespace)");
    Line_cursor lines(head.text);
    head.big_endian = read_ply_format(path, lines, head.summary);
    head.elements = read_ply_elements(path, lines);
    const Ply_vertex_and_face found = find_ply_vertex_and_face(path, head.elements);
    if (!found.vertex) fail(path, "bad header: there is no 'vertex' element");
    check_ply_vertex_properties(path, *found.vertex, head.summary);
    if (found.vertex->count == 0) fail(path, "no points: the header declares 0 vertices");
    if (found.face) mark_ply_face_indices(*found.face, head.summary);
    head.summary.vertices = static_cast<std::size_t>(found.vertex->count);
    head.body_offset = lines.offset();
    return head;
}

/// The vertices of a fixed-size vertex element `e` (every property a scalar), `count` items read
/// from `in` chunk by chunk into `data`.
inline void read_ply_fixed_vertices(const std::string& path, Ply_stream& in, const Ply_element& e, bool big_endian,
                                    bool has_normals, Point_data& data)
{
    struct Slot {
        std::size_t offset = 0;
        Ply_type type = Ply_type::float64;
    };
    Slot slots[6];
    std::size_t item = 0;
    for (const Ply_property& p : e.properties) {
        if (p.role == Ply_property::coordinate) slots[p.axis] = {item, p.type};
        if (p.role == Ply_property::normal) slots[3 + p.axis] = {item, p.type};
        item += ply_size(p.type);
    }
    const int used = has_normals ? 6 : 3;
    const std::uint64_t per_chunk = std::max<std::size_t>(1, Ply_stream::chunk / item);
    for (std::uint64_t j = 0; j < e.count;) {
        const std::size_t k = static_cast<std::size_t>(std::min(per_chunk, e.count - j));
        const char* const bytes = in.need(k * item);
        for (std::size_t i = 0; i < k; ++i, ++j) {
            const char* const at = bytes + i * item;
            double v[6] = {};
            for (int s = 0; s < used; ++s) {
                const std::size_t size = ply_size(slots[s].type);
                v[s] = Ply_bytes(std::string_view(at + slots[s].offset, size), big_endian).read(slots[s].type);
            }
            ply_check_item(path, e, j, 0, v, v + 3, has_normals);
            data.points.emplace_back(v[0], v[1], v[2]);
            if (has_normals) data.normals.emplace_back(v[3], v[4], v[5]);
        }
        in.consume(k * item);
    }
}

/// The points (and normals) of the PLY file `path` if it is binary, read in chunks; nothing for an
/// ascii PLY (or a file that is not a regular file), which the caller reads whole. Throws
/// File_error for every problem check_ply reports, with the same messages.
inline std::optional<Point_data> read_binary_ply_points(const std::string& path)
{
    std::ifstream in = open_file(path);
    const std::optional<std::uintmax_t> size = regular_file_size(path);
    if (!size) return std::nullopt;
    Ply_head head = read_ply_head(path, in, *size);
    if (!head.summary.binary) return std::nullopt;
    const std::uint64_t nv = head.summary.vertices;
    const bool has_normals = head.summary.normals;
    Ply_stream body(path, in, std::string_view(head.text).substr(head.body_offset), *size - head.body_offset,
                    head.big_endian);
    head.text = std::string();
    Point_data data;
    for (const Ply_element& e : head.elements) {
        const bool fixed_size = std::none_of(e.properties.begin(), e.properties.end(),
                                             [](const Ply_property& p) { return p.is_list; });
        std::size_t least = 0; // the size of an item, or the least size with lists (all empty)
        for (const Ply_property& p : e.properties) least += ply_size(p.is_list ? p.count_type : p.type);
        if (fixed_size && e.count > 0 && e.count > body.remaining() / least) // the file is shorter than declared
            ply_binary_truncated(path, e, body.remaining() / least);
        if (e.kind != Ply_element::vertex) {
            double ignored[6];
            for (std::uint64_t j = 0; j < e.count; ++j)
                check_ply_binary_item(path, body, e, j, nv, has_normals, ignored);
            continue;
        }
        const std::size_t reserve = static_cast<std::size_t>(std::min<std::uint64_t>(e.count, body.remaining() / least));
        data.points.reserve(reserve);
        if (has_normals) data.normals.reserve(reserve);
        if (fixed_size) {
            read_ply_fixed_vertices(path, body, e, head.big_endian, has_normals, data);
            continue;
        }
        double v[6];
        for (std::uint64_t j = 0; j < e.count; ++j) {
            check_ply_binary_item(path, body, e, j, nv, has_normals, v);
            data.points.emplace_back(v[0], v[1], v[2]);
            if (has_normals) data.normals.emplace_back(v[3], v[4], v[5]);
        }
    }
    if (body.remaining() != 0)
        fail(path, concat("unexpected data: ", body.remaining(),
                          " bytes after the last element (do the header's counts match the data?)"));
    return data;
}

} // namespace PCCD::IO::internal
