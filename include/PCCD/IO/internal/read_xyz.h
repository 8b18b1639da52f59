// PCCD/IO/internal/read_xyz.h -- PCCD's reader of XYZ/PWN files (doc/manual/io.md, the XYZ row of
// the format table, "Errors" and "How it works"): the file is read in chunks of 1 MiB, each
// complete line checked by Xyz_check (check_xyz.h; numbers parsed with std::from_chars) and its
// point stored at once, so that memory holds the result and one chunk, never the whole file.
// This header does not include CGAL.
#pragma once

#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/internal/check_xyz.h>
#include <PCCD/IO/internal/read_helpers.h>

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

/// The points (and normals) of the XYZ/PWN file `path`, checked line by line (Xyz_check).
/// Throws File_error on any problem. Memory: the result plus one chunk (or the longest line).
inline Point_data read_xyz_points(const std::string& path)
{
    constexpr std::size_t chunk = std::size_t(1) << 20;
    std::ifstream in = open_file(path);
    const std::optional<std::uintmax_t> file_size = regular_file_size(path);
    Xyz_check check(path);
    Point_data data;
    std::vector<char> buffer(chunk);
    std::size_t begin = 0, end = 0, line_number = 0;
    std::uintmax_t total = 0;
    bool reserved = false;
    double values[6] = {};
    const auto take = [&](std::string_view line) {
        if (!check.line(line, ++line_number, values)) return;
        data.points.emplace_back(values[0], values[1], values[2]);
        if (check.normals()) data.normals.emplace_back(values[3], values[4], values[5]);
    };
    // Reserves once, after the first chunk: the point count of line 1 when there is one, else the
    // file size over the bytes per line of the first chunk, plus 2 %; at most what the file can hold
    // (6 bytes a point).
    const auto reserve = [&] {
        reserved = true;
        if (!file_size || data.points.empty()) return;
        std::uintmax_t estimate = static_cast<std::uintmax_t>(1.02 * double(*file_size) * double(line_number) /
                                                              double(std::max<std::size_t>(begin, 1))) + 16;
        if (check.declared()) estimate = *check.declared();
        estimate = std::min<std::uintmax_t>(estimate, *file_size / 6 + 1);
        data.points.reserve(static_cast<std::size_t>(estimate));
        if (check.normals()) data.normals.reserve(static_cast<std::size_t>(estimate));
    };
    for (;;) {
        const std::size_t n = read_some(path, in, buffer.data() + end, buffer.size() - end);
        end += n;
        total += n;
        const char* const base = buffer.data();
        while (begin < end) {
            const void* newline = std::memchr(base + begin, '\n', end - begin);
            if (newline == nullptr) break;
            const std::size_t at = static_cast<std::size_t>(static_cast<const char*>(newline) - base);
            take(std::string_view(base + begin, at - begin));
            begin = at + 1;
        }
        if (!reserved) reserve();
        if (n == 0) { // the end of the file: a last line without '\n'
            if (begin < end) take(std::string_view(base + begin, end - begin));
            break;
        }
        // Keep the incomplete last line at the front; grow the buffer for a line longer than it.
        std::copy(buffer.begin() + static_cast<std::ptrdiff_t>(begin), buffer.begin() + static_cast<std::ptrdiff_t>(end),
                  buffer.begin());
        end -= begin;
        begin = 0;
        if (end == buffer.size()) buffer.resize(2 * buffer.size());
    }
    if (total == 0) fail(path, "the file is empty");
    check.finish();
    return data;
}

} // namespace PCCD::IO::internal
