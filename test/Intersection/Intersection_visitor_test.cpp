// Tests of PCCD/Intersection/Intersection_visitor.h: two unit-sphere clouds at crossing, grazing and
// separate distances, queried with a recording visitor. Every evaluation event is recomputed through
// the object's own surface (the value, and which object it belongs to); brackets are sign changes of
// one surface between two points of the other cloud; node and leaf pairs are valid indices (leaf
// pairs are leaves of A and B, in that order, within reach of each other) and, under the walked
// traversals, as many as the counters say for first hits and curves alike; the answer is the same
// without the visitor.
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "../intersection_test_helpers.h"
#include "../surface_test_helpers.h"

namespace {

struct Recorder final : PCCD::Intersection_visitor {
    struct Evaluation {
        PCCD::Query_object object;
        Eigen::Vector3d x;
        double value;
        bool defined;
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> nodes, leaves;
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> brackets;
    std::vector<Evaluation> evaluations;

    void node_pair(std::uint32_t a, std::uint32_t b) override { nodes.emplace_back(a, b); }
    void leaf_pair(std::uint32_t a, std::uint32_t b) override { leaves.emplace_back(a, b); }
    void bracket(const Eigen::Vector3d& from, const Eigen::Vector3d& to) override { brackets.emplace_back(from, to); }
    void evaluation(PCCD::Query_object object, const Eigen::Vector3d& x, const PCCD::Surface_evaluation& e) override
    {
        evaluations.push_back({object, x, e.value, e.defined()});
    }
};

} // namespace

TEST_CASE("A visitor sees every evaluation, bracket, node pair and leaf pair of a query, and changes nothing",
          "[intersection][hierarchy]")
{
    const auto sa = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 41);
    const auto sb = pccd_test::sample_shape(pccd_test::unit_sphere(), 2500, 0.0, 42);
    const PCCD::Point_cloud_object<> a(pccd_test::columns(sa.points)), b(pccd_test::columns(sb.points));
    const PCCD::Rigid_transform_3<double> pose_a(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    std::size_t with_brackets = 0, with_pairs = 0, curve_pairs = 0;
    for (const double d : {0.3, 1.0, 1.9, 1.99, 2.02, 2.1, 3.0}) {
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.4 * d, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
        const PCCD::Rigid_transform_3<double> pose_b(turn, Eigen::Vector3d(d, 0.1, 0.0));
        for (const auto traversal : {PCCD::Traversal::likelihood, PCCD::Traversal::depth_first, PCCD::Traversal::flat}) {
            for (const bool first_hit : {true, false}) {
                INFO("d " << d << " traversal " << int(traversal) << " first hit " << first_hit);
                Recorder recorder;
                PCCD::Intersection_options options{.seed = 7, .traversal = traversal};
                const auto plain = first_hit ? PCCD::do_intersect(a, pose_a, b, pose_b, options)
                                             : PCCD::intersection_points(a, pose_a, b, pose_b, options);
                options.visitor = &recorder;
                const auto seen = first_hit ? PCCD::do_intersect(a, pose_a, b, pose_b, options)
                                            : PCCD::intersection_points(a, pose_a, b, pose_b, options);
                CHECK(pccd_test::result_difference(plain, seen).empty());

                // Evaluations: one per counted f evaluation, each the object's own f at that point.
                REQUIRE(recorder.evaluations.size() == seen.counters.f_evaluations);
                for (const auto& e : recorder.evaluations) {
                    const bool is_a = e.object == PCCD::Query_object::a;
                    const auto& object = is_a ? a : b;
                    const auto& pose = is_a ? pose_a : pose_b;
                    const PCCD::Surface_evaluation again = object.surface().evaluate(pose.inverse().transform_point(e.x));
                    REQUIRE(again.defined() == e.defined);
                    if (e.defined) CHECK(again.value == Approx(e.value).margin(1e-12));
                }
                // Brackets: f of one surface changes sign between the two points.
                CHECK(recorder.brackets.size() == seen.counters.brackets_found);
                for (const auto& [from, to] : recorder.brackets) {
                    bool sign_change = false;
                    for (const bool is_a : {true, false}) {
                        const auto& object = is_a ? a : b;
                        const auto& pose = is_a ? pose_a : pose_b;
                        const auto f0 = object.surface().evaluate(pose.inverse().transform_point(from));
                        const auto f1 = object.surface().evaluate(pose.inverse().transform_point(to));
                        sign_change = sign_change || (f0.defined() && f1.defined() && (f0.value < 0.0) != (f1.value < 0.0));
                    }
                    CHECK(sign_change);
                }
                with_brackets += recorder.brackets.empty() ? 0 : 1;
                // Pairs: reported one by one by the separation test and the walked first-hit traversals.
                for (const auto& [i, j] : recorder.nodes) {
                    REQUIRE(i < a.hierarchy().nodes().size());
                    REQUIRE(j < b.hierarchy().nodes().size());
                }
                for (const auto& [i, j] : recorder.leaves) {
                    const auto& na = a.hierarchy().node(i);
                    const auto& nb = b.hierarchy().node(j);
                    CHECK(na.is_leaf());
                    CHECK(nb.is_leaf());
                    // A's leaf i and B's leaf j (not the other way round): their boxes, grown by their
                    // reaches, pass the traversals' box test (face normals of both boxes).
                    CHECK(PCCD::grown_boxes_may_overlap(na.box, pose_b.inverse() * pose_a, na.reach, nb.box, nb.reach));
                }
                // Under the walked traversals every counted pair is reported (separation test, walk,
                // reach regions of intersection_points).
                if (traversal != PCCD::Traversal::flat) {
                    CHECK(recorder.nodes.size() == seen.counters.node_pairs);
                    CHECK(recorder.leaves.size() == seen.counters.leaf_pairs);
                    with_pairs += recorder.nodes.empty() ? 0 : 1;
                    curve_pairs += !first_hit && !recorder.leaves.empty() ? 1 : 0;
                }
            }
        }
    }
    // The poses exercise every event.
    CHECK(with_brackets > 0);
    CHECK(with_pairs > 0);
    CHECK(curve_pairs > 0);
}
