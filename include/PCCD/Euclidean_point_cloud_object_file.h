// PCCD/Euclidean_point_cloud_object_file.h -- the file format of the lean object
// (Euclidean_point_cloud_object): the definitions of its save() and load(), sharing the sections
// of Point_cloud_object's format (PCCD/Point_cloud_object_file.h) without the geodesic one, behind
// a magic of its own. Included by PCCD/Euclidean_point_cloud_object.h. Implements
// doc/manual/surface.md, "The lean object: the Euclidean kernel for large scans" (its files).
#pragma once

#include <PCCD/Euclidean_point_cloud_object_class.h>

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>

#include <PCCD/internal/timing.h>

namespace PCCD {

// File format (version 1, little-endian whatever the host, with a byte-order mark, no padding):
//   magic "PCCDLEAN" | u32 version | u32 byte-order mark
//   | the sections of Point_cloud_object's format 5 from the point count to the hierarchy's layout
//     (PCCD/Point_cloud_object_file.h: N, r, h, theta_eps, normals given, orientation report,
//     timings, points, normals, scan estimate and domain radii, surface fit, input indices, layout)
//   | u64 checksum (FNV-1a over 64-bit words of everything before it)
template <PointCloudKernel K>
void Euclidean_point_cloud_object<K>::save(const std::string& path) const
{
    internal::write_object_file(path, internal::lean_object_magic, file_version, *this, [](internal::Binary_writer&) {});
}

template <PointCloudKernel K>
Euclidean_point_cloud_object<K> Euclidean_point_cloud_object<K>::load(const std::string& path)
{
    return load_file(path, nullptr);
}

template <PointCloudKernel K>
Euclidean_point_cloud_object<K> Euclidean_point_cloud_object<K>::load(const std::string& path,
                                                                      const Point_cloud_hierarchy_options& hierarchy)
{
    internal::check_load_options(hierarchy, "Euclidean_point_cloud_object::load");
    return load_file(path, &hierarchy);
}

template <PointCloudKernel K>
Euclidean_point_cloud_object<K> Euclidean_point_cloud_object<K>::load_file(const std::string& path,
                                                                           const Point_cloud_hierarchy_options* hierarchy)
{
    internal::Object_file_parts parts;
    {
        // Read from the file straight into the parts' arrays: nothing of the file is held beside them.
        std::uint64_t size = 0;
        std::ifstream file = internal::open_binary_file(path, size);
        internal::Binary_reader in(file, size, path);
        internal::read_object_file_header(in, file, size, file_version, true);
        // Its sections are those of Point_cloud_object's format 5, the hierarchy included.
        parts = internal::read_object_parts(in, 5);
        if (in.remaining() != sizeof(std::uint64_t)) in.fail("unexpected bytes after the hierarchy section");
    }
    const Point_cloud_hierarchy_options options = internal::loaded_hierarchy_options(parts, hierarchy);
    try {
        const auto start = internal::Steady_clock::now();
        Point_cloud<K> cloud = [&] {
            using Coordinates = typename Point_cloud<K>::Coordinates;
            if constexpr (std::is_same_v<Coordinates, Eigen::Matrix3Xd>)
                return Point_cloud<K>(Coordinates(std::move(parts.points)));
            else
                return Point_cloud<K>(Coordinates(parts.points.template cast<FT>()));
        }();
        cloud = std::move(cloud).with_cell_grid(cell_grid_side * parts.r);
        parts.timings.kd_tree = internal::ms_since(start);
        parts.timings.outliers = 0.0; // read, not computed
        const Gaussian_weight weight(parts.h, parts.theta);
        // The hierarchy's reaches are the domain radii (none without a domain), as when the object
        // was built.
        const auto hierarchy_start = internal::Steady_clock::now();
        Point_cloud_hierarchy tree = parts.layout
                                         ? Point_cloud_hierarchy(*parts.layout, cloud.coordinates(), *parts.domain, options.threads)
                                         : Point_cloud_hierarchy(cloud.coordinates(), *parts.domain, options);
        parts.layout.reset();
        parts.timings.hierarchy = internal::ms_since(hierarchy_start);
        Surface surface(Euclidean_distance<K>(cloud), weight, std::move(parts.normals), std::move(*parts.domain), parts.fit);
        return Euclidean_point_cloud_object(std::make_shared<const Data>(
            Data{std::move(cloud), parts.r, parts.orientation, parts.given, std::move(parts.scan), parts.timings,
                 std::move(surface), std::move(tree), std::move(parts.input_index)}));
    } catch (const File_error&) {
        throw;
    } catch (const Invalid_input& e) {
        throw File_error(path, internal::concat("inconsistent content: ", e.what()));
    }
}

} // namespace PCCD
