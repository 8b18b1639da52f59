// PCCD/object_file_info.h -- what a file holds, from its first 24 bytes, before anything loads it:
// an object file of Point_cloud_object::save (the geodesic kernel), one of
// Euclidean_point_cloud_object::save (the lean object, Euclidean kernel), or neither (a point or
// mesh file, or anything else); for an object file, its format version and number of points. The
// magic numbers of both object formats are defined here, once. Programs that take either a point
// file or a prepared object (the pccd tool, the Python module) decide with it which loader to call.
// Implements doc/manual/surface.md, "Object files".
#pragma once

#include <PCCD/Error.h>
#include <PCCD/internal/binary_stream.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

namespace PCCD {

/// The kinds of file object_file_info() tells apart.
enum class Object_file_kind {
    none,      ///< not a PCCD object file: a point or mesh file, or anything else
    geodesic,  ///< Point_cloud_object::save (magic "PCCDOBJ\0"): load with Point_cloud_object<>::load
    euclidean, ///< Euclidean_point_cloud_object::save (magic "PCCDLEAN"): load with Euclidean_point_cloud_object<>::load
};

/// "none", "geodesic" or "euclidean" (the kernel names of the pccd tool and the Python module).
constexpr const char* to_string(Object_file_kind kind) noexcept
{
    switch (kind) {
    case Object_file_kind::geodesic: return "geodesic";
    case Object_file_kind::euclidean: return "euclidean";
    case Object_file_kind::none: break;
    }
    return "none";
}

/// What object_file_info() read: the kind and, for an object file, its opening's figures.
struct Object_file_info {
    Object_file_kind kind = Object_file_kind::none;
    /// The file's format version as stored (0 when kind is none); whether this PCCD reads it is the
    /// loader's check.
    std::uint32_t version = 0;
    /// The number of points the file stores (0 when kind is none).
    std::uint64_t points = 0;
};

namespace internal {

inline constexpr char object_magic[8] = {'P', 'C', 'C', 'D', 'O', 'B', 'J', '\0'};
inline constexpr char lean_object_magic[8] = {'P', 'C', 'C', 'D', 'L', 'E', 'A', 'N'};

} // namespace internal

/// Reads the opening of the file `path` (magic, version, byte-order mark, number of points) and
/// tells what it holds. Only the first 24 bytes are read: the rest of the file (its checksum
/// included) is the loader's to check.
/// \throws File_error when the file cannot be opened, or when it opens like an object file but is
///         cut short before its number of points or was written on a machine of another byte order.
inline Object_file_info object_file_info(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) throw File_error(path, "cannot open the file");
    char opening[24] = {};
    file.read(opening, sizeof opening);
    const auto got = std::size_t(file.gcount());
    Object_file_info info;
    if (got >= 8 && std::memcmp(opening, internal::object_magic, 8) == 0)
        info.kind = Object_file_kind::geodesic;
    else if (got >= 8 && std::memcmp(opening, internal::lean_object_magic, 8) == 0)
        info.kind = Object_file_kind::euclidean;
    else
        return info;
    if (got < sizeof opening) throw File_error(path, "truncated file (an object file's opening is 24 bytes)");
    if (internal::decode_little_endian<std::uint32_t>(opening + 12) != internal::byte_order_mark)
        throw File_error(path, "written on a machine of another byte order");
    info.version = internal::decode_little_endian<std::uint32_t>(opening + 8);
    info.points = internal::decode_little_endian<std::uint64_t>(opening + 16);
    return info;
}

} // namespace PCCD
