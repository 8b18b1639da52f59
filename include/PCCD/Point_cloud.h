// PCCD/Point_cloud.h -- an immutable point cloud: flat coordinate store, bounding box, kd-tree,
// nearest-neighbour and radius queries, and the mean spacing. The first stage of every PCCD
// pipeline (doc/design.md, "Map, in data-flow order"); the graphs, the sampling radius and the
// surface all read the cloud through it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <ranges>
#include <type_traits>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Error.h>
#include <PCCD/Identity_point_map.h>
#include <PCCD/Kd_tree.h>
#include <PCCD/Point_traits.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/concepts/ReadablePointMap.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// An immutable cloud of N >= 1 points with finite coordinates, and its kd-tree.
///
/// \tparam K a model of PointCloudKernel; its `FT` is the coordinate type of the flat store.
///
/// Copies are cheap and share the (immutable) data. Thread safety: every member function is const
/// and safe to call concurrently from several threads.
template <PointCloudKernel K = Eigen_kernel<double>>
class Point_cloud {
public:
    using Kernel = K;
    using FT = typename K::FT;
    using Point_3 = typename K::Point_3;
    using Vector_3 = Eigen::Matrix<FT, 3, 1>;
    using Coordinates = Eigen::Matrix<FT, 3, Eigen::Dynamic>;
    using Bbox_3 = Eigen::AlignedBox<FT, 3>;
    using Index = std::uint32_t;
    using Neighbor = PCCD::Neighbor<FT>;

    /// \name Construction
    /// @{

    /// Copies the points of `items` through `point_map`.
    /// \tparam Range an input range of items.
    /// \tparam PointMap a model of ReadablePointMap for the range's items (identity by default).
    /// \throws Invalid_input if the range is empty or a coordinate is NaN or infinite (the message
    ///         names the first such point), or if it holds 2^32 - 1 points or more.
    /// Complexity: O(N log N) (kd-tree construction).
    template <std::ranges::input_range Range,
              class PointMap = Identity_point_map<std::ranges::range_value_t<Range>>>
        requires ReadablePointMap<PointMap, std::ranges::range_value_t<Range>>
    explicit Point_cloud(const Range& items, const PointMap& point_map = PointMap(), const K& kernel = K())
        : Point_cloud(to_coordinates(items, point_map), kernel)
    {
    }

    /// Copies a range of points (any Point3 type) with a given kernel object: the constructor above
    /// with the identity point map, which need not be spelled.
    template <std::ranges::input_range Range>
        requires Point3<std::ranges::range_value_t<Range>>
    Point_cloud(const Range& points, const K& kernel)
        : Point_cloud(points, Identity_point_map<std::ranges::range_value_t<Range>>(), kernel)
    {
    }

    /// Takes a 3 x N matrix of coordinates, one point per column.
    /// \throws Invalid_input as above.
    explicit Point_cloud(Coordinates coordinates, const K& kernel = K())
        : m_data(std::make_shared<Data>(checked(std::move(coordinates)), kernel))
    {
    }

    /// The points of `cloud` left when the points `removed` (sorted indices, each once) are taken
    /// out, in their order (point i becomes i minus the number removed before it). When `cloud` is
    /// the only holder of its points (no copy of it is alive), its kd-tree is kept without them
    /// (Kd_tree::without(), O(N)); otherwise a tree is built (O(N log N)). Queries answer as on a
    /// cloud made afresh of the points left. `cloud` is moved from.
    /// \throws Invalid_input if `removed` is not sorted, repeats an index, holds one >= size() or
    /// removes every point (`cloud` is then moved from all the same).
    Point_cloud(Point_cloud&& cloud, const std::vector<Index>& removed) : m_data(without(std::move(cloud), removed)) {}

    /// This cloud with a grid of cubic cells of side `cell` laid over its points
    /// (Kd_tree::lay_cell_grid()): radius queries whose ball meets few cells are answered from the
    /// grid, with the same results, faster in clouds too large for the caches. None is laid when
    /// the grid would not fit (cell not finite and normal, or 2^21 - 1 cells or more along an axis);
    /// the cloud is then unchanged. When `*this` is the only holder of its points its kd-tree is
    /// kept; otherwise one is built (O(N log N)). `*this` is moved from. O(N) expected.
    Point_cloud with_cell_grid(double cell) &&
    {
        std::shared_ptr<const Data> data = std::move(m_data);
        Kd_tree<FT> tree = taken_tree(data);
        tree.lay_cell_grid(cell);
        return Point_cloud(std::make_shared<Data>(std::move(tree), data->kernel));
    }
    /// @}

    /// The checked 3 x N coordinates of the points of `items` (through `point_map`), in their order,
    /// as the constructor from a range reads them but without building the kd-tree: for callers
    /// that reorder the points first.
    /// \throws Invalid_input as the constructors.
    template <std::ranges::input_range Range,
              class PointMap = Identity_point_map<std::ranges::range_value_t<Range>>>
        requires ReadablePointMap<PointMap, std::ranges::range_value_t<Range>>
    static Coordinates read_coordinates(const Range& items, const PointMap& point_map = PointMap())
    {
        return checked(to_coordinates(items, point_map));
    }

    /// `coordinates`, checked as the constructor from a matrix checks them, without building the
    /// kd-tree. \throws Invalid_input as the constructors.
    static Coordinates checked_coordinates(Coordinates coordinates) { return checked(std::move(coordinates)); }

    /// The largest coordinate magnitude accepted, sqrt(max(FT)) / 4 (about 3.3e153 for double,
    /// 4.6e18 for float): beyond it squared distances could overflow.
    static FT max_coordinate_magnitude() { return std::sqrt(std::numeric_limits<FT>::max()) / FT(4); }

    /// \name Access
    /// @{
    std::size_t size() const { return m_data->tree.size(); }
    /// The 3 x N coordinate store.
    const Coordinates& coordinates() const { return m_data->tree.coordinates(); }
    /// The coordinates of point `i` as an Eigen vector. \pre i < size()
    Vector_3 position(Index i) const
    {
        PCCD_debug_precondition(i < size());
        return coordinates().col(Eigen::Index(i));
    }
    /// Point `i` as a kernel point. \pre i < size()
    Point_3 point(Index i) const
    {
        const Vector_3 p = position(i);
        return m_data->kernel.construct_point_3_object()(p.x(), p.y(), p.z());
    }
    const Kernel& kernel() const { return m_data->kernel; }
    /// The axis-aligned bounding box of all points.
    const Bbox_3& bbox() const { return m_data->bbox; }
    /// The kd-tree over the points.
    const Kd_tree<FT>& kd_tree() const { return m_data->tree; }
    /// @}

    /// \name Queries (exact; results sorted by squared distance, then index)
    /// @{

    /// The `k` nearest cloud points to `query` (all of them if k >= size()). O(k log N) expected.
    void k_nearest(const Vector_3& query, std::size_t k, std::vector<Neighbor>& out) const
    {
        m_data->tree.k_nearest(query, k, out);
    }
    std::vector<Neighbor> k_nearest(const Vector_3& query, std::size_t k) const
    {
        return m_data->tree.k_nearest(query, k);
    }
    /// The cloud point nearest to `query` (smallest index among equally near ones).
    Neighbor nearest(const Vector_3& query) const { return m_data->tree.nearest(query); }
    /// All cloud points at distance <= `radius` from `query`. \pre radius >= 0
    void within_radius(const Vector_3& query, FT radius, std::vector<Neighbor>& out) const
    {
        m_data->tree.within_radius(query, radius, out);
    }
    std::vector<Neighbor> within_radius(const Vector_3& query, FT radius) const
    {
        return m_data->tree.within_radius(query, radius);
    }
    /// @}

    /// Mean over all points of the distance to the nearest *other* point of the cloud (a duplicate
    /// counts, at distance 0). For N points sampled uniformly at random from a surface of area A it
    /// is close to 0.5 * sqrt(A / N). Computed on every call: O(N log N).
    /// \throws Invalid_input if the cloud has a single point.
    double mean_spacing() const
    {
        if (size() < 2) throw Invalid_input("mean spacing needs at least two points, the cloud has one");
        std::vector<Neighbor> nn;
        double sum = 0.0;
        for (Index i = 0; i < Index(size()); ++i) {
            k_nearest(position(i), 2, nn);
            // The point itself is among the two nearest; the other entry is its nearest neighbour.
            const Neighbor& other = (nn[0].index == i) ? nn[1] : nn[0];
            sum += std::sqrt(double(other.squared_distance));
        }
        return sum / double(size());
    }

private:
    // Made non-const (make_shared<Data>) and held as const: the constructor that removes points
    // may take the tree of a Data it alone holds.
    struct Data {
        Kd_tree<FT> tree;
        Bbox_3 bbox;
        K kernel;
        Data(Coordinates c, const K& k) : tree(std::move(c)), bbox(compute_bbox(tree.coordinates())), kernel(k) {}
        Data(Kd_tree<FT> t, const K& k) : tree(std::move(t)), bbox(compute_bbox(tree.coordinates())), kernel(k) {}
    };

    static std::shared_ptr<const Data> without(Point_cloud&& cloud, const std::vector<Index>& removed)
    {
        std::shared_ptr<const Data> data = std::move(cloud.m_data);
        if (removed.size() >= data->tree.size())
            throw Invalid_input(internal::concat("point cloud: removing ", removed.size(), " of its ", data->tree.size(),
                                                 " points leaves none"));
        return std::make_shared<Data>(taken_tree(data).without(removed), data->kernel);
    }

    /// The kd-tree of `data`: moved out when `data` is its only holder, else built anew on a copy of
    /// its coordinates (O(N log N)).
    static Kd_tree<FT> taken_tree(const std::shared_ptr<const Data>& data)
    {
        if (data.use_count() == 1) return std::move(const_cast<Data&>(*data).tree); // not a const object (see Data)
        return Kd_tree<FT>(data->tree.coordinates());
    }

    static Bbox_3 compute_bbox(const Coordinates& c)
    {
        return Bbox_3(Vector_3(c.rowwise().minCoeff()), Vector_3(c.rowwise().maxCoeff()));
    }

    /// `value` as FT; a finite value beyond FT's range (a double cloud read into a float kernel)
    /// is rejected instead of becoming infinite (the conversion would also raise FE_OVERFLOW).
    template <class T>
    static FT narrowed(const T& value, std::size_t point)
    {
        if (internal::overflows_on_conversion<FT>(value))
            throw Invalid_input(internal::concat("point ", point, " has a coordinate (", value,
                                                 ") beyond the range of the kernel's ", sizeof(FT) == 4 ? "float" : "number type"));
        return static_cast<FT>(value);
    }

    template <class Range, class PointMap>
    static Coordinates to_coordinates(const Range& items, const PointMap& point_map)
    {
        std::vector<FT> flat;
        if constexpr (std::ranges::sized_range<Range>) flat.reserve(3 * std::ranges::size(items));
        std::size_t point = 0;
        for (const auto& item : items) {
            const auto& p = get(point_map, item);
            using P = std::remove_cvref_t<decltype(p)>;
            flat.push_back(narrowed(Point_traits<P>::x(p), point));
            flat.push_back(narrowed(Point_traits<P>::y(p), point));
            flat.push_back(narrowed(Point_traits<P>::z(p), point));
            ++point;
        }
        return Eigen::Map<const Coordinates>(flat.data(), 3, Eigen::Index(flat.size() / 3));
    }

    static Coordinates checked(Coordinates c)
    {
        if (c.cols() == 0) throw Invalid_input("point cloud is empty");
        if (std::uint64_t(c.cols()) >= std::uint64_t(std::numeric_limits<Index>::max()))
            throw Invalid_input(internal::concat("point cloud has ", c.cols(), " points; at most 2^32 - 2 are supported"));
        if (!internal::all_finite(c)) {
            for (Eigen::Index i = 0; i < c.cols(); ++i)
                if (!internal::all_finite(c.col(i)))
                    throw Invalid_input(internal::concat("point ", i, " has a non-finite coordinate (", c(0, i), ", ",
                                                         c(1, i), ", ", c(2, i), ")"));
        }
        // Squared distances between points must not overflow FT (the kd-tree and every distance
        // test use them): 3 (2 m)^2 < max for m = max_coordinate_magnitude().
        const FT limit = max_coordinate_magnitude();
        for (Eigen::Index i = 0; i < c.cols(); ++i)
            for (Eigen::Index a = 0; a < 3; ++a)
                if (std::isgreater(std::fabs(c(a, i)), limit))
                    throw Invalid_input(internal::concat("point ", i, " has a coordinate (", c(a, i),
                                                         ") beyond the supported magnitude ", limit,
                                                         " (squared distances would overflow); rescale the cloud, e.g. with "
                                                         "PCCD::normalize_to_unit_cube"));
        return c;
    }

    explicit Point_cloud(std::shared_ptr<const Data> data) : m_data(std::move(data)) {}

    std::shared_ptr<const Data> m_data;
};

} // namespace PCCD
