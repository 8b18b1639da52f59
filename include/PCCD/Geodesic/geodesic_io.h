// PCCD/Geodesic/geodesic_io.h -- saving and loading the preprocessed geodesic data of a cloud (its
// proximity graph and CPSP map) in one binary file, so that the O(N log N) preprocessing is paid
// once. Implements doc/manual/graphs.md, "Saving and loading"; the bytes go through the binary
// reader and writer of PCCD/internal/binary_stream.h.
//
// Format (version 1, little-endian whatever the host, every field at its natural size, no padding):
//   magic "PCCDGEO\0" | u32 version | u32 byte-order mark 0x01020304
//   u8 graph kind | u32 graph parameter | u64 N | u64 E (stored edge directions)
//   f64 sampling radius | f64 support eta | u64 M (CPSP entries)
//   u64 row offsets[N + 1] | u32 targets[E] | f32 lengths[E] | u8 virtual flags[E]
//   u64 CPSP offsets[N + 1] | u32 CPSP targets[M] | f32 CPSP distances[M] | u32 CPSP predecessors[M]
//   u64 checksum (FNV-1a over the little-endian 64-bit words of everything before it, zero-padded tail)
// The reader checks the magic, version, byte order, exact file size, checksum and the structure
// (offsets, index ranges, symmetric graph, sorted lists), so a file from another version, a
// truncated or corrupted file is a File_error, never undefined behaviour.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/internal/binary_stream.h>

namespace PCCD {

/// The version of the geodesic file format written by write_geodesic_data().
inline constexpr std::uint32_t geodesic_file_version = 1;

/// What a geodesic file holds.
struct Geodesic_data {
    Proximity_graph graph;
    Close_pairs_shortest_paths cpsp;
};

namespace internal {

inline constexpr char geodesic_magic[8] = {'P', 'C', 'C', 'D', 'G', 'E', 'O', '\0'};

inline std::uint64_t geodesic_file_size(std::uint64_t n, std::uint64_t e, std::uint64_t m)
{
    const std::uint64_t header = 8 + 4 + 4 + 1 + 4 + 8 + 8 + 8 + 8 + 8;
    return header + (n + 1) * 8 + e * (4 + 4 + 1) + (n + 1) * 8 + m * (4 + 4 + 4) + 8;
}

} // namespace internal

namespace internal {

/// \throws Invalid_input unless `cpsp` has one list per vertex of `graph`.
inline void check_same_points(const Proximity_graph& graph, const Close_pairs_shortest_paths& cpsp)
{
    if (graph.num_vertices() != cpsp.size())
        throw Invalid_input(internal::concat("geodesic file: the graph has ", graph.num_vertices(),
                                             " points but the CPSP map ", cpsp.size()));
}

/// The body of write_geodesic_data(), to any stream; `file` names it in error messages.
inline void write_geodesic_stream(std::ostream& stream, const std::string& file, const Proximity_graph& graph,
                                  const Close_pairs_shortest_paths& cpsp)
{
    check_same_points(graph, cpsp);
    internal::Binary_writer out(stream, file);
    out.write(internal::geodesic_magic, sizeof internal::geodesic_magic);
    out.put(geodesic_file_version);
    out.put(internal::byte_order_mark);
    out.put(static_cast<std::uint8_t>(graph.kind()));
    out.put(static_cast<std::uint32_t>(graph.parameter()));
    out.put(static_cast<std::uint64_t>(graph.num_vertices()));
    out.put(static_cast<std::uint64_t>(graph.targets().size()));
    out.put(cpsp.sampling_radius());
    out.put(cpsp.support());
    out.put(static_cast<std::uint64_t>(cpsp.num_entries()));
    out.put(graph.row_offsets());
    out.put(graph.targets());
    const std::uint64_t e = graph.targets().size();
    std::vector<float> lengths(e);
    std::vector<std::uint8_t> flags(e);
    for (std::uint64_t i = 0; i < e; ++i) {
        lengths[i] = graph.edge_property(i).length;
        flags[i] = graph.edge_property(i).is_virtual ? 1 : 0;
    }
    out.put(lengths);
    out.put(flags);
    out.put(cpsp.offsets());
    out.put(cpsp.all_targets());
    out.put(cpsp.all_distances());
    out.put(cpsp.all_predecessors());
    out.finish();
}

} // namespace internal

/// Writes `graph` and `cpsp` (built on that graph) to the binary file `path` (format in the header
/// comment), replacing it.
/// \throws File_error if the file cannot be written; Invalid_input if the two do not have the same
///         number of points.
/// Complexity: O(size of the data). Thread safety: reads its arguments only.
inline void write_geodesic_data(const std::string& path, const Proximity_graph& graph,
                                const Close_pairs_shortest_paths& cpsp)
{
    internal::check_same_points(graph, cpsp); // before the file is truncated
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw File_error(path, "cannot open for writing");
    internal::write_geodesic_stream(file, path, graph, cpsp);
    file.close();
    if (!file) throw File_error(path, "write failed (disk full?)");
}

namespace internal {

/// The body of read_geodesic_data(): reads `file_size` bytes of the geodesic format from `stream`
/// (exactly that many must make up the data); errors are File_error(file, prefix + problem).
inline Geodesic_data read_geodesic_stream(std::istream& stream, std::uint64_t file_size, const std::string& file,
                                          const std::string& prefix)
{
    internal::Binary_reader in(stream, file_size, file, prefix);
    char magic[8];
    if (file_size < sizeof magic) in.fail("truncated file: not a PCCD geodesic file");
    in.read(magic, sizeof magic);
    if (std::memcmp(magic, internal::geodesic_magic, sizeof magic) != 0) in.fail("not a PCCD geodesic file");
    const auto version = in.get<std::uint32_t>();
    if (version != geodesic_file_version)
        in.fail(internal::concat("geodesic file format version ", version, ", this PCCD reads version ",
                                 geodesic_file_version));
    if (in.get<std::uint32_t>() != internal::byte_order_mark) in.fail("written on a machine of another byte order");
    const auto kind = in.get<std::uint8_t>();
    if (kind > static_cast<std::uint8_t>(Graph_kind::sphere_of_influence))
        in.fail(internal::concat("unknown graph kind ", int(kind)));
    const auto parameter = in.get<std::uint32_t>();
    const auto n = in.get<std::uint64_t>();
    const auto e = in.get<std::uint64_t>();
    const auto radius = in.get<double>();
    const auto support = in.get<double>();
    const auto m = in.get<std::uint64_t>();
    // Sizes are checked against the file before anything is allocated.
    const std::uint64_t limit = file_size;
    if (n >= std::numeric_limits<std::uint32_t>::max() || e > limit || m > limit ||
        internal::geodesic_file_size(n, e, m) != file_size)
        in.fail(internal::concat("file size ", file_size, " does not match its header (truncated or corrupted)"));
    auto rows = in.get_vector<std::uint64_t>(n + 1);
    auto targets = in.get_vector<std::uint32_t>(e);
    const auto lengths = in.get_vector<float>(e);
    const auto flags = in.get_vector<std::uint8_t>(e);
    auto offsets = in.get_vector<std::uint64_t>(n + 1);
    auto cpsp_targets = in.get_vector<std::uint32_t>(m);
    auto distances = in.get_vector<float>(m);
    auto predecessors = in.get_vector<std::uint32_t>(m);
    in.check_sum();

    // Structure: a checksum only proves the bytes are those written; these checks make sure a file
    // crafted or written by a buggy program cannot break the invariants the library relies on.
    if (!(std::isfinite(radius) && radius > 0.0 && std::isfinite(support) && support > 0.0))
        in.fail("invalid sampling radius or support");
    auto check_offsets = [&](const std::vector<std::uint64_t>& o, std::uint64_t total, const char* what) {
        if (o.front() != 0 || o.back() != total) in.fail(internal::concat("inconsistent ", what, " offsets"));
        for (std::uint64_t i = 0; i < n; ++i)
            if (o[i] > o[i + 1]) in.fail(internal::concat("decreasing ", what, " offsets at point ", i));
    };
    check_offsets(rows, e, "graph");
    check_offsets(offsets, m, "CPSP");
    std::vector<Proximity_edge> properties(e);
    for (std::uint64_t i = 0; i < e; ++i) {
        if (targets[i] >= n) in.fail(internal::concat("graph edge ", i, " points to vertex ", targets[i]));
        if (!std::isgreaterequal(lengths[i], 0.f) || flags[i] > 1)
            in.fail(internal::concat("invalid property of graph edge ", i));
        properties[i] = Proximity_edge{lengths[i], flags[i] == 1};
    }
    for (std::uint64_t u = 0; u < n; ++u)
        for (std::uint64_t i = rows[u]; i < rows[u + 1]; ++i) {
            if (i > rows[u] && targets[i] <= targets[i - 1]) in.fail(internal::concat("unsorted row ", u));
            // The reverse direction must exist with the same property.
            const auto v = targets[i];
            const auto first = targets.begin() + std::ptrdiff_t(rows[v]);
            const auto last = targets.begin() + std::ptrdiff_t(rows[v + 1]);
            const auto it = std::lower_bound(first, last, std::uint32_t(u));
            if (it == last || *it != u || !(properties[std::uint64_t(it - targets.begin())] == properties[i]))
                in.fail(internal::concat("graph is not symmetric at edge ", u, " - ", v));
        }
    const double bound = support * radius;
    for (std::uint64_t p = 0; p < n; ++p) {
        const std::uint64_t begin = offsets[p], end = offsets[p + 1];
        if (begin == end || cpsp_targets[begin] != p || distances[begin] != 0.f || predecessors[begin] != 0)
            in.fail(internal::concat("CPSP list of point ", p, " does not start with the point itself"));
        for (std::uint64_t i = begin + 1; i < end; ++i)
            if (cpsp_targets[i] >= n || !std::isgreaterequal(distances[i], distances[i - 1]) ||
                !std::islessequal(double(distances[i]), float(bound)) ||
                predecessors[i] >= i - begin)
                in.fail(internal::concat("invalid CPSP entry ", i - begin, " of point ", p));
    }
    Proximity_graph graph(internal::make_csr_graph(rows, targets, properties), static_cast<Graph_kind>(kind),
                          parameter);
    return {std::move(graph), Close_pairs_shortest_paths(radius, support, std::move(offsets), std::move(cpsp_targets),
                                                         std::move(distances), std::move(predecessors))};
}

} // namespace internal

/// Reads a file written by write_geodesic_data(). The result equals what was written, bit for bit.
/// \throws File_error naming the file and the problem if it cannot be read, is not a PCCD geodesic
///         file, was written by another format version or carries another byte-order mark (as the
///         files of older versions of PCCD written on a big-endian machine do), is
///         truncated or longer than its header says, fails its checksum, or holds an inconsistent
///         graph or CPSP map.
/// Complexity: O(size of the data).
inline Geodesic_data read_geodesic_data(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) throw File_error(path, "cannot open for reading");
    std::error_code error;
    const std::uint64_t file_size = std::filesystem::file_size(path, error);
    if (error) throw File_error(path, "cannot read the file size");
    return internal::read_geodesic_stream(file, file_size, path, "");
}

} // namespace PCCD
