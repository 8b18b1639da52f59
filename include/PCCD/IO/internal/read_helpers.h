// PCCD/IO/internal/read_helpers.h -- what every PCCD reader does around the check of its format
// (doc/manual/io.md, "Functions" and "How it works"): open the file, or load the whole of it into
// memory, with a File_error for a missing, unreadable or empty one; choose the format from the
// extension; hint at the format a misnamed file seems to be in; make a checked ascii file easy on
// CGAL's line readers; and report a CGAL reader that disagrees with the checks. This header does
// not include CGAL.
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/internal/text_scanner.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace PCCD::IO::internal {

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

/// Opens the file `path` for binary reading. Throws File_error if it is missing, a directory or
/// unreadable.
inline std::ifstream open_file(const std::string& path)
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
    return in;
}

/// The size in bytes of the regular file `path`, or nothing for another kind of file (a pipe, a
/// device), whose size is only known once it is read.
inline std::optional<std::uintmax_t> regular_file_size(const std::string& path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return std::nullopt;
    return size;
}

/// Up to `n` bytes of `in` into `out`; the number read. Throws File_error on an input error.
inline std::size_t read_some(const std::string& path, std::ifstream& in, char* out, std::size_t n)
{
    in.read(out, static_cast<std::streamsize>(n));
    if (in.bad()) fail(path, "cannot read the file (input error)");
    return static_cast<std::size_t>(in.gcount());
}

/// The whole content of the file `path`. Throws File_error if it is missing, a directory,
/// unreadable or empty.
inline std::string load_file(const std::string& path)
{
    std::ifstream in = open_file(path);
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

} // namespace PCCD::IO::internal
