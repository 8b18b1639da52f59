// PCCD/Hierarchy/node_pair_tests.h -- the tests that prune a pair of nodes of two point cloud
// hierarchies under a relative rigid motion (doc/algorithms.md "Point cloud hierarchy",
// doc/manual/hierarchy.md "Bounding volumes"): the separating axes of two boxes grown by margins,
// the slabs of the nodes that have one, and which of the tests a pair of hierarchies gets. Each
// test is conservative: it prunes a pair only when no point of one node can come within the
// margins of a point of the other.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

namespace internal {

/// grown_boxes_may_overlap() with the rotation r of the motion, |r| and a's centre already mapped
/// (a traversal computes |r| once).
inline bool grown_boxes_may_overlap(const Eigen::AlignedBox3d& a, const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r,
                                    const Eigen::Vector3d& mapped_centre_a, double margin_a, const Eigen::AlignedBox3d& b,
                                    double margin_b)
{
    const Eigen::Vector3d ha = 0.5 * (a.max() - a.min()) + Eigen::Vector3d::Constant(margin_a);
    const Eigen::Vector3d hb = 0.5 * (b.max() - b.min()) + Eigen::Vector3d::Constant(margin_b);
    const Eigen::Vector3d t = mapped_centre_a - b.center();
    for (int i = 0; i < 3; ++i)
        if (std::abs(t(i)) > hb(i) + abs_r.row(i).dot(ha)) return false;
    for (int j = 0; j < 3; ++j)
        if (std::abs(t.dot(r.col(j))) > ha(j) + abs_r.col(j).dot(hb)) return false;
    return true;
}

/// An interval holding m . p for the points p of `node` (its local frame; without a slab, the box's projection):
/// with m = a n + w, w normal to the slab's normal n, a n . p lies in the slab's interval scaled by
/// a and w . p in the box's projection onto w. For m along n it is the slab's own interval, however
/// thick the box; for m normal to n, the box's projection.
inline std::pair<double, double> node_extent_along(const Point_cloud_hierarchy::Node& node, const Eigen::Vector3d& m)
{
    const Eigen::Vector3d c = node.box.center(), h = 0.5 * (node.box.max() - node.box.min());
    if (!node.has_slab()) { // no slab (a refitted tree): the box's projection
        const double mc = m.dot(c), mh = m.cwiseAbs().dot(h);
        return {mc - mh, mc + mh};
    }
    const double a = m.dot(node.slab_normal);
    const Eigen::Vector3d w = m - a * node.slab_normal;
    const double wc = w.dot(c), wh = w.cwiseAbs().dot(h);
    return {(a >= 0.0 ? a * node.slab_min : a * node.slab_max) + wc - wh,
            (a >= 0.0 ? a * node.slab_max : a * node.slab_min) + wc + wh};
}

/// Node `ns` of s as seen from t's frame: its box centre, its slab normal and the shift of its
/// slab's interval, its sphere's centre (a node pair's test needs them; a walk meets each node in
/// several pairs).
struct Mapped_node {
    Point_cloud_hierarchy::Index node = std::numeric_limits<Point_cloud_hierarchy::Index>::max();
    Eigen::Vector3d centre;
    Eigen::Vector3d slab_normal;
    double slab_shift = 0.0;
    Eigen::Vector3d sphere_centre;
};

/// Which tests a traversal of s against t applies to its node pairs: the boxes' separating axes
/// unless both hierarchies use spheres, the spheres when both have them, and the slabs of the
/// nodes that have one (a box_and_slab hierarchy's, not refitted).
struct Pair_tests {
    bool boxes;
    bool spheres;

    Pair_tests(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t)
        : boxes(!(s.volume() == Bounding_volume::sphere && t.volume() == Bounding_volume::sphere)),
          spheres(s.has_spheres() && t.has_spheres())
    {
    }
};

/// Whether node `ns` of s (seen from t's frame as `mapped`; r the rotation of the motion) and node
/// `nt` of t may hold points closer than `margin`, by their slabs: along each node's slab normal,
/// the node's slab against the other node's extent (node_extent_along). False only when one of the
/// two normals separates them. A node without a slab (zero normal, infinite interval) never separates.
inline bool slabs_may_overlap(const Point_cloud_hierarchy::Node& ns, const Mapped_node& mapped, const Eigen::Matrix3d& r,
                              const Eigen::Vector3d& shift, const Point_cloud_hierarchy::Node& nt, double margin)
{
    if (ns.has_slab()) {
        // s's slab in t's frame: normal r n_s, interval shifted by (r n_s) . shift.
        const auto [lo, hi] = node_extent_along(nt, mapped.slab_normal);
        if (lo > ns.slab_max + mapped.slab_shift + margin || hi < ns.slab_min + mapped.slab_shift - margin) return false;
    }
    if (nt.has_slab()) {
        // t's slab normal n_t seen from s: n_t . (r p + shift) = (r^T n_t) . p + n_t . shift.
        const Eigen::Vector3d u = r.transpose() * nt.slab_normal;
        const double offset = nt.slab_normal.dot(shift);
        const auto [lo, hi] = node_extent_along(ns, u);
        if (lo + offset > nt.slab_max + margin || hi + offset < nt.slab_min - margin) return false;
    }
    return true;
}

} // namespace internal

/// Whether box `a` mapped by `a_to_b` and grown by `margin_a`, and the axis-aligned box `b` grown by
/// `margin_b`, may overlap: false only when one of the six face normals separates them (the grown
/// boxes contain the Minkowski sums of the boxes with balls of those radii, so a false answer means
/// no point within margin_a of box a is within margin_b of box b). O(1); pure.
inline bool grown_boxes_may_overlap(const Eigen::AlignedBox3d& a, const Rigid_transform_3<double>& a_to_b,
                                    double margin_a, const Eigen::AlignedBox3d& b, double margin_b)
{
    const Eigen::Matrix3d& r = a_to_b.rotation();
    const Eigen::Matrix3d abs_r = r.cwiseAbs();
    return internal::grown_boxes_may_overlap(a, r, abs_r, a_to_b.transform_point(a.center()), margin_a, b, margin_b);
}

/// Whether the box `a` (in the frame of a's hierarchy, mapped by `a_to_b` into b's frame) and the
/// axis-aligned box `b` grown by `margin` on every side may overlap: false only when one of the six
/// face normals separates them (grown_boxes_may_overlap() with margin_a = 0). O(1). Pure function:
/// safe to call concurrently.
inline bool boxes_may_overlap(const Eigen::AlignedBox3d& a, const Rigid_transform_3<double>& a_to_b,
                              const Eigen::AlignedBox3d& b, double margin)
{
    return grown_boxes_may_overlap(a, a_to_b, 0.0, b, margin);
}

} // namespace PCCD
