// benchmark/collision_baselines.h -- what a user can do today instead of PCCD, as baselines for the
// intersection benchmarks (the poses of doc/manual/sampling.md): collide the meshes the clouds came from with
// FCL, or call two clouds colliding when some pair of their points is closer than a threshold.
// Used by benchmark programs only; not part of the library (it needs FCL, which PCCD does not).
//
// Both answer the question of the benchmark for two posed copies of one object, A at T_A and B at
// T_B: do their surfaces touch? Both stop at the first contact they find, as the benchmark asks of
// every method. FCL also gives the proximity benchmark its reference: the exact distance between
// the two posed meshes (Fcl_mesh_baseline::distance).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <PCCD/Error.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::benchmark {

/// What FCL's distance() reports for two posed meshes: the distance between their surfaces (0 when
/// they intersect) and a closest point on each, as FCL gives them.
struct Fcl_distance {
    double distance = 0.0;
    Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
    Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
};

/// Mesh-mesh collision with FCL (the Flexible Collision Library, 0.7): a bounding-volume hierarchy
/// of OBBRSS nodes (oriented box plus rectangle swept sphere) over the triangles, built once; a
/// query descends both copies' hierarchies under the relative motion and tests triangle pairs in
/// floating point, stopping at the first intersecting pair.
///
/// collide() returns whether the surfaces of two copies of the mesh, placed by `pose_a` and
/// `pose_b`, intersect, as FCL decides it. A copy nested inside the other without surface contact
/// is not a collision (FCL's BVH models are triangle soups, without volume), which is also how
/// PCCD::exact_do_intersect answers.
///
/// Queries are const and allocate only FCL's small result object; concurrent queries are safe.
class Fcl_mesh_baseline {
public:
    using Model = fcl::BVHModel<fcl::OBBRSSd>;

    /// Builds the hierarchy over `mesh` (local coordinates, e.g. normalized into [-1, 1]^3).
    /// \throws PCCD::Invalid_input if the mesh has no triangle or FCL rejects it.
    /// Complexity: O(T log T) for T triangles.
    explicit Fcl_mesh_baseline(const PCCD::Triangle_mesh_data& mesh) : m_model(std::make_shared<Model>())
    {
        if (mesh.triangles.empty()) throw PCCD::Invalid_input("FCL baseline: the mesh has no triangle");
        std::vector<fcl::Vector3d> vertices(mesh.vertices.begin(), mesh.vertices.end());
        std::vector<fcl::Triangle> triangles;
        triangles.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
        if (m_model->beginModel(int(triangles.size()), int(vertices.size())) != fcl::BVH_OK ||
            m_model->addSubModel(vertices, triangles) != fcl::BVH_OK || m_model->endModel() != fcl::BVH_OK)
            throw PCCD::Invalid_input("FCL baseline: FCL could not build the BVH model");
        m_request.num_max_contacts = 1; // stop at the first intersecting triangle pair
        m_request.enable_contact = false;
        m_distance_request.enable_nearest_points = true;
        m_distance_request.rel_err = 0.0; // exact: no node pair pruned on a relative or absolute slack
        m_distance_request.abs_err = 0.0;
    }

    /// Whether the surfaces of the copies at `pose_a` and `pose_b` intersect, according to FCL.
    /// Complexity: O(log T) node pairs for far-apart copies, up to O(T^2) in theory.
    bool collide(const PCCD::Rigid_transform_3<double>& pose_a, const PCCD::Rigid_transform_3<double>& pose_b) const
    {
        fcl::CollisionResultd result;
        fcl::collide(m_model.get(), to_fcl(pose_a), m_model.get(), to_fcl(pose_b), m_request, result);
        return result.isCollision();
    }

    /// The distance between the surfaces of the copies at `pose_a` and `pose_b` with FCL's
    /// distance() (exact: rel_err = abs_err = 0, nearest points enabled): a branch and bound
    /// descent of both hierarchies that ends at the closest triangle pair; 0 when some triangle
    /// pair intersects (no penetration depth: the meshes are triangle soups).
    /// Complexity: O(log T) node pairs for well-separated copies, more as they come close.
    Fcl_distance distance(const PCCD::Rigid_transform_3<double>& pose_a, const PCCD::Rigid_transform_3<double>& pose_b) const
    {
        fcl::DistanceResultd result;
        fcl::distance(m_model.get(), to_fcl(pose_a), m_model.get(), to_fcl(pose_b), m_distance_request, result);
        return {std::max(0.0, result.min_distance), result.nearest_points[0], result.nearest_points[1]};
    }

    /// Number of BVH nodes (a size figure for reports).
    std::size_t number_of_nodes() const { return std::size_t(m_model->getNumBVs()); }

private:
    static fcl::Transform3d to_fcl(const PCCD::Rigid_transform_3<double>& pose)
    {
        fcl::Transform3d t = fcl::Transform3d::Identity();
        t.linear() = pose.rotation();
        t.translation() = pose.translation();
        return t;
    }

    // FCL's collide() takes geometries by pointer to const; both copies share one model.
    std::shared_ptr<Model> m_model;
    fcl::CollisionRequestd m_request;
    fcl::DistanceRequestd m_distance_request;
};

/// The naive point-cloud test: two clouds collide iff some point of B lies within `threshold` of
/// some point of A. Each point p of B is mapped into A's local frame by T_A^-1 T_B; it is skipped
/// when it falls outside A's bounding box grown by the threshold (no point of A can be that close),
/// otherwise a kd-tree radius query over A decides it. The test stops at the first point of B that
/// has a neighbour in A, and answers at once when B's bounding box, moved into A's frame, misses the
/// grown box.
///
/// collide() returns that verdict. It has no notion of a surface: a gap narrower than the threshold
/// is a collision, and two sheets crossing between samples are missed unless two samples happen to
/// lie within the threshold of each other near the crossing.
///
/// Queries are const; concurrent queries are safe (each uses its own result buffer).
class Threshold_baseline {
public:
    /// Takes cloud A (local coordinates; copies of a Point_cloud share its data), the points of
    /// cloud B (columns, B's local frame) and the threshold, by default one mean spacing of A
    /// (Point_cloud::mean_spacing, O(N log N) once). For two copies of one object pass
    /// `cloud.coordinates()` as B.
    /// \throws PCCD::Invalid_input if B is empty, or the threshold is given and not finite and >= 0.
    Threshold_baseline(PCCD::Point_cloud<> cloud_a, Eigen::Matrix3Xd points_b,
                       std::optional<double> threshold = std::nullopt)
        : m_cloud_a(std::move(cloud_a)),
          m_points_b(std::move(points_b)),
          m_threshold(threshold ? *threshold : m_cloud_a.mean_spacing())
    {
        if (m_points_b.cols() == 0) throw PCCD::Invalid_input("threshold baseline: cloud B has no point");
        if (!(std::isfinite(m_threshold) && m_threshold >= 0.0))
            throw PCCD::Invalid_input(PCCD::internal::concat("threshold baseline: threshold ", m_threshold,
                                                             " must be finite and >= 0"));
        m_grown_box_a = m_cloud_a.bbox();
        m_grown_box_a.min().array() -= m_threshold;
        m_grown_box_a.max().array() += m_threshold;
        m_box_b = Eigen::AlignedBox3d(Eigen::Vector3d(m_points_b.rowwise().minCoeff()),
                                      Eigen::Vector3d(m_points_b.rowwise().maxCoeff()));
    }

    /// Whether some point of B placed by `pose_b` lies within threshold() of a point of A placed by
    /// `pose_a`.
    /// Complexity: O(1) when the boxes miss, else O(M) box tests plus one O(log N) expected radius
    /// query per point of B inside the grown box, M points in B; stops at the first hit.
    bool collide(const PCCD::Rigid_transform_3<double>& pose_a, const PCCD::Rigid_transform_3<double>& pose_b) const
    {
        const PCCD::Rigid_transform_3<double> b_to_a = pose_a.inverse() * pose_b;
        const Eigen::Matrix3d& rotation = b_to_a.rotation();
        const Eigen::Vector3d& translation = b_to_a.translation();
        // The box of B's moved box: centre moved, half-extents through |R|.
        const Eigen::Vector3d centre = rotation * m_box_b.center() + translation;
        const Eigen::Vector3d half = rotation.cwiseAbs() * (0.5 * m_box_b.sizes());
        if (!m_grown_box_a.intersects(Eigen::AlignedBox3d(centre - half, centre + half))) return false;
        std::vector<PCCD::Neighbor<double>> near;
        for (Eigen::Index i = 0; i < m_points_b.cols(); ++i) {
            const Eigen::Vector3d p = rotation * m_points_b.col(i) + translation;
            if (!m_grown_box_a.contains(p)) continue;
            m_cloud_a.within_radius(p, m_threshold, near);
            if (!near.empty()) return true;
        }
        return false;
    }

    double threshold() const { return m_threshold; }
    const PCCD::Point_cloud<>& cloud_a() const { return m_cloud_a; }

private:
    PCCD::Point_cloud<> m_cloud_a;
    Eigen::Matrix3Xd m_points_b;
    double m_threshold;
    Eigen::AlignedBox3d m_grown_box_a;
    Eigen::AlignedBox3d m_box_b;
};

} // namespace PCCD::benchmark
