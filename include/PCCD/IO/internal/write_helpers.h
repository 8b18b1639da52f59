// PCCD/IO/internal/write_helpers.h -- what write_points and write_triangle_mesh share
// (doc/manual/io.md, "Functions" and "Errors"): the format from the extension, the check of the
// Write_options (Invalid_input), and opening and finishing the file with a File_error when it
// cannot be written completely. This header does not include CGAL.
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace PCCD::IO::internal {

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

} // namespace PCCD::IO::internal
