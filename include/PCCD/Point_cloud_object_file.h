// PCCD/Point_cloud_object_file.h -- the object file format of Point_cloud_object: the
// definitions of save() and load() and their helpers, through the little-endian binary reader and
// writer of PCCD/internal/binary_stream.h, streamed: a save writes to the file as it goes and a
// load reads it straight into the object's arrays, neither holding the file's bytes. Included by
// PCCD/Point_cloud_object.h. Implements doc/manual/surface.md, "One call: Point_cloud_object"
// (save and load).
#pragma once

#include <PCCD/Point_cloud_object_class.h>
#include <PCCD/object_file_info.h>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace PCCD {

namespace internal {

/// The file `path` opened for reading; `size` is set to its size in bytes (0 when the size cannot
/// be told, as for a directory: every read of it then fails as a truncated file).
inline std::ifstream open_binary_file(const std::string& path, std::uint64_t& size)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw File_error(path, "cannot open the file: it does not exist or is not readable");
    in.seekg(0, std::ios::end);
    const std::streamoff end = in.tellg();
    size = end > 0 ? std::uint64_t(end) : 0;
    in.clear();
    in.seekg(0);
    return in;
}

/// Compares the checksum stored in the last 8 bytes of the `size`-byte file `file` with that of the
/// bytes before them, read in chunks of 1 MiB (nothing of the file is held), and puts `file` back
/// where it was. Errors are `in`'s.
inline void check_trailing_checksum(std::istream& file, std::uint64_t size, const Binary_reader& in)
{
    if (size < sizeof(std::uint64_t)) in.fail("truncated file");
    const std::streampos resume = file.tellg();
    file.seekg(0);
    Word_checksum checksum;
    std::vector<char> chunk(std::size_t(1) << 20);
    for (std::uint64_t left = size - sizeof(std::uint64_t); left > 0;) {
        const auto take = std::size_t(std::min<std::uint64_t>(left, chunk.size()));
        file.read(chunk.data(), std::streamsize(take));
        if (std::size_t(file.gcount()) != take) in.fail("truncated file");
        checksum.update(chunk.data(), take);
        left -= take;
    }
    char stored[sizeof(std::uint64_t)];
    file.read(stored, sizeof stored);
    if (std::size_t(file.gcount()) != sizeof stored) in.fail("truncated file");
    if (decode_little_endian<std::uint64_t>(stored) != checksum.value())
        in.fail("checksum mismatch: the file is truncated or corrupted");
    file.clear();
    file.seekg(resume);
}

} // namespace internal

namespace internal {

/// The scan section of an object file (format version >= 2): noise estimate, outliers and domain
/// radii of an object of n points, checked.
inline void read_scan_section(Binary_reader& in, std::uint64_t n, Scan_estimate& scan,
                              std::optional<Eigen::VectorXd>& domain)
{
    scan.noise = in.get<double>();
    const auto input = in.get<std::uint64_t>();
    const auto m = in.get<std::uint64_t>();
    if (!(std::isfinite(scan.noise) && scan.noise >= 0.0)) in.fail(internal::concat("invalid noise estimate ", scan.noise));
    if (input < n || input - n != m || in.remaining() / sizeof(std::uint32_t) < m)
        in.fail(internal::concat("inconsistent outlier count ", m, " for ", input, " input points"));
    scan.input_points = std::size_t(input);
    scan.outliers.resize(std::size_t(m));
    in.read(scan.outliers.data(), sizeof(std::uint32_t) * std::size_t(m));
    for (std::size_t k = 0; k < scan.outliers.size(); ++k)
        if (scan.outliers[k] >= input || (k > 0 && scan.outliers[k] <= scan.outliers[k - 1]))
            in.fail("outlier indices out of range or not ascending");
    const auto radii = in.get<std::uint64_t>();
    if ((radii != 0 && radii != n) || in.remaining() / sizeof(double) < radii)
        in.fail(internal::concat("inconsistent number of domain radii ", radii));
    domain.emplace(Eigen::Index(radii));
    in.read(domain->data(), sizeof(double) * std::size_t(radii));
}

/// The opening of an object file: magic (`lean`: a lean object's), format version (1 to `newest`),
/// byte-order mark, and the checksum over the whole file (`file`, of `size` bytes, the stream `in`
/// reads). Returns the version; fails on `in` otherwise, naming the loader of the other kind's file.
inline std::uint32_t read_object_file_header(Binary_reader& in, std::istream& file, std::uint64_t size,
                                             std::uint32_t newest, bool lean = false)
{
    char magic[8];
    in.read(magic, sizeof magic);
    if (std::memcmp(magic, lean ? lean_object_magic : object_magic, sizeof magic) != 0) {
        if (!lean && std::memcmp(magic, lean_object_magic, sizeof magic) == 0)
            in.fail("a lean object's file (Euclidean_point_cloud_object::save): load it with "
                    "Euclidean_point_cloud_object::load");
        if (lean && std::memcmp(magic, object_magic, sizeof magic) == 0)
            in.fail("a Point_cloud_object's file (geodesic kernel): load it with Point_cloud_object::load");
        in.fail(lean ? "not a PCCD lean object file" : "not a PCCD object file");
    }
    const auto version = in.get<std::uint32_t>();
    if (version == 0 || version > newest)
        in.fail(concat("object file format version ", version, ", this PCCD reads versions 1 to ", newest));
    if (in.get<std::uint32_t>() != byte_order_mark) in.fail("written on a machine of another byte order");
    check_trailing_checksum(file, size, in);
    return version;
}

/// The input-index section of an object file (format version >= 4): one index per point, each below
/// scan.input_points and none repeated or an outlier's.
inline void read_input_indices(Binary_reader& in, const Scan_estimate& scan, std::vector<std::uint32_t>& input_index)
{
    if (in.get<std::uint64_t>() != input_index.size()) in.fail("the input indices are not one per point");
    in.read(input_index.data(), sizeof(std::uint32_t) * input_index.size());
    std::vector<bool> seen(scan.input_points); // an index is a kept point's or an outlier's, once
    for (const std::uint32_t i : scan.outliers) seen[i] = true;
    for (const std::uint32_t i : input_index) {
        if (i >= scan.input_points || seen[i])
            in.fail(concat("input index ", i, " repeated or beyond the ", scan.input_points, " points given"));
        seen[i] = true;
    }
}

/// The hierarchy section of an object file (format version >= 5): the layout of the object's
/// hierarchy (Point_cloud_hierarchy::Layout) over n points. Checked for sizes and values here; its
/// shape is checked when the hierarchy is rebuilt from it.
inline Point_cloud_hierarchy::Layout read_hierarchy_section(Binary_reader& in, std::uint64_t n)
{
    Point_cloud_hierarchy::Layout layout;
    const auto volume = in.get<std::uint8_t>();
    if (volume > std::uint8_t(Bounding_volume::sphere)) in.fail(concat("unknown bounding volume ", int(volume)));
    layout.volume = Bounding_volume(volume);
    const auto leaf_size = in.get<std::uint64_t>();
    if (leaf_size == 0 || leaf_size > std::numeric_limits<std::uint32_t>::max())
        in.fail(concat("invalid hierarchy leaf size ", leaf_size));
    layout.leaf_size = std::size_t(leaf_size);
    const auto nodes = in.get<std::uint64_t>();
    if (nodes == 0 || nodes >= 2 * n || in.remaining() / (2 * sizeof(std::uint32_t)) < nodes)
        in.fail(concat("inconsistent number of hierarchy nodes ", nodes, " for ", n, " points"));
    layout.counts.resize(std::size_t(nodes));
    layout.rights.resize(std::size_t(nodes));
    layout.order.resize(std::size_t(n));
    in.read(layout.counts.data(), sizeof(std::uint32_t) * layout.counts.size());
    in.read(layout.rights.data(), sizeof(std::uint32_t) * layout.rights.size());
    in.read(layout.order.data(), sizeof(std::uint32_t) * layout.order.size());
    return layout;
}

/// What an object file holds before its geodesic section (the whole of a lean object's file).
struct Object_file_parts {
    std::uint64_t n = 0;
    double r = 0.0, h = 0.0, theta = 0.0;
    bool given = false;
    Orientation_report orientation;
    Preprocessing_times timings;
    Eigen::Matrix3Xd points, normals;
    Scan_estimate scan;
    std::optional<Eigen::VectorXd> domain;
    Surface_fit fit = Surface_fit::plane;
    std::vector<std::uint32_t> input_index;
    std::optional<Point_cloud_hierarchy::Layout> layout;
};

/// Reads the parts of a file of format `version` (1 to 5; see the format below), after its header.
inline Object_file_parts read_object_parts(Binary_reader& in, std::uint32_t version)
{
    Object_file_parts p;
    p.n = in.get<std::uint64_t>();
    const std::uint64_t n = p.n;
    if (n < 2 || n >= std::uint64_t(std::numeric_limits<std::uint32_t>::max()) || in.remaining() < 6 * sizeof(double) * n)
        in.fail(concat("inconsistent point count ", n));
    p.r = in.get<double>();
    p.h = in.get<double>();
    p.theta = in.get<double>();
    p.given = in.get<std::uint8_t>() != 0;
    p.orientation.flipped = std::size_t(in.get<std::uint64_t>());
    p.orientation.components = std::size_t(in.get<std::uint64_t>());
    p.orientation.unoriented = std::size_t(in.get<std::uint64_t>());
    for (double* t : {&p.timings.kd_tree, &p.timings.graph, &p.timings.sampling_radius, &p.timings.cpsp, &p.timings.normals})
        *t = in.get<double>();
    p.points.resize(3, Eigen::Index(n));
    p.normals.resize(3, Eigen::Index(n));
    in.read(p.points.data(), sizeof(double) * 3 * n);
    in.read(p.normals.data(), sizeof(double) * 3 * n);
    p.scan.input_points = std::size_t(n);
    if (version >= 2) read_scan_section(in, n, p.scan, p.domain);
    if (version >= 3) {
        const auto stored = in.get<std::uint8_t>();
        if (stored > std::uint8_t(Surface_fit::imls)) in.fail(concat("unknown surface fit ", int(stored)));
        p.fit = Surface_fit(stored);
    }
    p.input_index.resize(n);
    if (version >= 4) {
        read_input_indices(in, p.scan, p.input_index);
    } else {
        std::iota(p.input_index.begin(), p.input_index.end(), std::uint32_t(0));
    }
    if (version >= 5) p.layout = read_hierarchy_section(in, n);
    if (!(std::isfinite(p.r) && p.r > 0.0)) in.fail(concat("invalid sampling radius ", p.r));
    return p;
}

/// The hierarchy options a load uses: the caller's (`asked`; null: the stored layout's leaf size and
/// volume), and the stored layout kept in `parts` only when it has those.
inline Point_cloud_hierarchy_options loaded_hierarchy_options(Object_file_parts& parts, const Point_cloud_hierarchy_options* asked)
{
    Point_cloud_hierarchy_options options = asked ? *asked : Point_cloud_hierarchy_options{};
    if (parts.layout && !asked) options.leaf_size = parts.layout->leaf_size, options.volume = parts.layout->volume;
    if (parts.layout && (parts.layout->leaf_size != options.leaf_size || parts.layout->volume != options.volume))
        parts.layout.reset();
    return options;
}

/// Writes what read_object_parts() reads (the newest format) of `object`, a Point_cloud_object or
/// a Euclidean_point_cloud_object (the same accessors).
template <class Object>
void write_object_parts(Binary_writer& out, const Object& object)
{
    out.put(std::uint64_t(object.size()));
    out.put(object.sampling_radius());
    out.put(object.bandwidth());
    out.put(object.weight().threshold());
    out.put(std::uint8_t(object.normals_given() ? 1 : 0));
    out.put(std::uint64_t(object.orientation().flipped));
    out.put(std::uint64_t(object.orientation().components));
    out.put(std::uint64_t(object.orientation().unoriented));
    const Preprocessing_times& t = object.timings();
    for (double x : {t.kd_tree, t.graph, t.sampling_radius, t.cpsp, t.normals}) out.put(x);
    const auto& coordinates = object.cloud().coordinates();
    if constexpr (std::is_same_v<std::decay_t<decltype(coordinates)>, Eigen::Matrix3Xd>) {
        out.write(coordinates.data(), sizeof(double) * std::size_t(coordinates.size()));
    } else {
        const Eigen::Matrix3Xd points = coordinates.template cast<double>();
        out.write(points.data(), sizeof(double) * std::size_t(points.size()));
    }
    out.write(object.normals().data(), sizeof(double) * std::size_t(object.normals().size()));
    const Scan_estimate& scan = object.scan();
    out.put(scan.noise);
    out.put(std::uint64_t(scan.input_points));
    out.put(std::uint64_t(scan.outliers.size()));
    out.write(scan.outliers.data(), sizeof(std::uint32_t) * scan.outliers.size());
    out.put(std::uint64_t(object.domain_radii().size()));
    out.write(object.domain_radii().data(), sizeof(double) * std::size_t(object.domain_radii().size()));
    out.put(std::uint8_t(object.surface().fit()));
    out.put(std::uint64_t(object.input_indices().size()));
    out.write(object.input_indices().data(), sizeof(std::uint32_t) * object.input_indices().size());
    const Point_cloud_hierarchy::Layout layout = object.hierarchy().layout();
    out.put(std::uint8_t(layout.volume));
    out.put(std::uint64_t(layout.leaf_size));
    out.put(std::uint64_t(layout.counts.size()));
    out.write(layout.counts.data(), sizeof(std::uint32_t) * layout.counts.size());
    out.write(layout.rights.data(), sizeof(std::uint32_t) * layout.rights.size());
    out.write(layout.order.data(), sizeof(std::uint32_t) * layout.order.size());
}

/// Writes `object`'s file to `path` (replaced if it exists): `magic`, `version`, the byte-order
/// mark, its parts (write_object_parts()), then what `sections` writes (called with the writer:
/// the geodesic section), and the checksum. Streamed to the file through a buffer of 1 MiB:
/// nothing of the file is held in memory.
template <class Object, class Sections>
void write_object_file(const std::string& path, const char (&magic)[8], std::uint32_t version, const Object& object,
                       Sections&& sections)
{
    std::vector<char> buffer(std::size_t(1) << 20);
    std::ofstream file;
    file.rdbuf()->pubsetbuf(buffer.data(), std::streamsize(buffer.size()));
    file.open(path, std::ios::binary | std::ios::trunc);
    if (!file) throw File_error(path, "cannot open the file for writing");
    Binary_writer out(file, path);
    out.write(magic, sizeof magic);
    out.put(version);
    out.put(byte_order_mark);
    write_object_parts(out, object);
    sections(out);
    out.finish();
    file.close();
    if (!file) throw File_error(path, "write failed (disk full?)");
}

/// The hierarchy options of a load() that takes them, checked before the file is read (a bad option
/// is the caller's error, not the file's); `function` names the load in the message.
inline void check_load_options(const Point_cloud_hierarchy_options& hierarchy, const char* function)
{
    if (hierarchy.leaf_size == 0) throw Invalid_input(concat(function, ": the hierarchy's leaf_size must be >= 1"));
    check_threads(hierarchy.threads, concat(function, ": the hierarchy's threads").c_str());
}

} // namespace internal

// File format (version 5, little-endian whatever the host, with a byte-order mark, no padding):
//   magic "PCCDOBJ\0" | u32 version | u32 byte-order mark | u64 N | f64 sampling radius
//   f64 bandwidth h | f64 theta_eps | u8 normals given | u64 flipped, components, unoriented
//   f64 timings[5] | f64 points[3N] | f64 normals[3N]
//   | f64 noise | u64 input points | u64 M | u32 outliers[M] | u64 D (0 or N) | f64 domain radii[D]
//   | u8 surface fit (Surface_fit) | u64 I (N) | u32 input indices[I]
//   | u8 bounding volume | u64 leaf size | u64 M | u32 node counts[M] | u32 right children[M]
//     | u32 hierarchy order[N]      (the hierarchy's Layout)
//   | u64 G | G bytes: a geodesic file
//   | u64 checksum (FNV-1a over 64-bit words of everything before it)
// Version 1 files (without the scan section) still load: no outliers, noise 0, and the domain of
// the default Surface_domain_options; versions 1 and 2 (without the fit) get the plane fit they
// were made with; versions 1 to 3 (points in the order given) get the identity as input indices;
// versions 1 to 4 (without the hierarchy) get one built with the options load() is given.
template <PointCloudKernel K>
void Point_cloud_object<K>::save(const std::string& path) const
{
    const Data& d = *m_data;
    internal::check_same_points(*d.graph, *d.cpsp);
    // The geodesic section goes straight to the file behind its size, known beforehand.
    const std::uint64_t geodesic_size =
        internal::geodesic_file_size(d.graph->num_vertices(), d.graph->targets().size(), d.cpsp->num_entries());
    internal::write_object_file(path, internal::object_magic, file_version, *this, [&](internal::Binary_writer& out) {
        out.put(geodesic_size);
        const std::uint64_t written = out.write_section(
            [&](std::ostream& section) { internal::write_geodesic_stream(section, path, *d.graph, *d.cpsp); });
        if (written != geodesic_size)
            throw std::logic_error(internal::concat("Point_cloud_object::save: the geodesic section has ", written,
                                                    " bytes, not the ", geodesic_size, " its format gives"));
    });
}

template <PointCloudKernel K>
Point_cloud_object<K> Point_cloud_object<K>::load(const std::string& path)
{
    return load_file(path, nullptr);
}

template <PointCloudKernel K>
Point_cloud_object<K> Point_cloud_object<K>::load(const std::string& path, const Point_cloud_hierarchy_options& hierarchy)
{
    internal::check_load_options(hierarchy, "Point_cloud_object::load");
    return load_file(path, &hierarchy);
}

template <PointCloudKernel K>
Point_cloud_object<K> Point_cloud_object<K>::load_file(const std::string& path, const Point_cloud_hierarchy_options* hierarchy)
{
    std::uint64_t size = 0;
    std::ifstream file = internal::open_binary_file(path, size);
    internal::Binary_reader in(file, size, path);
    const std::uint32_t version = internal::read_object_file_header(in, file, size, file_version);
    internal::Object_file_parts parts = internal::read_object_parts(in, version);
    const Point_cloud_hierarchy_options hierarchy_options = internal::loaded_hierarchy_options(parts, hierarchy);
    const std::uint64_t n = parts.n;
    const auto geodesic_size = in.get<std::uint64_t>();
    if (in.remaining() < sizeof(std::uint64_t) || in.remaining() - sizeof(std::uint64_t) != geodesic_size)
        in.fail("inconsistent size of the geodesic section");

    // The section follows in the file, where `in` stopped (it reads the stream unbuffered).
    Geodesic_data geodesic = internal::read_geodesic_stream(file, geodesic_size, path, "geodesic section: ");
    if (geodesic.graph.num_vertices() != n || geodesic.cpsp.size() != n)
        in.fail("the geodesic section does not have one vertex per point");

    try {
        const auto start = internal::Steady_clock::now();
        Point_cloud<K> cloud(typename Point_cloud<K>::Coordinates(parts.points.template cast<FT>()));
        parts.timings.kd_tree = internal::ms_since(start);
        const Gaussian_weight weight(parts.h, parts.theta);
        auto cpsp = std::make_shared<const Close_pairs_shortest_paths>(std::move(geodesic.cpsp));
        auto graph = std::make_shared<const Proximity_graph>(std::move(geodesic.graph));
        if (!parts.domain) parts.domain = surface_domain_radii(cloud);
        return Point_cloud_object(std::make_shared<const Data>(
            make_data(std::move(cloud), std::move(graph), std::move(cpsp), parts.r, weight, std::move(parts.normals),
                      std::move(*parts.domain), parts.orientation, parts.given, std::move(parts.scan), parts.timings,
                      Point_cloud_object_options{.surface_fit = parts.fit, .hierarchy = hierarchy_options},
                      std::move(parts.input_index), parts.layout ? &*parts.layout : nullptr)));
    } catch (const File_error&) {
        throw;
    } catch (const Invalid_input& e) {
        in.fail(internal::concat("inconsistent content: ", e.what()));
    }
}

} // namespace PCCD
