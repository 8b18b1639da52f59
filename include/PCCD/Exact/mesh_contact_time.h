// PCCD/Exact/mesh_contact_time.h -- the exact reference for continuous collision on two triangle
// meshes moving rigidly over t in [0, 1] (doc/manual/exact.md, "Contact time"; the truth behind
// the continuous collision figures of doc/benchmarks.md): exact_time_of_contact, conservative
// advancement on the exact mesh distance of mesh_distance.h, which brackets the first time the
// surfaces come within a tolerance to a stated accuracy, and also reports the smallest distance the
// motion reaches when they do not.
//
// Includes CGAL's Polygon_mesh_processing (through Exact_mesh.h): keep it out of the core headers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_distance.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/RigidMotion.h>

namespace PCCD {

/// The result of exact_time_of_contact.
struct Exact_contact_time {
    /// Whether the surfaces come within tolerance + accuracy of each other at some time in [0, 1].
    bool contact = false;
    /// contact: the surfaces stay farther apart than the tolerance over [0, t) (certified, see
    /// exact_time_of_contact) and are within tolerance + accuracy at t. No contact: t = 1.
    double t = 1.0;
    /// The smallest exact distance between the surfaces at the times the advancement visited (0 when
    /// they intersect there).
    double min_distance = std::numeric_limits<double>::infinity();
    /// Exact distance computations.
    std::size_t steps = 0;
};

/// The first time in [0, 1] at which the surfaces of the meshes `a` moving by `motion_a` and `b`
/// moving by `motion_b` come within `tolerance` of each other, to within `accuracy` (world units).
///
/// Method: conservative advancement on the exact distance d(t) (exact_distance, exact
/// intersection test and exhaustive closest features). No vertex of a moves faster than
/// va = motion_a.max_point_speed(centre, radius) for the root ball of its vertex ball tree, likewise
/// for b; a point of a triangle moves no faster than its fastest vertex, so d(t') >= d(t) -
/// (va + vb) |t' - t| and the surfaces stay farther apart than `tolerance` until
/// t + (d(t) - tolerance) / (va + vb). The time advances by that much until d(t) <= tolerance +
/// accuracy (contact at t) or t reaches 1.
///
/// Guarantee (up to the rounding of exact_distance, a few ulps): contact at t means the distance
/// exceeded `tolerance` over [0, t) and is at most tolerance + accuracy at t, so the first time the
/// surfaces come within `tolerance` is >= t, and the first time they come within tolerance +
/// accuracy is <= t. No contact means the distance exceeded `tolerance` over all of [0, 1].
///
/// \tparam MA, MB models of RigidMotion.
/// \throws Invalid_input if tolerance is negative or not finite, accuracy not finite and > 0, or
///         the speed bound is not finite; as exact_distance otherwise.
/// Complexity: one exact_distance per step; the steps grow like log(d(0) / accuracy) on a direct
/// approach and like 1 / accuracy on a grazing one. Thread-safe.
template <RigidMotion MA, RigidMotion MB>
Exact_contact_time exact_time_of_contact(const Exact_mesh& a, const MA& motion_a, const Exact_mesh& b, const MB& motion_b,
                                         double tolerance, double accuracy)
{
    if (!(std::isfinite(tolerance) && tolerance >= 0.0))
        throw Invalid_input(internal::concat("exact_time_of_contact: tolerance ", tolerance, " must be finite and >= 0"));
    if (!(std::isfinite(accuracy) && accuracy > 0.0))
        throw Invalid_input(internal::concat("exact_time_of_contact: accuracy ", accuracy, " must be finite and > 0"));
    const auto ball_speed = [](const Exact_mesh& m, const auto& motion) {
        const Exact_mesh::Vertex_ball& root = m.vertex_ball_tree().front();
        return double(motion.max_point_speed(Eigen::Vector3d(root.centre.x(), root.centre.y(), root.centre.z()), root.radius));
    };
    const double v = ball_speed(a, motion_a) + ball_speed(b, motion_b);
    if (!(std::isfinite(v) && v >= 0.0))
        throw Invalid_input(internal::concat("exact_time_of_contact: the motions' speed bound ", v, " is not finite"));
    Exact_contact_time r;
    double t = 0.0;
    while (true) {
        ++r.steps;
        const Exact_distance d = exact_distance(a, motion_a.pose(t), b, motion_b.pose(t));
        const double gap = d.surfaces_intersect ? 0.0 : d.distance;
        r.min_distance = std::min(r.min_distance, gap);
        if (gap <= tolerance + accuracy) {
            r.contact = true;
            r.t = t;
            return r;
        }
        if (t >= 1.0 || v == 0.0) break;
        // Advance by at least accuracy / v: the gap exceeds tolerance + accuracy here.
        t = std::min(1.0, t + (gap - tolerance) / v);
    }
    r.contact = false;
    r.t = 1.0;
    return r;
}

} // namespace PCCD
