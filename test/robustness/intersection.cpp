// Bad-input catalogue, intersection queries (doc/reliability.md, "Intersection queries"): identical
// objects at the identical pose, non-rigid and non-finite poses, invalid options and policy fields
// (each an Invalid_input naming the field), tiny and degenerate objects against a sphere (no crash,
// no NaN in a result point), far-apart objects (separate without evaluating f), and sphere pairs at
// the 1e-6 and 1e6 scales (the analytic answer, scaled).
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>

#include "robustness_helpers.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace pccd_robustness;

namespace {

using Object = PCCD::Point_cloud_object<>;
using Transform = PCCD::Rigid_transform_3<double>;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

const Object& unit_sphere()
{
    static const Object object(fibonacci_sphere(1500));
    return object;
}

Transform shifted(double x, double y = 0.0, double z = 0.0)
{
    return Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(x, y, z));
}

/// Runs the four queries (both policies, both entry points) and checks what every result must
/// satisfy: finite point positions, f values finite where they were evaluated, a status that agrees
/// with the answer.
template <class A, class B>
std::vector<PCCD::Intersection_result> all_queries(const A& a, const Transform& pose_a, const B& b,
                                                   const Transform& pose_b, const PCCD::Intersection_options& options = {})
{
    std::vector<PCCD::Intersection_result> results{
        PCCD::do_intersect(a, pose_a, b, pose_b, options),
        PCCD::intersection_points(a, pose_a, b, pose_b, options),
        PCCD::do_intersect(a, pose_a, b, pose_b, options, PCCD::Randomized_sampling{}),
        PCCD::intersection_points(a, pose_a, b, pose_b, options, PCCD::Randomized_sampling{})};
    for (const auto& r : results) {
        CHECK(r.intersects == !r.points.empty());
        CHECK((r.status == PCCD::Intersection_status::intersecting) == r.intersects);
        for (const auto& p : r.points) {
            CHECK(p.position.allFinite());
            if (p.kind != PCCD::Intersection_point_kind::approximate) {
                CHECK(std::isfinite(p.f_a));
                CHECK(std::isfinite(p.f_b));
            }
        }
    }
    return results;
}

} // namespace

TEST_CASE("intersection: two identical objects at the identical pose intersect", "[robustness][intersection]")
{
    // RST answers "intersecting" at any density: every sample near the surface is within epsilon of
    // both. The interpolation search needs a sign change of f along a path, which coincident
    // surfaces only give where the WLS surface's own residual at the sample points changes sign or
    // is below epsilon: true at 6000 points on the unit sphere, not at 1500 (known bug below).
    static const Object dense(fibonacci_sphere(6000));
    for (const Transform& pose : {Transform(), shifted(5.0, -3.0, 1e3)}) {
        INFO("pose shift " << pose.translation().transpose());
        const auto results = all_queries(dense, pose, dense, pose, {.refinement = PCCD::Refinement::none});
        for (const auto& r : results) {
            CHECK(r.intersects);
            // Every point lies on the (common) surface.
            for (const auto& p : r.points) CHECK(std::abs(pose.inverse().transform_point(p.position).norm() - 1.0) < 0.05);
        }
        // intersection_points() covers the whole surface: many points, not one.
        CHECK(results[1].points.size() > 50);
        const Object& coarse = unit_sphere();
        CHECK(PCCD::do_intersect(coarse, pose, coarse, pose, {}, PCCD::Randomized_sampling{}).intersects);
        CHECK(PCCD::intersection_points(coarse, pose, coarse, pose, {}, PCCD::Randomized_sampling{}).intersects);
    }
}

TEST_CASE("intersection: identical coarse objects at the identical pose, interpolation search", "[robustness][intersection]")
{
    // 1500 points on the unit sphere: the WLS surface's residual at its own points has one sign and
    // exceeds epsilon = 0.05 r everywhere, so no bracket is ever found. With verified contacts the
    // samples within epsilon + the noise estimate of the other surface are candidates, and their
    // projection converges on the common zero set: "intersecting".
    const Object& s = unit_sphere();
    CHECK(PCCD::do_intersect(s, Transform(), s, Transform()).intersects);
    CHECK(PCCD::intersection_points(s, Transform(), s, Transform()).intersects);
}

TEST_CASE("intersection: non-rigid and non-finite poses are rejected when the pose is built", "[robustness][intersection]")
{
    const Object& s = unit_sphere();
    const Eigen::Vector3d t(0.5, 0.0, 0.0);
    Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
    shear(0, 1) = 0.5;
    const std::vector<std::pair<Eigen::Matrix3d, std::vector<std::string>>> bad{
        {1.5 * Eigen::Matrix3d::Identity(), {"scales", "column 0"}},
        {Eigen::Vector3d(1, 1, 1e-3).asDiagonal(), {"scales", "column 2"}},
        {shear, {"shears", "columns 0 and 1"}},
        {Eigen::Vector3d(1, -1, 1).asDiagonal(), {"reflection", "determinant -1"}},
        {-Eigen::Matrix3d::Identity(), {"reflection"}},
    };
    for (const auto& [r, keywords] : bad) {
        INFO("R =\n" << r);
        require_invalid_input([&] { (void)PCCD::do_intersect(s, Transform(), s, Transform(r, t)); }, keywords);
        require_invalid_input([&] { (void)PCCD::intersection_points(s, Transform(r, t), s, Transform()); }, keywords);
    }
    for (const double x : {not_a_number, infinity, -infinity}) {
        Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
        r(1, 2) = x;
        require_invalid_input([&] { (void)PCCD::do_intersect(s, Transform(r, t), s, Transform()); }, {"rotation entry (1, 2) is"});
        require_invalid_input([&] { (void)PCCD::do_intersect(s, Transform(), s, shifted(0.5, x)); }, {"translation entry (1, 3) is"});
    }
    // A rotation given to 7 digits passes, is made orthonormal, and answers like the exact one.
    const Eigen::Matrix3d exact = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Matrix3d rounded = (exact * 1e7).array().round() / 1e7;
    const auto a = PCCD::do_intersect(s, Transform(), s, Transform(exact, t), {.seed = 4});
    const auto b = PCCD::do_intersect(s, Transform(), s, Transform(rounded, t), {.seed = 4});
    CHECK(a.intersects);
    CHECK(b.intersects);
}

TEST_CASE("intersection: invalid options and policy fields are named", "[robustness][intersection]")
{
    const Object& s = unit_sphere();
    const Transform id, near = shifted(1.0);
    const auto options = [&](const PCCD::Intersection_options& o, const std::vector<std::string>& keywords) {
        require_invalid_input([&] { (void)PCCD::do_intersect(s, id, s, near, o); }, keywords);
        require_invalid_input([&] { (void)PCCD::intersection_points(s, id, s, near, o, PCCD::Randomized_sampling{}); }, keywords);
    };
    for (const double e : {0.0, -1e-3, -infinity, infinity, not_a_number})
        options({.epsilon = e}, {"epsilon", "must be finite and > 0"});
    for (const double e : {0.0, -1.0, infinity, not_a_number})
        options({.point_spacing = e}, {"point_spacing", "must be finite and > 0"});
    options({.max_f_evaluations = 0}, {"max_f_evaluations = 0"});
    options({.refinement = PCCD::Refinement::sampling, .refinement_samples = 0}, {"refinement_samples"});
    options({.region = PCCD::Overlap_region(7)}, {"unknown overlap region"});
    options({.refinement = PCCD::Refinement(9)}, {"unknown refinement"});
    require_invalid_input([&] { (void)PCCD::do_intersect(s, id, s, near, {.epsilon = -1.0}); }, {"do_intersect: epsilon"});
    require_invalid_input([&] { (void)PCCD::intersection_points(s, id, s, near, {.epsilon = -1.0}); },
                          {"intersection_points: epsilon"});

    const auto isearch = [&](const PCCD::Interpolation_search& p, const std::vector<std::string>& keywords) {
        require_invalid_input([&] { (void)PCCD::do_intersect(s, id, s, near, {}, p); }, keywords);
        require_invalid_input([&] { (void)PCCD::intersection_points(s, id, s, near, {}, p); }, keywords);
    };
    isearch({.min_samples = 0}, {"interpolation search", "min_samples must be >= 1"});
    isearch({.min_samples = 200, .max_samples = 199}, {"interpolation search", "max_samples 199 must be >= min_samples 200"});
    isearch({.min_samples = 1, .max_samples = 0}, {"max_samples 0"});
    isearch({.samples = 0}, {"samples must be >= 1 when set"});
    for (const double x : {0.0, -0.5, 1.0 + 1e-12, 2.0, not_a_number})
        isearch({.annulus_outer = x}, {"annulus_outer", "must be in (0, 1]"});
    for (const double x : {0.0, 1.5, not_a_number}) isearch({.annulus_width = x}, {"annulus_width"});
    isearch({.partner_candidates = 0}, {"partner_candidates must be >= 1"});
    for (const double x : {0.99, not_a_number, infinity}) isearch({.lipschitz_slack = x}, {"lipschitz_slack"});
    for (const double x : {-1.0, not_a_number, infinity}) isearch({.coverage_c = x}, {"coverage_c"});
    for (const double x : {-0.1, -infinity, not_a_number})
        isearch({.walk_predicted_cover = x}, {"walk_predicted_cover", "must be >= 0"});
    isearch({.partner_choice = PCCD::Partner_choice(5)}, {"unknown partner_choice"});

    const auto rst = [&](const PCCD::Randomized_sampling& p, const std::vector<std::string>& keywords) {
        require_invalid_input([&] { (void)PCCD::do_intersect(s, id, s, near, {}, p); }, keywords);
        require_invalid_input([&] { (void)PCCD::intersection_points(s, id, s, near, {}, p); }, keywords);
    };
    rst({.max_samples = 0}, {"randomized sampling", "max_samples must be >= 1"});
    for (const double x : {0.0, -0.35, -infinity, infinity, not_a_number})
        rst({.epsilon_factor = x}, {"randomized sampling", "epsilon_factor", "must be finite and > 0"});
    for (const double x : {-1.0, not_a_number}) rst({.coverage_c = x}, {"coverage_c"});

    // The extremes that are valid: a budget of one evaluation, the smallest policy values.
    const auto one = PCCD::do_intersect(s, id, s, shifted(3.0), {.max_f_evaluations = 1});
    CHECK(one.counters.f_evaluations <= 1);
    // (The cap of the walk itself: without the certification pass, which samples as
    // intersection_points() does.)
    const auto tiny = PCCD::do_intersect(s, id, s, near, {.certify_separation = false},
                                         PCCD::Interpolation_search{.min_samples = 1, .max_samples = 1,
                                                                                        .annulus_outer = 1e-9,
                                                                                        .partner_candidates = 1});
    CHECK(tiny.counters.samples <= 2);
}

TEST_CASE("intersection: tiny and degenerate objects against a sphere", "[robustness][intersection]")
{
    const Object& sphere = unit_sphere();
    // Each straddles the sphere's surface near (1, 0, 0).
    const std::vector<std::pair<std::string, Points>> clouds{
        {"two points", {{0.9, 0.0, 0.0}, {1.1, 0.0, 0.0}}},
        {"three points", {{0.9, 0.0, 0.0}, {1.1, 0.0, 0.0}, {1.0, 0.1, 0.0}}},
        {"collinear", [] {
             Points p;
             for (int i = 0; i < 20; ++i) p.emplace_back(0.8 + 0.02 * i, 0.0, 0.0);
             return p;
         }()},
        {"oblique collinear", [] {
             Points p;
             for (int i = 0; i < 20; ++i) p.emplace_back(0.8 + 0.02 * i, 0.01 * i, -0.005 * i);
             return p;
         }()},
        {"flat", flat_grid(12, 0.04, Eigen::Vector3d(0.78, -0.22, 0.0))},
    };
    for (const auto& [name, points] : clouds) {
        const Object tiny(points);
        // What the answers must be: far away, separate; near (1, 0, 0.05), the flat patch (a plane
        // z = 0.05 across the sphere) intersects it along an arc, while points on a line or two
        // points define no surface (every evaluation is degenerate), so nothing can intersect them.
        const bool surface = name == "flat";
        const bool has_truth = surface || name == "two points" || name == "collinear" || name == "oblique collinear";
        for (const bool near : {true, false}) {
            const Transform pose = near ? shifted(0.0, 0.0, 0.05) : shifted(3.0);
            INFO(name << ", pose shift " << pose.translation().transpose());
            std::vector<PCCD::Intersection_result> results = all_queries(tiny, pose, sphere, Transform());
            for (auto& r : all_queries(sphere, Transform(), tiny, pose,
                                       {.refinement = PCCD::Refinement::sampling, .refinement_samples = 8}))
                results.push_back(std::move(r));
            all_queries(tiny, pose, tiny, pose);
            if (!has_truth) continue;
            for (const auto& r : results) {
                CHECK(r.intersects == (near && surface));
                for (const auto& p : r.points) { // on the arc: on the sphere and on the plane
                    CHECK(std::abs(p.position.norm() - 1.0) < 0.05);
                    CHECK(std::abs(p.position.z() - 0.05) < 0.02);
                }
            }
        }
    }
}

TEST_CASE("intersection: far-apart objects are separate without an evaluation of f", "[robustness][intersection]")
{
    const Object& s = unit_sphere();
    for (const double distance : {1e6, -1e6, 1e12}) {
        for (const Transform& pose : {shifted(distance), shifted(0.0, distance, distance)}) {
            INFO("shift " << pose.translation().transpose());
            for (const auto& r : all_queries(s, Transform(), s, pose)) {
                CHECK(r.status == PCCD::Intersection_status::separate);
                CHECK(r.counters.f_evaluations == 0);
                CHECK(r.counters.samples == 0);
            }
        }
    }
}

TEST_CASE("intersection: sphere pairs at the 1e-6 and 1e6 scales give the scaled analytic answer",
          "[robustness][intersection]")
{
    for (const double scale : {1e-6, 1e6}) {
        const Object a(fibonacci_sphere(1500, scale)), b(fibonacci_sphere(1200, scale));
        const double r = std::max(a.sampling_radius(), b.sampling_radius());
        for (const double d : {0.5, 1.9, 2.2, 3.0}) {
            const bool truth = d < 2.0;
            INFO("scale " << scale << ", centre distance " << d << " radii");
            const auto results = all_queries(a, Transform(), b, shifted(d * scale), {.seed = 2});
            for (const auto& result : results) {
                CHECK(result.intersects == truth);
                // Every point lies near both spheres, at the object's own scale.
                for (const auto& p : result.points) {
                    CHECK(std::abs(p.position.norm() - scale) < r);
                    CHECK(std::abs((p.position - Eigen::Vector3d(d * scale, 0, 0)).norm() - scale) < r);
                }
            }
            if (truth && d > 0.0) {
                // The refined points of intersection_points() lie on the exact circle.
                const double circle = scale * std::sqrt(1.0 - d * d / 4.0);
                for (const auto& p : results[1].points) {
                    if (p.kind != PCCD::Intersection_point_kind::refined) continue;
                    const double off = std::hypot(p.position.x() - d * scale / 2.0,
                                                  std::hypot(p.position.y(), p.position.z()) - circle);
                    CHECK(off < 0.5 * r);
                }
            }
        }
    }
}
