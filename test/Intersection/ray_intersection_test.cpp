// Tests of ray_intersection() (doc/manual/intersection.md "Ray queries") against independent
// truth: a sampled sphere (analytic ray-sphere intersection and normal), a noisy area-sampled box
// with sharp edges (analytic ray-box intersection by slabs), posed objects, rays from inside, the
// budget and the rejected inputs. Also covers Intersection/Ray_hit.h and Intersection/Ray_options.h.
#include <PCCD/Error.h>
#include <PCCD/Intersection/Ray_hit.h>
#include <PCCD/Intersection/Ray_options.h>
#include <PCCD/Intersection/ray_intersection.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/sample_triangle_mesh.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/pose_generator.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "surface_test_helpers.h"

namespace {

using PCCD::Ray_hit;
using PCCD::Ray_status;
using PCCD::Rigid_transform_3;
using Vector = Eigen::Vector3d;
constexpr double inf = std::numeric_limits<double>::infinity();

double degrees(const Vector& u, const Vector& v)
{
    return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

Vector random_unit(PCCD::Random_engine& engine)
{
    const Vector v(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
    return v.normalized();
}

/// A unit vector perpendicular to u.
Vector perpendicular(const Vector& u, PCCD::Random_engine& engine)
{
    for (;;) {
        const Vector v = random_unit(engine);
        const Vector p = v - v.dot(u) * u;
        if (p.norm() > 0.1) return p.normalized();
    }
}

/// The unit sphere sampled with 6000 clean points (fixed seed); its spacing is the mean distance of
/// a point to its nearest neighbour, 0.5 sqrt(area / N) = 0.023.
struct Sphere_object {
    PCCD::Point_cloud_object<> object;
    double spacing;
};

const Sphere_object& sphere()
{
    static const Sphere_object s = [] {
        const auto sample = pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 31);
        return Sphere_object{PCCD::Point_cloud_object<>(sample.points), 0.5 * std::sqrt(4.0 * 3.14159265358979323846 / 6000)};
    }();
    return s;
}

/// The box [-1, 1] x [-0.6, 0.6] x [-0.4, 0.4] as 12 triangles, area-sampled with 10,000 points and
/// Gaussian noise of 0.3 spacings (fixed seed).
const Vector box_min(-1.0, -0.6, -0.4), box_max(1.0, 0.6, 0.4);

struct Box_object {
    PCCD::Point_cloud_object<> object;
    double spacing;
};

const Box_object& box()
{
    static const Box_object b = [] {
        std::vector<Vector> v;
        for (int k = 0; k < 8; ++k)
            v.emplace_back(k & 1 ? box_max.x() : box_min.x(), k & 2 ? box_max.y() : box_min.y(),
                           k & 4 ? box_max.z() : box_min.z());
        const std::vector<std::array<int, 3>> faces{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
        const Vector size = box_max - box_min;
        const double area = 2.0 * (size.x() * size.y() + size.y() * size.z() + size.x() * size.z());
        const std::size_t n = 10000;
        const double spacing = 0.5 * std::sqrt(area / double(n));
        PCCD::Random_engine engine(41);
        const auto sample = PCCD::sample_triangle_mesh(v, faces, n, engine, {.noise_sigma = 0.3 * spacing});
        return Box_object{PCCD::Point_cloud_object<>(sample.points), spacing};
    }();
    return b;
}

/// The analytic first hit of o + t u (|u| = 1), t >= 0, with the box (slabs): t and the face normal;
/// t = +inf for a miss. `grow` enlarges the box on every side.
struct Box_hit {
    double t = inf;
    Vector normal = Vector::Zero();
};

Box_hit ray_box(const Vector& o, const Vector& u, double grow = 0.0)
{
    double enter = 0.0, exit = inf;
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
        const double lo = box_min(a) - grow, hi = box_max(a) + grow;
        if (u(a) == 0.0) {
            if (o(a) < lo || o(a) > hi) return {};
            continue;
        }
        double t1 = (lo - o(a)) / u(a), t2 = (hi - o(a)) / u(a);
        if (t1 > t2) std::swap(t1, t2);
        if (t1 > enter) enter = t1, axis = a;
        exit = std::min(exit, t2);
    }
    if (enter > exit || axis < 0) return {};
    Box_hit hit{enter, Vector::Zero()};
    hit.normal(axis) = u(axis) > 0.0 ? -1.0 : 1.0;
    return hit;
}

/// Distance from p to the nearest edge of the box (the lines where two faces meet, clipped).
double distance_to_edges(const Vector& p)
{
    double best = inf;
    for (int a = 0; a < 3; ++a) { // edges parallel to axis a
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (const double yb : {box_min(b), box_max(b)})
            for (const double yc : {box_min(c), box_max(c)}) {
                const double along = std::clamp(p(a), box_min(a), box_max(a));
                const double db = p(b) - yb, dc = p(c) - yc, da = p(a) - along;
                best = std::min(best, std::sqrt(da * da + db * db + dc * dc));
            }
    }
    return best;
}

/// Distance from p to the box's surface.
double distance_to_box_surface(const Vector& p)
{
    const Vector outside = (p - box_max).cwiseMax(box_min - p).cwiseMax(0.0);
    if (outside.squaredNorm() > 0.0) return outside.norm();
    return std::min((box_max - p).minCoeff(), (p - box_min).minCoeff());
}

} // namespace

TEST_CASE("ray_intersection: rays from outside hit a sampled sphere where the analytic sphere is", "[intersection][ray]")
{
    const Sphere_object& s = sphere();
    PCCD::Random_engine engine(7);
    std::vector<double> t_errors, angles;
    std::vector<std::size_t> evaluations;
    for (int k = 0; k < 300; ++k) {
        // impact parameter b in [0, 0.9] (incidence up to 64 degrees), origin 1.5 to 4 away along -u
        const Vector u = random_unit(engine);
        const double b = 0.9 * std::sqrt(PCCD::uniform_01(engine));
        const double back = PCCD::uniform_real(engine, 1.5, 4.0);
        const Vector origin = b * perpendicular(u, engine) - back * u;
        const double t_true = back - std::sqrt(1.0 - b * b);
        const Ray_hit hit = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, 3.0 * u);
        INFO("ray " << k << ": b " << b << " t_true " << t_true << " status " << PCCD::to_string(hit.status));
        REQUIRE(hit.status == Ray_status::hit);
        REQUIRE(hit.hit);
        REQUIRE(static_cast<bool>(hit));
        CHECK(hit.entering);
        CHECK((hit.point - (origin + hit.t * u)).norm() <= 1e-12);
        CHECK(std::abs(hit.normal.norm() - 1.0) <= 1e-12);
        CHECK(std::abs(hit.f) <= 0.05 * s.object.sampling_radius());
        CHECK(hit.nearest_point < s.object.size());
        // along the sphere's normal: |t - t_true| cos(incidence), cos = sqrt(1 - b^2)
        t_errors.push_back(std::abs(hit.t - t_true) * std::sqrt(1.0 - b * b) / s.spacing);
        CHECK(std::abs(hit.point.norm() - 1.0) <= 0.2 * s.spacing);
        angles.push_back(degrees(hit.normal, hit.point));
        evaluations.push_back(hit.counters.f_evaluations);
    }
    std::sort(t_errors.begin(), t_errors.end());
    std::sort(angles.begin(), angles.end());
    std::sort(evaluations.begin(), evaluations.end());
    INFO("|t - t_true| cos: median " << t_errors[150] << ", max " << t_errors.back() << " spacings; normal: median "
                                 << angles[150] << ", max " << angles.back() << " degrees; f evaluations: median "
                                 << evaluations[150] << ", max " << evaluations.back());
    std::printf("sphere: |t - t_true| cos(incidence) median %.3f max %.3f spacings; normal median %.2f max %.2f deg; f evaluations median %zu max %zu\n",
                t_errors[150], t_errors.back(), angles[150], angles.back(), evaluations[150], evaluations.back());
    // The hit lies within epsilon (0.05 r, 0.12 spacings) of the fitted sphere, which lies within a
    // small fraction of a spacing of the true one: within 0.2 spacings along the normal.
    CHECK(t_errors.back() <= 0.2);
    CHECK(angles.back() <= 3.0);
    CHECK(evaluations[150] <= 8);
    CHECK(evaluations.back() <= 30);
}

TEST_CASE("ray_intersection: misses, t_max and a posed sphere", "[intersection][ray]")
{
    const Sphere_object& s = sphere();
    PCCD::Random_engine engine(8);
    SECTION("rays passing more than 2 spacings from the sphere miss")
    {
        for (int k = 0; k < 100; ++k) {
            const Vector u = random_unit(engine);
            const double b = 1.0 + s.spacing * PCCD::uniform_real(engine, 2.0, 10.0);
            const Vector origin = b * perpendicular(u, engine) - 3.0 * u;
            const Ray_hit hit = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u);
            INFO("ray " << k << ": passes " << (b - 1.0) / s.spacing << " spacings from the sphere");
            CHECK(hit.status == Ray_status::miss);
            CHECK_FALSE(hit);
            CHECK(std::isinf(hit.t));
            CHECK(std::isnan(hit.point.x()));
        }
    }
    SECTION("t_max before the sphere: no hit; just after it: the hit")
    {
        for (int k = 0; k < 40; ++k) {
            const Vector u = random_unit(engine);
            const double b = 0.8 * PCCD::uniform_01(engine);
            const Vector origin = b * perpendicular(u, engine) - 3.0 * u;
            const double t_true = 3.0 - std::sqrt(1.0 - b * b);
            const Ray_hit short_ray = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u,
                                                             t_true - 2.0 * s.spacing);
            CHECK(short_ray.status == Ray_status::miss);
            const Ray_hit long_ray = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u,
                                                            t_true + 2.0 * s.spacing);
            REQUIRE(long_ray.hit);
            CHECK(long_ray.t <= t_true + 2.0 * s.spacing);
            CHECK(std::abs(long_ray.t - t_true) * std::sqrt(1.0 - b * b) <= 0.2 * s.spacing);
        }
        // t_max = 0 looks at the origin only
        CHECK(PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), Vector(0, 0, -3), Vector::UnitZ(), 0.0).status ==
              Ray_status::miss);
    }
    SECTION("a rotated and translated sphere: the same hits in the world frame")
    {
        for (int k = 0; k < 40; ++k) {
            const Rigid_transform_3<double> pose(PCCD::testing::uniform_random_rotation(engine),
                                                 Vector(PCCD::uniform_real(engine, -5, 5), PCCD::uniform_real(engine, -5, 5),
                                                        PCCD::uniform_real(engine, -5, 5)));
            const Vector centre = pose.translation();
            const Vector u = random_unit(engine);
            const double b = 0.85 * PCCD::uniform_01(engine);
            const Vector origin = centre + b * perpendicular(u, engine) - 2.5 * u;
            const double t_true = 2.5 - std::sqrt(1.0 - b * b);
            const Ray_hit hit = PCCD::ray_intersection(s.object, pose, origin, 0.25 * u);
            REQUIRE(hit.hit);
            CHECK(std::abs(hit.t - t_true) * std::sqrt(1.0 - b * b) <= 0.2 * s.spacing);
            CHECK(std::abs((hit.point - centre).norm() - 1.0) <= 0.2 * s.spacing);
            CHECK(degrees(hit.normal, hit.point - centre) <= 3.0);
            // the same ray in the sphere's frame gives the same t
            const Rigid_transform_3<double> inverse = pose.inverse();
            const Ray_hit local = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(),
                                                         inverse.transform_point(origin), inverse.transform_vector(u));
            REQUIRE(local.hit);
            CHECK(std::abs(local.t - hit.t) <= 1e-3 * s.spacing);
        }
    }
}

TEST_CASE("ray_intersection: a ray starting inside hits where it leaves", "[intersection][ray]")
{
    const Sphere_object& s = sphere();
    PCCD::Random_engine engine(9);
    for (int k = 0; k < 40; ++k) {
        // from the centre (f undefined there: far from every point) and from just inside the surface
        const Vector u = random_unit(engine);
        const Vector origin = (k % 2 == 0 ? 0.0 : 0.95) * random_unit(engine);
        const double along = origin.dot(u);
        const double t_true = -along + std::sqrt(along * along - origin.squaredNorm() + 1.0);
        const Ray_hit hit = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u);
        INFO("ray " << k << " from " << origin.norm());
        REQUIRE(hit.hit);
        CHECK_FALSE(hit.entering);
        // within 0.2 spacings of the sphere, so within 0.2 spacings / cos(incidence) along the ray
        const double cosine = std::abs(u.dot((origin + t_true * u).normalized()));
        CHECK(std::abs(hit.point.norm() - 1.0) <= 0.2 * s.spacing);
        CHECK(std::abs(hit.t - t_true) <= 0.2 * s.spacing / cosine);
        CHECK(degrees(hit.normal, hit.point) <= 3.0); // outward, along the ray's way out
    }
    // a ray starting on the surface hits at t = 0
    const Ray_hit on = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), Vector(0, 0, 1), Vector(1, 0, 0));
    REQUIRE(on.hit);
    CHECK(on.t == 0.0);
}

TEST_CASE("ray_intersection: a noisy box with sharp edges against the analytic ray-box intersection", "[intersection][ray]")
{
    // 1000 rays from a sphere of radius 3 around the box, aimed at points of the box grown by 30 %
    // (fixed seed). Classes, by the analytic intersection:
    // - face rays: the entry point, and the ray's point 2 spacings above the face, lie 8 spacings
    //   or more from every edge (the implicit surface rounds the edges over its kernel, about 7
    //   spacings), incidence below 75 degrees: must hit, within 0.5 spacings of the face (measured
    //   along the face normal: |t - t_true| cos(incidence)), the normal within 10 degrees of the
    //   face's, entering;
    // - edge rays (the other analytic hits): must hit, within 2 spacings of the box surface, unless
    //   the chord through the box is shorter than 4 spacings (an edge or corner clipped, which the
    //   rounded surface may lose),
    //   and not beyond the middle of its chord through the box (no ray passes through a wall
    //   unseen; a ray grazing an edge may see the rounded surface from inside first);
    // - misses by more than 2 spacings (the ray misses the box grown by 2 spacings): must miss.
    // A ray that does not do what its class asks is a failure.
    const Box_object& b = box();
    PCCD::Random_engine engine(10);
    const int rays = 1000;
    int face_rays = 0, edge_rays = 0, miss_rays = 0, face_failures = 0, edge_failures = 0, miss_failures = 0;
    int approximate = 0, exits = 0;
    std::vector<double> face_errors, face_angles, edge_errors;
    std::size_t evaluations = 0, rejected = 0;
    for (int k = 0; k < rays; ++k) {
        const Vector origin = 3.0 * random_unit(engine);
        const Vector target(PCCD::uniform_real(engine, -1.3, 1.3), PCCD::uniform_real(engine, -0.8, 0.8),
                            PCCD::uniform_real(engine, -0.55, 0.55));
        const Vector u = (target - origin).normalized();
        const Box_hit truth = ray_box(origin, u);
        const Ray_hit hit = PCCD::ray_intersection(b.object, Rigid_transform_3<double>(), origin, u);
        INFO("ray " << k << ": analytic t " << truth.t << ", found " << PCCD::to_string(hit.status) << " at t " << hit.t);
        evaluations += hit.counters.f_evaluations;
        rejected += hit.counters.rejected_sign_changes;
        REQUIRE(hit.status != Ray_status::undecided);
        if (hit.hit) {
            approximate += hit.approximate ? 1 : 0;
            if (!hit.entering) ++exits;
        }
        if (std::isinf(truth.t)) {
            if (!std::isinf(ray_box(origin, u, 2.0 * b.spacing).t)) continue; // within 2 spacings of the box
            ++miss_rays;
            if (hit.hit) ++miss_failures;
            continue;
        }
        const Vector entry = origin + truth.t * u;
        const double cosine = std::abs(truth.normal.dot(u));
        const Vector above = entry - (2.0 * b.spacing / cosine) * u;
        if (cosine >= 0.26 && distance_to_edges(entry) >= 8.0 * b.spacing && distance_to_edges(above) >= 8.0 * b.spacing) {
            ++face_rays;
            if (!hit.hit) {
                ++face_failures;
                continue;
            }
            face_errors.push_back(std::abs(hit.t - truth.t) * cosine / b.spacing);
            face_angles.push_back(degrees(hit.normal, truth.normal));
            if (face_errors.back() > 0.5 || face_angles.back() > 10.0 || !hit.entering) ++face_failures;
        } else {
            ++edge_rays;
            // the chord: from the entry to the exit of the box
            double exit = inf;
            for (int a = 0; a < 3; ++a)
                if (u(a) != 0.0) exit = std::min(exit, std::max((box_min(a) - origin(a)) / u(a), (box_max(a) - origin(a)) / u(a)));
            const bool short_chord = exit - truth.t < 4.0 * b.spacing;
            if (!hit.hit) {
                if (!short_chord) ++edge_failures;
                continue;
            }
            edge_errors.push_back(distance_to_box_surface(hit.point) / b.spacing);
            // near the box, and not through it: not beyond the middle of a chord of 4 spacings or more
            if (edge_errors.back() > 2.0 || (!short_chord && hit.t > 0.5 * (truth.t + exit))) ++edge_failures;
        }
    }
    std::sort(face_errors.begin(), face_errors.end());
    std::sort(face_angles.begin(), face_angles.end());
    std::sort(edge_errors.begin(), edge_errors.end());
    const auto median = [](const std::vector<double>& v) { return v.empty() ? 0.0 : v[v.size() / 2]; };
    const auto largest = [](const std::vector<double>& v) { return v.empty() ? 0.0 : v.back(); };
    std::printf("box: %d face rays (offset median %.3f max %.3f spacings, normal median %.2f max %.2f deg, %d failures), "
                "%d edge rays (distance to the box median %.3f max %.3f spacings, %d failures), %d misses (%d failures); "
                "%.1f f evaluations per ray, %zu rejected sign changes, %d approximate hits, %d exits\n",
                face_rays, median(face_errors), largest(face_errors), median(face_angles), largest(face_angles), face_failures,
                edge_rays, median(edge_errors), largest(edge_errors), edge_failures, miss_rays, miss_failures,
                double(evaluations) / rays, rejected, approximate, exits);
    CHECK(face_rays >= 300);
    CHECK(edge_rays >= 50);
    CHECK(miss_rays >= 100);
    // At most 1 % of each class (this seed: none). Five other seeds of cloud and rays failed 2 of
    // 2250 face rays by passing through a pocket of the noisy face where f is undefined all along
    // their way through (the domain radii of a noisy cluster are small), 1 by a 0.54-spacing
    // offset; 7 of 1650 edge rays and 2 of 880 misses met the surface 2.3-3.3 spacings outside a
    // sharp edge, where the fit bulges out.
    CHECK(face_failures <= face_rays / 100);
    CHECK(edge_failures <= edge_rays / 100);
    CHECK(miss_failures <= miss_rays / 100);
}

TEST_CASE("ray_intersection: the budget and deterministic answers", "[intersection][ray]")
{
    const Sphere_object& s = sphere();
    const Vector origin(0.3, -0.2, -3.0), u(0, 0, 1);
    const Ray_hit full = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u);
    REQUIRE(full.hit);
    REQUIRE(full.counters.f_evaluations >= 2);
    const Ray_hit again = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u);
    CHECK(again.t == full.t);
    CHECK(again.counters.f_evaluations == full.counters.f_evaluations);
    CHECK(again.counters.node_visits == full.counters.node_visits);
    CHECK(full.counters.node_visits >= full.counters.leaf_visits);
    CHECK(full.counters.leaf_visits >= 1);
    const Ray_hit cut = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u, inf,
                                               {.max_f_evaluations = full.counters.f_evaluations - 1});
    CHECK(cut.status == Ray_status::undecided);
    CHECK_FALSE(cut);
    CHECK(cut.counters.f_evaluations == full.counters.f_evaluations - 1);
    const Ray_hit enough = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u, inf,
                                                  {.max_f_evaluations = full.counters.f_evaluations});
    CHECK(enough.hit);
    CHECK(enough.t == full.t);
    // a far miss costs no evaluation: the ray crosses no reach ball
    const Ray_hit far = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), Vector(5, 5, 5), Vector(1, 0, 0));
    CHECK(far.status == Ray_status::miss);
    CHECK(far.counters.f_evaluations == 0);
    // a tighter epsilon: |f| at the hit within it
    const Ray_hit tight = PCCD::ray_intersection(s.object, Rigid_transform_3<double>(), origin, u, inf, {.epsilon = 1e-6});
    REQUIRE(tight.hit);
    CHECK(std::abs(tight.f) <= 1e-6);
    CHECK(std::string(PCCD::to_string(Ray_status::hit)) == "hit");
    CHECK(std::string(PCCD::to_string(Ray_status::miss)) == "miss");
    CHECK(std::string(PCCD::to_string(Ray_status::undecided)) == "undecided");
}

TEST_CASE("ray_intersection: bad input is rejected with a message", "[intersection][ray][robustness]")
{
    const Sphere_object& s = sphere();
    const Rigid_transform_3<double> pose;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto message = [&](auto&& call) -> std::string {
        try {
            call();
        } catch (const PCCD::Invalid_input& e) {
            return e.what();
        }
        return "no exception";
    };
    using Catch::Matchers::Contains;
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector(nan, 0, 0), Vector::UnitX()); }),
               Contains("origin") && Contains("not finite"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector(inf, 0, 0), Vector::UnitX()); }),
               Contains("origin"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector(0, inf, 0)); }),
               Contains("direction") && Contains("not finite"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::Zero()); }),
               Contains("direction is zero"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), -1.0); }),
               Contains("t_max"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), nan); }),
               Contains("t_max"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), inf, {.epsilon = 0.0}); }),
               Contains("epsilon"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), inf, {.epsilon = nan}); }),
               Contains("epsilon"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), inf, {.step_fraction = 0.0}); }),
               Contains("step_fraction"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), inf, {.step_fraction = 1.5}); }),
               Contains("step_fraction"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), inf, {.step_fraction = nan}); }),
               Contains("step_fraction"));
    CHECK_THAT(message([&] { PCCD::ray_intersection(s.object, pose, Vector::Zero(), Vector::UnitX(), inf, {.max_f_evaluations = 0}); }),
               Contains("max_f_evaluations"));
    // huge and tiny directions are normalized without overflow
    CHECK(PCCD::ray_intersection(s.object, pose, Vector(0, 0, -3), Vector(0, 0, 1e300)).hit);
    CHECK(PCCD::ray_intersection(s.object, pose, Vector(0, 0, -3), Vector(0, 0, 1e-300)).hit);
    // t_max = +inf and directions along an axis (parallel to box faces) are fine
    CHECK(PCCD::ray_intersection(s.object, pose, Vector(0, 0, -3), Vector(0, 0, 1), inf).hit);
}
