// The sphere fit of the implicit surface (PCCD/Surface/Surface_fit.h) against analytic truth: the
// closed form reproduces spheres and planes exactly from their points and normals, WLS_surface with
// the sphere fit is a signed distance on sampled spheres (where the plane fit shrinks), and on noisy
// samples of curved shapes its zero set lies closer to the true surface than the plane's.
#include "surface_test_helpers.h"

#include <PCCD/Surface/Euclidean_distance.h>
#include <PCCD/Surface/Surface_fit.h>
#include <PCCD/Surface/WLS_surface.h>

#include <PCCD/testing/statistics.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace pccd_test;
using Catch::Detail::Approx;

namespace {

/// `count` points of the sphere (centre, radius) within `cap` of the direction `axis` (an angular
/// cap), with their outward (or inward) normals, and random weights.
PCCD::internal::Sphere_sums sphere_sums(const Eigen::Vector3d& centre, double radius, const Eigen::Vector3d& x,
                                        bool outward, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    PCCD::internal::Sphere_sums sums;
    const Eigen::Vector3d axis = (x - centre).normalized();
    for (int k = 0; k < 40; ++k) {
        Eigen::Vector3d d = axis + 0.4 * Eigen::Vector3d(PCCD::standard_normal(engine), PCCD::standard_normal(engine),
                                                          PCCD::standard_normal(engine));
        d.normalize();
        const Eigen::Vector3d p = centre + radius * d;
        sums.add(p - x, PCCD::uniform_real(engine, 0.1, 1.0), outward ? d : Eigen::Vector3d(-d));
    }
    return sums;
}

using PCCD::testing::upper_median;

} // namespace

TEST_CASE("the closed-form sphere fit reproduces a sphere from its points and normals", "[surface]")
{
    const Eigen::Vector3d centre(0.3, -1.2, 2.0);
    const double radius = 0.7;
    for (const double offset : {-0.2, -0.01, 0.0, 0.05, 0.3}) {
        const Eigen::Vector3d x = centre + (radius + offset) * Eigen::Vector3d(1, 2, -2).normalized();
        const Eigen::Vector3d outward = (x - centre).normalized();
        // Outward normals: f is the signed distance |x - c| - radius, n the outward radial direction.
        const auto out = PCCD::internal::fit_sphere(sphere_sums(centre, radius, x, true, 11), outward);
        REQUIRE(out.has_value());
        CHECK(out->value == Approx(offset).margin(1e-12));
        CHECK((out->normal - outward).norm() < 1e-12);
        // Inward normals (the inside of a hollow): the sign flips with them.
        const auto in = PCCD::internal::fit_sphere(sphere_sums(centre, radius, x, false, 12), -outward);
        REQUIRE(in.has_value());
        CHECK(in->value == Approx(-offset).margin(1e-12));
        CHECK((in->normal + outward).norm() < 1e-12);
        // A reference against the fitted normals: not determined (the plane answers).
        CHECK_FALSE(PCCD::internal::fit_sphere(sphere_sums(centre, radius, x, true, 13), -outward).has_value());
    }
}

TEST_CASE("the closed-form sphere fit of a plane is the plane", "[surface]")
{
    PCCD::Random_engine engine(21);
    const Eigen::Vector3d normal = Eigen::Vector3d(0.2, -0.5, 1.0).normalized();
    const Eigen::Vector3d origin(1.0, 2.0, 3.0);
    const Eigen::Vector3d t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
    const Eigen::Vector3d x = origin + 0.3 * t1 + 0.25 * normal;
    PCCD::internal::Sphere_sums sums;
    for (int k = 0; k < 30; ++k) {
        const Eigen::Vector3d p =
            origin + PCCD::uniform_real(engine, -1.0, 1.0) * t1 + PCCD::uniform_real(engine, -1.0, 1.0) * t2;
        sums.add(p - x, PCCD::uniform_real(engine, 0.1, 1.0), normal);
    }
    const auto fit = PCCD::internal::fit_sphere(sums, normal);
    REQUIRE(fit.has_value());
    CHECK(fit->value == Approx(0.25).margin(1e-12));
    CHECK((fit->normal - normal).norm() < 1e-12);
}

TEST_CASE("the sphere fit is undetermined without spread or weight", "[surface]")
{
    PCCD::internal::Sphere_sums sums;
    CHECK_FALSE(PCCD::internal::fit_sphere(sums, Eigen::Vector3d::UnitZ()).has_value()); // no weight
    for (int k = 0; k < 5; ++k) sums.add(Eigen::Vector3d(0.1, 0.2, 0.3), 1.0, Eigen::Vector3d::UnitZ());
    CHECK_FALSE(PCCD::internal::fit_sphere(sums, Eigen::Vector3d::UnitZ()).has_value()); // one position
}

TEST_CASE("WLS_surface with the sphere fit is the signed distance of a sampled sphere", "[surface]")
{
    // Exact points and normals of a sphere: the sphere fit reproduces it wherever f is defined
    // (up to rounding); the plane fit's zero set lies inside (shrinkage ~ kappa h^2 / 2).
    const PCCD::testing::Sphere_shape sphere(Eigen::Vector3d(0.5, 0.0, -0.25), 0.8);
    const auto sample = sample_shape(sphere, 3000, 0.0, 31);
    const PCCD::Point_cloud<> cloud(sample.points);
    const PCCD::Gaussian_weight weight(0.12, 0.01);
    const PCCD::WLS_surface<PCCD::Euclidean_distance<>> sphere_fit(PCCD::Euclidean_distance<>(cloud), weight,
                                                                   sample.normals, {}, PCCD::Surface_fit::sphere);
    const PCCD::WLS_surface<PCCD::Euclidean_distance<>> plane_fit(PCCD::Euclidean_distance<>(cloud), weight,
                                                                  sample.normals);
    CHECK(sphere_fit.fit() == PCCD::Surface_fit::sphere);
    CHECK(plane_fit.fit() == PCCD::Surface_fit::plane);
    std::size_t defined = 0;
    std::vector<double> plane_at_surface;
    for (const Query& q : queries_near(sphere, 500, 0.05, 32)) {
        const auto s = sphere_fit.evaluate(q.x);
        const auto p = plane_fit.evaluate(q.x);
        REQUIRE(s.status == p.status); // the fit changes f and n, never where f is defined
        if (!s.defined()) continue;
        ++defined;
        CHECK(s.value == Approx(q.signed_distance).margin(1e-9));
        CHECK((s.normal - q.normal).norm() < 1e-8);
        plane_at_surface.push_back(p.value - q.signed_distance);
    }
    CHECK(defined > 450);
    // The plane's zero set is shrunk: f - d > 0 (x is outside its plane) by a visible amount.
    CHECK(upper_median(plane_at_surface) > 1e-3);
}

TEST_CASE("on noisy curved samples the sphere fit's zero set is closer to the surface", "[surface]")
{
    // Noise 0.3 mean spacings on the sphere and the torus, default Point_cloud_object options but
    // the fit: the zero set is found by projecting points of the true surface along n(x) (Newton on
    // f), and its distance to the true surface measured. Fixed seeds; measured medians (mean
    // spacings): sphere 0.072 (sphere fit) vs 0.101 (plane fit), torus 0.071 vs 0.133 (the noise,
    // 0.3 spacings, averaged over the kernel, sets the floor both fits share). Asserted: the sphere
    // fit's median at most 0.8 of the plane's.
    for (int shape_index = 0; shape_index < 2; ++shape_index) {
        const auto run = [&](const auto& shape, const char* name) {
            const auto sample = sample_shape(shape, 4000, 0.3, 41 + shape_index);
            const double spacing = 0.5 * std::sqrt(shape.area() / 4000.0);
            std::vector<double> errors[2];
            for (const PCCD::Surface_fit fit : {PCCD::Surface_fit::plane, PCCD::Surface_fit::sphere}) {
                const PCCD::Point_cloud_object<> object(columns(sample.points), {}, {.surface_fit = fit});
                REQUIRE(object.surface().fit() == fit);
                for (const Query& q : queries_near(shape, 400, 0.0, 51)) {
                    Eigen::Vector3d x = q.x;
                    bool defined = true;
                    for (int step = 0; step < 6 && defined; ++step) {
                        const auto e = object.surface().evaluate(x);
                        defined = e.defined();
                        if (defined) x -= e.value * e.normal;
                    }
                    if (defined) errors[int(fit)].push_back(std::abs(shape.signed_distance(x)) / spacing);
                }
            }
            REQUIRE(errors[0].size() > 350);
            REQUIRE(errors[1].size() > 350);
            const double plane = upper_median(errors[0]), sphere = upper_median(errors[1]);
            INFO(name << ": median distance of the zero set, plane " << plane << ", sphere " << sphere << " spacings");
            CHECK(sphere <= 0.8 * plane);
        };
        if (shape_index == 0) run(unit_sphere(), "sphere");
        else run(test_torus(), "torus");
    }
}

TEST_CASE("Point_cloud_object fits spheres by default, and an unknown fit is refused", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 500, 0.0, 61);
    const PCCD::Point_cloud_object<> object(columns(sample.points));
    CHECK(object.surface().fit() == PCCD::Surface_fit::sphere);
    CHECK(object.euclidean_surface().fit() == PCCD::Surface_fit::sphere);
    CHECK(std::string(PCCD::to_string(PCCD::Surface_fit::sphere)) == "sphere");
    CHECK(std::string(PCCD::to_string(PCCD::Surface_fit::plane)) == "plane");
    const PCCD::Point_cloud<> cloud(sample.points);
    CHECK_THROWS_AS(PCCD::WLS_surface<PCCD::Euclidean_distance<>>(PCCD::Euclidean_distance<>(cloud),
                                                                  PCCD::Gaussian_weight(0.1, 0.01), sample.normals,
                                                                  {}, PCCD::Surface_fit(7)),
                    PCCD::Invalid_input);
}
