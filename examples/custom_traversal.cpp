// A query of your own on the one walk of PCCD (doc/manual/hierarchy.md, "Traversals: one walk,
// queries as traits"): the points of a cloud within a radius of a query point, as traits of
// PCCD::traverse over the cloud's Point_cloud_hierarchy (a node is entered when the ball meets its
// box; a leaf compares its points), and the pairs of leaves of two posed hierarchies whose boxes
// overlap, as traits of the pair walk. Both answers are checked against brute force.
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>

#include <cstdio>
#include <vector>

using Index = PCCD::Point_cloud_hierarchy::Index;

// The points of `tree` within `radius` of q: positions in hierarchy order (columns of ordered_points()).
struct Points_in_ball {
    const PCCD::Point_cloud_hierarchy& tree;
    Eigen::Vector3d q;
    double radius;
    std::vector<std::size_t> found{};

    bool go_further() const { return true; }
    bool enter(Index i) const { return tree.node(i).box.squaredExteriorDistance(q) <= radius * radius; }
    void leaf(Index i)
    {
        const auto& node = tree.node(i);
        for (Index k = node.first; k < node.first + node.count; ++k)
            if ((tree.ordered_points().col(k).head<3>() - q).squaredNorm() <= radius * radius) found.push_back(k);
    }
    bool left_first(Index) const { return true; }
};

// The leaf pairs of a and b (a mapped by a_to_b) whose boxes may overlap: open the node with more points.
struct Overlapping_leaves {
    const PCCD::Point_cloud_hierarchy& a;
    const PCCD::Point_cloud_hierarchy& b;
    PCCD::Rigid_transform_3<double> a_to_b;
    std::size_t pairs = 0;

    bool go_further() const { return true; }
    bool enter(Index i, Index j) const { return PCCD::boxes_may_overlap(a.node(i).box, a_to_b, b.node(j).box, 0.0); }
    PCCD::Pair_split split(Index i, Index j) const
    {
        if (a.is_leaf(i) && b.is_leaf(j)) return PCCD::Pair_split::leaves;
        if (b.is_leaf(j) || (!a.is_leaf(i) && a.node(i).count >= b.node(j).count)) return PCCD::Pair_split::first;
        return PCCD::Pair_split::second;
    }
    void leaf_pair(Index, Index) { ++pairs; }
    bool first_left_first(Index, Index) const { return true; }
    bool second_left_first(Index, Index) const { return true; }
};

int main()
{
    PCCD::Random_engine engine(7);
    Eigen::Matrix3Xd points(3, 5000);
    for (Eigen::Index i = 0; i < points.cols(); ++i) {
        Eigen::Vector3d p(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
        points.col(i) = p.normalized(); // the unit sphere
    }
    const PCCD::Point_cloud_hierarchy tree(points);

    Points_in_ball ball{tree, Eigen::Vector3d(0.0, 0.0, 1.0), 0.2};
    const PCCD::Walk_counters walk = PCCD::traverse(tree, Index(0), ball);
    std::size_t brute = 0;
    for (Eigen::Index i = 0; i < points.cols(); ++i) brute += (points.col(i) - ball.q).norm() <= ball.radius;
    std::printf("points within 0.2 of the north pole: %zu (brute force %zu), %zu of %zu nodes tested\n",
                ball.found.size(), brute, walk.tested, tree.nodes().size());

    Overlapping_leaves overlap{tree, tree, PCCD::Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.5, 0, 0))};
    PCCD::traverse(tree, Index(0), tree, Index(0), overlap);
    std::printf("leaf pairs whose boxes may overlap, sphere against a copy 1.5 to the side: %zu\n", overlap.pairs);
    return ball.found.size() == brute ? 0 : 1;
}
