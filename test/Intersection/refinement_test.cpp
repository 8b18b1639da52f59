// Tests of PCCD/Intersection/refinement.h against analytic truth: two sampled planes crossing at a
// right angle (z = 0 and x = 0, posed as objects A and B) meet on the line x = z = 0. The projection
// refinement (refine_by_projection) takes a start near the line onto it (both surfaces within
// epsilon, the point within a tenth of the spacing of the line), refuses a start where a surface is
// undefined and a start whose projection would leave the allowed ball, and counts its evaluations;
// the sampling refinement (refine_by_sampling) returns only points within its sphere whose
// max(|f_A|, |f_B|) is at most epsilon; evaluate_both never overdraws a budget.
#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Intersection/refinement.h>
#include <PCCD/Point_cloud_object.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {

constexpr double spacing = 0.05;

/// A square grid of 41 x 41 points, spacing 0.05, in the plane z = 0 centred at the origin.
PCCD::Point_cloud_object<PCCD::Eigen_kernel<double>> plane_object()
{
    Eigen::Matrix3Xd points(3, 41 * 41);
    for (int i = 0; i < 41; ++i)
        for (int j = 0; j < 41; ++j) points.col(41 * i + j) = Eigen::Vector3d((i - 20) * spacing, (j - 20) * spacing, 0.0);
    return PCCD::Point_cloud_object<PCCD::Eigen_kernel<double>>(points);
}

/// The rotation taking the plane z = 0 onto the plane x = 0 (a quarter turn about the y axis).
PCCD::Rigid_transform_3<double> quarter_turn()
{
    Eigen::Matrix3d r;
    r << 0, 0, 1, 0, 1, 0, -1, 0, 0;
    return PCCD::Rigid_transform_3<double>(r, Eigen::Vector3d::Zero());
}

/// Distance of x from the line x = z = 0.
double from_line(const Eigen::Vector3d& x) { return std::hypot(x.x(), x.z()); }

} // namespace

TEST_CASE("Projection refinement lands on the crossing line of two planes", "[intersection][refinement]")
{
    const auto plane = plane_object();
    const PCCD::Posed_object<decltype(plane)> a(plane, PCCD::Rigid_transform_3<double>());
    const PCCD::Posed_object<decltype(plane)> b(plane, quarter_turn());
    const double epsilon = 1e-3 * spacing;
    int projected = 0;
    for (int k = 0; k < 20; ++k) {
        std::vector<PCCD::Intersection_point> out;
        PCCD::Query_state state(std::uint64_t(k), std::nullopt, true, spacing, out);
        // Starts up to 0.3 spacings off the line, along it within the planes' middle.
        const Eigen::Vector3d start(0.3 * spacing * std::cos(k), 0.5 * (k - 10) * spacing / 10.0, 0.3 * spacing * std::sin(k));
        const auto point = PCCD::internal::refine_by_projection(a, b, start, 2.0 * spacing, epsilon, state);
        REQUIRE(point);
        ++projected;
        CHECK(std::abs(point->f_a) <= epsilon);
        CHECK(std::abs(point->f_b) <= epsilon);
        CHECK(from_line(point->position) <= 0.1 * spacing);
        CHECK((point->position - start).norm() <= 2.0 * spacing);
        CHECK(point->kind == PCCD::Intersection_point_kind::refined);
        CHECK(state.counters.refinement_samples >= 1);
        CHECK(state.counters.f_evaluations >= 2);
    }
    CHECK(projected == 20);
}

TEST_CASE("Projection refinement refuses undefined starts and steps out of its ball", "[intersection][refinement]")
{
    const auto plane = plane_object();
    const PCCD::Posed_object<decltype(plane)> a(plane, PCCD::Rigid_transform_3<double>());
    const PCCD::Posed_object<decltype(plane)> b(plane, quarter_turn());
    std::vector<PCCD::Intersection_point> out;
    PCCD::Query_state state(1, std::nullopt, true, spacing, out);
    // Far from both clouds: A's surface is undefined there.
    CHECK_FALSE(PCCD::internal::refine_by_projection(a, b, Eigen::Vector3d(5.0, 5.0, 5.0), spacing, 1e-4, state));
    // A start half a spacing off the line with a ball of a hundredth of a spacing: the first step leaves it.
    CHECK_FALSE(PCCD::internal::refine_by_projection(a, b, Eigen::Vector3d(0.5 * spacing, 0.0, 0.5 * spacing),
                                                     0.01 * spacing, 1e-6, state));
}

TEST_CASE("Sampling refinement returns points within its sphere and tolerance", "[intersection][refinement]")
{
    const auto plane = plane_object();
    const PCCD::Posed_object<decltype(plane)> a(plane, PCCD::Rigid_transform_3<double>());
    const PCCD::Posed_object<decltype(plane)> b(plane, quarter_turn());
    int found = 0;
    for (int k = 0; k < 10; ++k) {
        std::vector<PCCD::Intersection_point> out;
        PCCD::Query_state state(std::uint64_t(100 + k), std::nullopt, true, spacing, out);
        const Eigen::Vector3d centre(0.1 * spacing, 0.02 * k, -0.1 * spacing);
        const double radius = 0.5 * spacing, epsilon = 0.1 * spacing;
        const auto point = PCCD::internal::refine_by_sampling(a, b, centre, radius, epsilon, 5000, state);
        if (!point) continue;
        ++found;
        CHECK((point->position - centre).norm() <= radius * (1.0 + 1e-12));
        CHECK(std::max(std::abs(point->f_a), std::abs(point->f_b)) <= epsilon);
        // |f| of a plane's surface is the distance to the plane: the point is within epsilon of both.
        CHECK(from_line(point->position) <= std::sqrt(2.0) * epsilon * 1.05);
    }
    // The ball of radius 0.5 spacing around a point 0.14 spacing off the line holds a large share of
    // points within 0.1 spacing of both planes: 5000 samples find one every time.
    CHECK(found == 10);
}

TEST_CASE("evaluate_both stops at the budget after the first surface", "[intersection][refinement]")
{
    const auto plane = plane_object();
    const PCCD::Posed_object<decltype(plane)> a(plane, PCCD::Rigid_transform_3<double>());
    const PCCD::Posed_object<decltype(plane)> b(plane, quarter_turn());
    std::vector<PCCD::Intersection_point> out;
    PCCD::Query_state state(1, std::size_t(1), true, spacing, out);
    CHECK_FALSE(PCCD::internal::evaluate_both(a, b, Eigen::Vector3d::Zero(), state));
    CHECK(state.counters.f_evaluations == 1);
}
