// PCCD/IO/Format.h -- the file formats PCCD reads and writes, the choice of a format from a file
// name, and the options of the writers. Implements the format table, "Functions" and
// Write_options of doc/manual/io.md. This header does not include CGAL.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <string>

namespace PCCD::IO {

/// A file format.
enum class Format {
    ply, ///< Stanford PLY, ascii or binary (little or big endian); extension `.ply`.
    off, ///< Object File Format (OFF, NOFF, COFF, CNOFF), ascii; extension `.off`.
    xyz  ///< one point per line, `x y z` or `x y z nx ny nz`; extensions `.xyz` and `.pwn`.
};

/// The name of a format: "PLY", "OFF" or "XYZ".
inline const char* format_name(Format format) noexcept
{
    switch (format) {
    case Format::ply: return "PLY";
    case Format::off: return "OFF";
    case Format::xyz: return "XYZ";
    }
    return "unknown";
}

/// The format named by the extension of `path` (case-insensitive): `.ply`, `.off`, `.xyz` or `.pwn`;
/// no value for any other extension or none.
inline std::optional<Format> format_from_extension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ply") return Format::ply;
    if (ext == ".off") return Format::off;
    if (ext == ".xyz" || ext == ".pwn") return Format::xyz;
    return std::nullopt;
}

/// Options of write_points and write_triangle_mesh.
struct Write_options {
    /// Binary output: PLY only (binary little endian, coordinates as `double`, bit-exact). Asking
    /// for binary OFF or XYZ throws PCCD::Invalid_input.
    bool binary = false;
    /// Significant digits of ascii output, in [1, 17]. With 17 (the default) every double reads
    /// back exactly.
    int precision = 17;
};

} // namespace PCCD::IO
