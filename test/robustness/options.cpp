// Bad-input catalogue, options and transforms (doc/reliability.md): every numeric knob of the
// preprocessing (graph, sampling radius, bandwidth, threads) outside its documented range, and
// non-rigid or non-finite Rigid_transform_3 input. Each case asserts Invalid_input naming the
// option, or the documented answer for an unusual but valid value.
#include "robustness_helpers.h"

#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/Surface/Gaussian_weight.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/sampling_radius.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <string>
#include <vector>

using namespace pccd_robustness;

namespace {

using Object = PCCD::Point_cloud_object<>;
using Options = PCCD::Point_cloud_object_options;

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

const Points& sphere()
{
    static const Points points = fibonacci_sphere(300);
    return points;
}

void require_rejected(const Options& options, const std::vector<std::string>& keywords)
{
    require_invalid_input([&] { Object object(sphere(), PCCD::Identity_point_map<Eigen::Vector3d>(), options); },
                          keywords);
}

Object build(const Options& options) { return Object(sphere(), PCCD::Identity_point_map<Eigen::Vector3d>(), options); }

} // namespace

TEST_CASE("options: proximity graphs", "[robustness]")
{
    SECTION("r = 0 for the r-SIG, k = 0 for the k-NN graph")
    {
        require_rejected({.sphere_of_influence = {.r = 0}}, {"sphere-of-influence graph", "r must be >= 1, got 0"});
        require_rejected({.graph = PCCD::Graph_kind::knn, .knn = {.k = 0}}, {"k-NN graph", "k must be >= 1, got 0"});
        // r and k are unsigned: a "negative" value wraps to 2^32 - 1, which means every other point.
        const PCCD::Point_cloud<> small(fibonacci_sphere(40));
        CHECK(PCCD::sphere_of_influence_graph(small, {.r = unsigned(-1)}).num_edges() == 40 * 39 / 2);
        CHECK(PCCD::knn_graph(small, {.k = unsigned(-1)}).num_edges() == 40 * 39 / 2);
    }
    SECTION("long-edge factor <= 0 or NaN; +infinity turns the test off")
    {
        for (const double factor : {0.0, -1.0, not_a_number, -infinity}) {
            INFO("factor " << factor);
            require_rejected({.sphere_of_influence = {.long_edges = {.factor = factor}}}, {"long-edge factor must be > 0"});
            require_rejected({.graph = PCCD::Graph_kind::knn, .knn = {.long_edges = {.factor = factor}}},
                             {"long-edge factor must be > 0"});
        }
        CHECK(build({.sphere_of_influence = {.long_edges = {.factor = infinity}}}).graph().num_virtual_edges() == 0);
    }
    SECTION("the CPSP map: sampling radius and support factor <= 0 or not finite")
    {
        const PCCD::Point_cloud<> cloud(sphere());
        const auto graph = PCCD::sphere_of_influence_graph(cloud);
        for (const double bad : {0.0, -1.0, not_a_number, infinity}) {
            INFO("value " << bad);
            require_invalid_input([&] { PCCD::Close_pairs_shortest_paths cpsp(graph, bad); },
                                  {"CPSP map: the sampling radius must be finite and > 0"});
            require_invalid_input([&] { PCCD::Close_pairs_shortest_paths cpsp(graph, 0.1, {.support = bad}); },
                                  {"CPSP map: the support factor eta must be finite and > 0"});
        }
    }
}

TEST_CASE("options: sampling radius", "[robustness]")
{
    require_rejected({.sampling_radius = {.samples = 0}}, {"sampling radius: samples must be >= 1"});
    for (const double quantile : {0.0, -0.5, 1.5, not_a_number, infinity}) {
        INFO("quantile " << quantile);
        require_rejected({.sampling_radius = {.quantile = quantile}}, {"sampling radius: quantile must be in (0, 1]"});
    }
    for (const unsigned neighbors : {0u, 1u})
        require_rejected({.sampling_radius = {.neighbors = neighbors}}, {"sampling radius: neighbors must be >= 2"});
    for (const double factor : {0.0, -3.0, not_a_number, infinity}) {
        INFO("disk factor " << factor);
        require_rejected({.sampling_radius = {.disk_factor = factor}}, {"sampling radius: disk_factor must be finite and > 0"});
    }
    // quantile = 1 (the maximum) is valid; the other functions of the header check their input too.
    CHECK(build({.sampling_radius = {.quantile = 1.0}}).sampling_radius() > 0.0);
    require_invalid_input([] { (void)PCCD::subsample_sampling_radius(0.1, 100, 0); }, {"subsample of 0 points out of 100"});
    require_invalid_input([] { (void)PCCD::subsample_sampling_radius(0.1, 100, 101); }, {"subsample of 101 points"});
    for (const double surfel : {0.0, -1.0, not_a_number})
        require_invalid_input([&] { (void)PCCD::estimated_surfel_count(100, 0.1, surfel); }, {"surfel radius must be > 0"});
}

TEST_CASE("options: bandwidth (eta, theta_eps, h)", "[robustness]")
{
    for (const double eta : {0.0, -1.0, not_a_number, infinity, -infinity}) {
        INFO("eta " << eta);
        require_rejected({.bandwidth = {.eta = eta}}, {"bandwidth: eta is", "must be finite and > 0"});
    }
    for (const double theta : {0.0, 1.0, -0.5, 1.5, not_a_number, infinity}) {
        INFO("theta_eps " << theta);
        require_rejected({.bandwidth = {.theta_eps = theta}}, {"bandwidth: theta_eps is", "must lie in (0, 1)"});
    }
    for (const double h : {0.0, -1.0, not_a_number, infinity, -infinity}) {
        INFO("h " << h);
        require_rejected({.bandwidth = {.bandwidth = h}}, {"bandwidth: the given bandwidth is", "must be finite and > 0"});
    }
    // Finite but absurd: h^2 or 1 / h^2 would overflow.
    for (const double h : {1e300, 1e-300, 1e155, 1e-155}) {
        INFO("h " << h);
        require_rejected({.bandwidth = {.bandwidth = h}}, {"Gaussian weight", "overflow double precision"});
    }
    for (const double eta : {1e300, 1e-300}) {
        INFO("eta " << eta);
        require_rejected({.bandwidth = {.eta = eta}}, {"Gaussian weight", "overflow double precision"});
    }
    // Extreme but valid thresholds: a tiny support leaves the normals undetermined, a threshold
    // near 1 gives a huge bandwidth; both build and stay finite.
    const Object tiny = build({.bandwidth = {.theta_eps = 1e-300}});
    CHECK(std::isfinite(tiny.bandwidth()));
    CHECK(tiny.orientation().unoriented > 0);
    const Object wide = build({.bandwidth = {.theta_eps = 1.0 - 1e-12}});
    CHECK(std::isfinite(wide.bandwidth()));
    CHECK(wide.orientation().unoriented == 0);
    // The kernel itself, as used directly.
    require_invalid_input([] { (void)PCCD::Gaussian_weight(0.0, 0.01); }, {"bandwidth h is 0"});
    require_invalid_input([] { (void)PCCD::Gaussian_weight(1.0, not_a_number); }, {"threshold theta_eps is nan"});
    require_invalid_input([] { (void)PCCD::kernel_bandwidth(not_a_number); }, {"the sampling radius is nan"});
    require_invalid_input([] { (void)PCCD::kernel_bandwidth(0.0); }, {"the sampling radius is 0"});
}

TEST_CASE("options: threads", "[robustness]")
{
    // Unset means "all available", any count >= 1 is valid (capped by TBB); the result never
    // depends on it. 0 is refused: it is no count of threads.
    const Object reference = build({.threads = 1});
    for (const std::optional<unsigned> threads : {std::optional<unsigned>(), std::optional<unsigned>(2u),
                                                  std::optional<unsigned>(64u)}) {
        INFO("threads " << threads.value_or(0));
        const Object object = build({.threads = threads});
        CHECK(object.graph() == reference.graph());
        CHECK(object.cpsp() == reference.cpsp());
        CHECK(object.sampling_radius() == reference.sampling_radius());
        CHECK(object.normals() == reference.normals());
    }
    require_rejected({.threads = 0}, {"threads = 0", "leave it unset"});
    require_rejected({.sphere_of_influence = {.threads = 0}}, {"threads = 0", "leave it unset"});
    require_invalid_input([] { (void)PCCD::sampling_radius(PCCD::Point_cloud<>(std::vector<Eigen::Vector3d>{
                                                                {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}),
                                                            {.threads = 0}); },
                          {"threads = 0"});
}

TEST_CASE("transforms: scaling, shear, reflection, NaN and infinite entries", "[robustness]")
{
    using Transform = PCCD::Rigid_transform_3<>;
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    const auto rejected = [&](const Eigen::Matrix3d& r, const Eigen::Vector3d& t, const std::vector<std::string>& keywords) {
        INFO("R =\n" << r << "\nt = " << t.transpose());
        require_invalid_input([&] { Transform transform(r, t); }, keywords);
        require_invalid_input([&] { PCCD::Rigid_transform_3<float> transform(r, t); }, keywords);
    };
    SECTION("scaling")
    {
        rejected(2.0 * Eigen::Matrix3d::Identity(), zero, {"scales", "column 0", "length 2"});
        rejected(Eigen::Vector3d(1, 1, 1.01).asDiagonal(), zero, {"scales", "column 2"});
        rejected(Eigen::Matrix3d::Zero(), zero, {"scales", "length 0"});
        rejected(1e-30 * Eigen::Matrix3d::Identity(), zero, {"scales"});
        rejected(1e20 * Eigen::Matrix3d::Identity(), zero, {"scales", "entry (0, 0)"});
        require_invalid_input([] { Transform t(1e200 * Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()); },
                              {"scales", "entry (0, 0)"});
    }
    SECTION("shear")
    {
        Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
        shear(0, 1) = 0.5;
        rejected(shear, zero, {"shears", "columns 0 and 1"});
        Eigen::Matrix3d rank_deficient = Eigen::Matrix3d::Identity();
        rank_deficient.col(2) = rank_deficient.col(1);
        rejected(rank_deficient, zero, {"shears", "columns 1 and 2"});
    }
    SECTION("reflection")
    {
        rejected(Eigen::Vector3d(1, 1, -1).asDiagonal(), zero, {"reflection", "determinant -1"});
        rejected(-Eigen::Matrix3d::Identity(), zero, {"reflection"});
        Eigen::Matrix3d swap = Eigen::Matrix3d::Zero();
        swap(0, 1) = swap(1, 0) = swap(2, 2) = 1.0;
        rejected(swap, zero, {"reflection"});
    }
    SECTION("NaN and infinite entries, each position named")
    {
        for (const double bad : {not_a_number, infinity, -infinity})
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 4; ++j) {
                    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
                    Eigen::Vector3d t = zero;
                    if (j < 3)
                        r(i, j) = bad;
                    else
                        t(i) = bad;
                    const std::string where = std::string(j < 3 ? "rotation" : "translation") + " entry (" +
                                              std::to_string(i) + ", " + std::to_string(j) + ") is";
                    rejected(r, t, {where});
                    std::array<double, 12> row_major = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
                    row_major[std::size_t(4 * i + j)] = bad;
                    require_invalid_input([&] { Transform transform(row_major); }, {where});
                }
    }
    SECTION("bad shapes and tolerances")
    {
        require_invalid_input([] { Transform t(Eigen::MatrixXd::Identity(3, 4), Eigen::Vector3d::Zero()); }, {"not 3 x 3"});
        require_invalid_input([] { Transform t(Eigen::Matrix3d::Identity(), Eigen::VectorXd::Zero(2)); }, {"not 3 x 1"});
        for (const double tolerance : {-1e-6, 0.5, not_a_number})
            require_invalid_input([&] { Transform t(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), tolerance); },
                                  {"tolerance", "is not in [0, 0.5)"});
    }
    SECTION("valid: a rotation given to 7 digits and a huge translation are accepted, made exact")
    {
        Eigen::Matrix3d r;
        r << 0.7044663, -0.5576550, -0.4390309, 0.5933638, 0.1233521, 0.7954267, -0.3894183, -0.8208563, 0.4177897;
        const Transform transform(r, Eigen::Vector3d(1e300, -1e300, 0));
        CHECK((transform.rotation().transpose() * transform.rotation()).isApprox(Eigen::Matrix3d::Identity(), 1e-15));
        CHECK(transform.rotation().determinant() == Approx(1.0).epsilon(1e-15));
        CHECK((transform.rotation() - r).cwiseAbs().maxCoeff() < 1e-6);
    }
}

TEST_CASE("a float transform from doubles beyond FLT_MAX is rejected by entry", "[robustness]")
{
    // Was a known bug: the constructor cast to float before validating (the cast overflowed, a trap
    // in Debug; in Release the message said the entry was infinity).
    require_invalid_input([] { PCCD::Rigid_transform_3<float> t(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1e39, 0, 0)); },
                          {"translation entry (0, 3)", "float"});
    // The same through the constructor from an affine transformation exposing m(i, j) (CGAL style).
    struct Affine {
        double m(int i, int j) const { return i == 1 && j == 3 ? -1e39 : (i == j ? 1.0 : 0.0); }
    };
    require_invalid_input([] { PCCD::Rigid_transform_3<float> t(Affine{}); }, {"translation entry (1, 3)", "float"});
}
