// Flightplans (doc/manual/kinetic.md, "Flightplans"; doc/reference/kinetic-concepts.md): concepts,
// and crossing times of linear, piecewise-linear and cubic flightplans against independent truths --
// closed forms, exact integer key frames, motions with crossings at known times, next_crossing's
// definition evaluated over the negative intervals of the difference, Eigen's polynomial solver
// and dense sampling. Crossings at key-frame boundaries must be found exactly once.
// Also covers Kinetic/Cubic.h, Kinetic/next_crossing.h: the test cases below exercise what they declare.
#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/Kinetic/Polynomial_flightplan.h>
#include <PCCD/Kinetic/next_crossing.h>
#include <PCCD/Random.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

#include <unsupported/Eigen/Polynomials>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

using PCCD::Linear_flightplan;
using PCCD::Piecewise_linear_flightplan;
using PCCD::Polynomial_flightplan;

static_assert(PCCD::Flightplan<Linear_flightplan>);
static_assert(PCCD::Flightplan<Piecewise_linear_flightplan>);
static_assert(PCCD::Flightplan<Polynomial_flightplan>);
static_assert(!PCCD::Flightplan<int>);
static_assert(!PCCD::Flightplan<Eigen::Vector3d>);
static_assert(PCCD::KineticPrimitive<PCCD::Kinetic_point>);
static_assert(PCCD::KineticPrimitive<PCCD::Kinetic_triangle>);
static_assert(!PCCD::KineticPrimitive<int>);
static_assert(!PCCD::KineticPrimitive<std::array<std::uint32_t, 3>>);

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// All crossings of coordinate `axis` after t_begin, found by alternating next_crossing between the
/// flightplan currently above and the one below. The one that stays above longer starts as the
/// upper one (so leaving an initial tie is no crossing).
template <class F>
std::vector<double> enumerate_crossings(const F& a, const F& b, int axis, double t_begin)
{
    std::vector<double> out;
    const bool a_upper = a.next_crossing(b, axis, t_begin) >= b.next_crossing(a, axis, t_begin);
    const F* upper = a_upper ? &a : &b;
    const F* lower = a_upper ? &b : &a;
    double t = t_begin;
    for (int guard = 0; guard < 10000; ++guard) {
        const double s = upper->next_crossing(*lower, axis, t);
        if (s == inf) break;
        if (s > t_begin) out.push_back(s);
        std::swap(upper, lower);
        t = s;
    }
    return out;
}

Eigen::Vector3d random_vector(PCCD::Random_engine& rng, double scale)
{
    return {PCCD::uniform_real(rng, -scale, scale), PCCD::uniform_real(rng, -scale, scale),
            PCCD::uniform_real(rng, -scale, scale)};
}

} // namespace

TEST_CASE("linear flightplans cross where the closed form says", "[kinetic][flightplan]")
{
    const Linear_flightplan a({0, 0, 0}, {1, 0, 0});
    const Linear_flightplan b({1, 0, 0}, {0, 0, 0});
    CHECK(a.position(2.0) == Eigen::Vector3d(2, 0, 0));
    CHECK(a.next_crossing(b, 0, -3.0) == -3.0); // a is below b already
    CHECK(b.next_crossing(a, 0, -3.0) == 1.0);  // b drops below a at t = 1
    CHECK(b.next_crossing(a, 0, 2.0) == 2.0);
    CHECK(a.next_crossing(b, 0, 2.0) == inf);
    CHECK(a.next_crossing(b, 1, 0.0) == inf); // tied forever on y: not a crossing
    CHECK(a.next_crossing(a, 2, 0.0) == inf);

    PCCD::Random_engine rng(11);
    for (int trial = 0; trial < 1000; ++trial) {
        const Linear_flightplan p(random_vector(rng, 1), random_vector(rng, 1), PCCD::uniform_real(rng, -1, 1));
        const Linear_flightplan q(random_vector(rng, 1), random_vector(rng, 1), PCCD::uniform_real(rng, -1, 1));
        const int axis = int(PCCD::uniform_index(rng, 3));
        // d(t) = p - q = alpha + beta t
        const double beta = p.velocity()[axis] - q.velocity()[axis];
        const double alpha = p.start()[axis] - p.velocity()[axis] * p.t0() - q.start()[axis] + q.velocity()[axis] * q.t0();
        const double root = -alpha / beta;
        const double t = PCCD::uniform_real(rng, -3, 3);
        const double got = p.next_crossing(q, axis, t);
        if (alpha + beta * t < -1e-12 && (beta < 0 || root > t + 1e-9)) {
            CHECK(got == t);
        } else if (beta < 0 && root > t + 1e-9) {
            CHECK(got == Approx(root).margin(1e-9));
        } else if (beta > 0 && root < t - 1e-9) {
            CHECK(got == inf);
        }
    }
}

TEST_CASE("piecewise-linear crossings at key frames are found exactly once", "[kinetic][flightplan]")
{
    const std::vector<double> times{0, 1, 2, 3};
    auto along_x = [&](std::vector<double> xs) {
        std::vector<Eigen::Vector3d> p;
        for (double x : xs) p.emplace_back(x, 0, 0);
        return Piecewise_linear_flightplan(times, p);
    };
    const auto zero = along_x({0, 0, 0, 0});

    SECTION("a transversal crossing exactly at a key frame")
    {
        const auto a = along_x({2, 0, -2, -4});
        CHECK(a.next_crossing(zero, 0, -1.0) == 1.0);
        CHECK(zero.next_crossing(a, 0, 1.0) == inf);
        CHECK(enumerate_crossings(a, zero, 0, -1.0) == std::vector<double>{1.0});
    }
    SECTION("touching at a key frame is no crossing")
    {
        const auto a = along_x({2, 0, 2, 2});
        CHECK(a.next_crossing(zero, 0, -1.0) == inf);
        CHECK(enumerate_crossings(a, zero, 0, -1.0).empty());
    }
    SECTION("running tied over a segment, then crossing at its end")
    {
        const auto a = along_x({1, 0, 0, -1});
        CHECK(a.next_crossing(zero, 0, -1.0) == 2.0);
        CHECK(a.next_crossing(zero, 0, 1.5) == 2.0);
        CHECK(zero.next_crossing(a, 0, -1.0) == -1.0); // zero is below a until t = 1
        CHECK(zero.next_crossing(a, 0, 1.0) == inf);   // then tied, then above
        CHECK(enumerate_crossings(a, zero, 0, -1.0) == std::vector<double>{2.0});
    }
    SECTION("clamped outside the key range")
    {
        const auto a = along_x({-1, 1, 1, 1});
        CHECK(a.position(-5.0).x() == -1.0);
        CHECK(a.position(7.0).x() == 1.0);
        CHECK(zero.next_crossing(a, 0, -10.0) == 0.5);
    }
    SECTION("exhaustive integer key frames: every sign change once, at its exact time")
    {
        PCCD::Random_engine rng(5);
        const std::vector<double> keys{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
        for (int trial = 0; trial < 2000; ++trial) {
            std::vector<Eigen::Vector3d> pa, pb;
            std::vector<double> d;
            for (std::size_t k = 0; k < keys.size(); ++k) {
                const double x = double(PCCD::uniform_index(rng, 3)) - 1.0;
                const double y = double(PCCD::uniform_index(rng, 3)) - 1.0;
                pa.emplace_back(x, 0, 0);
                pb.emplace_back(y, 0, 0);
                d.push_back(x - y);
            }
            // Truth: sign changes of d between key frames, skipping zeros; the crossing time is
            // where d leaves zero (or the linear root between two nonzero values).
            std::vector<double> expected;
            int last_sign = 0;
            std::size_t last_index = 0;
            for (std::size_t k = 0; k < d.size(); ++k) {
                const int s = (d[k] > 0) - (d[k] < 0);
                if (s == 0) continue;
                if (last_sign != 0 && s != last_sign) {
                    if (last_index + 1 == k)
                        expected.push_back(keys[last_index] + d[last_index] / (d[last_index] - d[k]));
                    else
                        expected.push_back(keys[k - 1]);
                }
                last_sign = s;
                last_index = k;
            }
            // Separate key time vectors take the general path, shared ones the key scan.
            const Piecewise_linear_flightplan a(keys, pa), b(keys, pb);
            const auto shared = std::make_shared<const std::vector<double>>(keys);
            const Piecewise_linear_flightplan sa(shared, pa), sb(shared, pb);
            for (const auto& got : {enumerate_crossings(a, b, 0, -1.0), enumerate_crossings(sa, sb, 0, -1.0)}) {
                REQUIRE(got.size() == expected.size());
                for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-12));
                CHECK(std::is_sorted(got.begin(), got.end()));
                CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
            }
        }
    }
}

namespace {

/// next_crossing of two key-framed motions with the same key times `ts`, from its definition
/// inf{ s > t : d(s) < 0 } for d = a - b, by a route of its own: `d` holds the differences at the
/// keys (exact for the data below); d is linear between keys and constant outside, so its negative
/// set is a union of open intervals read off the signs of d at the ends of each key interval (the
/// whole constant end beyond the first or last key when d is negative there). The answer is the
/// smallest max(begin, t) over the intervals that end after t, +infinity when none does. Zeros
/// inside a key interval are computed in long double from the interval's far end, so they agree
/// with the flightplan's to rounding only.
long double crossing_by_definition(const std::vector<double>& ts, const std::vector<double>& d, double t)
{
    struct Interval {
        long double begin, end;
    };
    constexpr long double unbounded = std::numeric_limits<long double>::infinity();
    std::vector<Interval> negative;
    if (d.front() < 0) negative.push_back({-unbounded, ts.front()});
    for (std::size_t k = 1; k < ts.size(); ++k) {
        const long double lo = ts[k - 1], hi = ts[k], d0 = d[k - 1], d1 = d[k];
        auto zero = [&] { return hi - (hi - lo) * d1 / (d1 - d0); }; // only where the signs differ
        if (d0 < 0 && d1 < 0)
            negative.push_back({lo, hi});
        else if (d0 >= 0 && d1 < 0)
            negative.push_back({zero(), hi});
        else if (d0 < 0 && d1 >= 0)
            negative.push_back({lo, zero()});
    }
    if (d.back() < 0) negative.push_back({ts.back(), unbounded});
    long double first = unbounded;
    for (const Interval& i : negative)
        if (i.end > t) first = std::min(first, std::max(i.begin, static_cast<long double>(t)));
    return first;
}

/// x rounded to a multiple of 2^-10: differences of such values in [-8, 8] are exact doubles.
double quantized(double x) { return std::round(x * 1024.0) / 1024.0; }

} // namespace

TEST_CASE("piecewise-linear crossings on shared key times, blocks skipped or not, match the definition",
          "[kinetic][flightplan]")
{
    // Long animations alternating stretches where the two flightplans are far apart (whole blocks
    // of keys skipped by the key scan) with stretches of near-ties, exact ties (axis 2) and
    // crossings, at query times on and between keys. Both the key scan (shared key times) and the
    // general route (the same key times in two vectors) are held to crossing_by_definition.
    PCCD::Random_engine rng(31);
    int finite = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t keys = 20 + PCCD::uniform_index(rng, 300);
        const auto ts = std::make_shared<std::vector<double>>(keys);
        std::vector<Eigen::Vector3d> pa(keys), pb(keys);
        double gap = 1.0;
        for (std::size_t k = 0; k < keys; ++k) {
            (*ts)[k] = 0.5 * double(k);
            if (PCCD::uniform_index(rng, 12) == 0)
                gap = PCCD::uniform_index(rng, 3) == 0 ? 0.0 : quantized(2.0 * PCCD::uniform_real(rng, -1.0, 1.0));
            for (int axis = 0; axis < 3; ++axis) {
                pb[k][axis] = quantized(PCCD::uniform_real(rng, -0.5, 0.5));
                pa[k][axis] = pb[k][axis] + gap + (axis == 2 ? 0.0 : quantized(PCCD::uniform_real(rng, -0.3, 0.3)));
            }
        }
        const Piecewise_linear_flightplan a(ts, pa), b(ts, pb);
        const Piecewise_linear_flightplan general_a(*ts, pa), general_b(*ts, pb);
        REQUIRE(a.key_times() == b.key_times());
        REQUIRE(general_a.key_times() != general_b.key_times());
        for (int q = 0; q < 40; ++q) {
            const double t = q % 4 == 0 ? (*ts)[PCCD::uniform_index(rng, keys)] : PCCD::uniform_real(rng, -1.0, 0.5 * double(keys));
            for (int axis = 0; axis < 3; ++axis) {
                std::vector<double> ab(keys), ba(keys);
                for (std::size_t k = 0; k < keys; ++k) {
                    ab[k] = pa[k][axis] - pb[k][axis];
                    ba[k] = pb[k][axis] - pa[k][axis];
                }
                const long double a_drops = crossing_by_definition(*ts, ab, t);
                const long double b_drops = crossing_by_definition(*ts, ba, t);
                for (const auto& [x, y, truth] : {std::tuple(&a, &b, a_drops), std::tuple(&b, &a, b_drops),
                                                  std::tuple(&general_a, &general_b, a_drops),
                                                  std::tuple(&general_b, &general_a, b_drops)}) {
                    const double got = x->next_crossing(*y, axis, t);
                    if (truth == std::numeric_limits<long double>::infinity()) {
                        CHECK(got == inf);
                    } else {
                        CHECK(got == Approx(double(truth)).margin(1e-11));
                        ++finite;
                    }
                }
            }
        }
    }
    CHECK(finite > 10000);
}

TEST_CASE("piecewise-linear key scan over long separated stretches: a triangle wave crossing at known times",
          "[kinetic][flightplan]")
{
    // a's x falls by 0.25 per key for 20 keys, then rises for 20 (keys every 0.5, from 2.625 down to
    // -2.375 and back); b rests at 0. a drops below b halfway between keys 10 and 11 of each period,
    // at t = 5.25 + 20 j, and rises above it at t = 14.75 + 20 j, for j = 0 .. 4 (200 keys, then a
    // rests above b). On y a stays 10 above b: never a crossing. All these times are exact doubles.
    const std::size_t keys = 200;
    const auto ts = std::make_shared<std::vector<double>>(keys);
    std::vector<Eigen::Vector3d> pa(keys), pb(keys, Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < keys; ++k) {
        (*ts)[k] = 0.5 * double(k);
        const std::size_t phase = k % 40, descent = phase <= 20 ? phase : 40 - phase;
        pa[k] = Eigen::Vector3d(2.625 - 0.25 * double(descent), 10.0, 0.0);
    }
    // The open intervals where a's x is below b's and where b's is below a's, and the definition of
    // next_crossing over them: the smallest max(begin, t) of an interval that ends after t.
    std::vector<std::pair<double, double>> a_below{}, b_below{{-inf, 5.25}};
    for (int j = 0; j < 5; ++j) {
        a_below.emplace_back(5.25 + 20 * j, 14.75 + 20 * j);
        b_below.emplace_back(14.75 + 20 * j, j < 4 ? 25.25 + 20 * j : inf);
    }
    auto first_after = [](const std::vector<std::pair<double, double>>& intervals, double t) {
        double first = inf;
        for (const auto& [begin, end] : intervals)
            if (end > t) first = std::min(first, std::max(begin, t));
        return first;
    };
    const Piecewise_linear_flightplan a(ts, pa), b(ts, pb);
    const Piecewise_linear_flightplan general_a(*ts, pa), general_b(*ts, pb);
    std::vector<double> queries{-3.0, 0.0, 5.0, 5.25, 5.5, 10.0, 14.75, 14.8, 20.0, 25.25, 60.0, 94.75, 99.5, 120.0};
    for (int i = 0; i <= 1000; ++i) queries.push_back(-1.0 + 0.125 * i);
    for (const double t : queries) {
        CHECK(a.next_crossing(b, 0, t) == first_after(a_below, t));
        CHECK(b.next_crossing(a, 0, t) == first_after(b_below, t));
        CHECK(general_a.next_crossing(general_b, 0, t) == first_after(a_below, t));
        CHECK(general_b.next_crossing(general_a, 0, t) == first_after(b_below, t));
        CHECK(a.next_crossing(b, 1, t) == inf);
        CHECK(b.next_crossing(a, 1, t) == t);
    }
    CHECK(enumerate_crossings(a, b, 0, -1.0) ==
          std::vector<double>{5.25, 14.75, 25.25, 34.75, 45.25, 54.75, 65.25, 74.75, 85.25, 94.75});
}

TEST_CASE("piecewise-linear flightplans with different key times match dense sampling", "[kinetic][flightplan]")
{
    PCCD::Random_engine rng(23);
    for (int trial = 0; trial < 300; ++trial) {
        auto make = [&]() {
            std::vector<double> ts;
            std::vector<Eigen::Vector3d> ps;
            double t = PCCD::uniform_real(rng, -0.5, 0.5);
            for (int k = 0; k < 12; ++k) {
                ts.push_back(t);
                ps.push_back(random_vector(rng, 1));
                t += PCCD::uniform_real(rng, 0.1, 1.0);
            }
            return Piecewise_linear_flightplan(ts, ps);
        };
        const auto a = make();
        const auto b = make();
        const int axis = int(PCCD::uniform_index(rng, 3));
        const std::vector<double> got = enumerate_crossings(a, b, axis, -1.0);
        // Truth: sign changes on the merged key times (d is linear in between).
        std::vector<double> cuts = *a.key_times();
        cuts.insert(cuts.end(), b.key_times()->begin(), b.key_times()->end());
        cuts.push_back(-1.0);
        std::sort(cuts.begin(), cuts.end());
        std::vector<double> expected;
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            if (cuts[k] < -1.0) continue;
            const double d0 = a.coordinate(axis, cuts[k]) - b.coordinate(axis, cuts[k]);
            const double d1 = a.coordinate(axis, cuts[k + 1]) - b.coordinate(axis, cuts[k + 1]);
            if ((d0 < 0) != (d1 < 0)) expected.push_back(cuts[k] + (cuts[k + 1] - cuts[k]) * d0 / (d0 - d1));
        }
        if (!expected.empty() && expected.front() <= -1.0) expected.erase(expected.begin());
        REQUIRE(got.size() == expected.size());
        for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-9));
    }
}

TEST_CASE("cubic flightplans: simple and double roots", "[kinetic][flightplan]")
{
    using C = Polynomial_flightplan::Coefficients;
    const Eigen::Vector3d z = Eigen::Vector3d::Zero();
    auto x_only = [&](double c0, double c1, double c2, double c3) {
        return Polynomial_flightplan(C{Eigen::Vector3d(c0, 0, 0), Eigen::Vector3d(c1, 0, 0), Eigen::Vector3d(c2, 0, 0),
                                       Eigen::Vector3d(c3, 0, 0)});
    };
    const Polynomial_flightplan zero(C{z, z, z, z});
    // (t - 1)(t - 2)(t - 4) = t^3 - 7 t^2 + 14 t - 8
    const auto a = x_only(-8, 14, -7, 1);
    CHECK(a.next_crossing(zero, 0, 0.0) == 0.0);
    CHECK(a.next_crossing(zero, 0, 1.5) == Approx(2.0).margin(1e-14));
    CHECK(zero.next_crossing(a, 0, 0.0) == Approx(1.0).margin(1e-14));
    CHECK(zero.next_crossing(a, 0, 2.5) == Approx(4.0).margin(1e-14));
    CHECK(a.next_crossing(zero, 0, 4.5) == inf);
    CHECK(enumerate_crossings(a, zero, 0, -10.0).size() == 3);
    // (t - 1)^2 (t - 3) = t^3 - 5 t^2 + 7 t - 3: touches 0 at t = 1, crosses at t = 3.
    const auto touching = x_only(-3, 7, -5, 1);
    CHECK(zero.next_crossing(touching, 0, -5.0) == Approx(3.0).margin(1e-12));
    CHECK(touching.next_crossing(zero, 0, 3.5) == inf);
    // A pure double root is no crossing at all: (t - 2)^2.
    const auto parabola = x_only(4, -4, 1, 0);
    CHECK(parabola.next_crossing(zero, 0, -10.0) == inf);
}

TEST_CASE("random cubics agree with Eigen's polynomial solver", "[kinetic][flightplan]")
{
    PCCD::Random_engine rng(77);
    int crossings = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double origin_a = PCCD::uniform_real(rng, -1, 1), origin_b = PCCD::uniform_real(rng, -1, 1);
        Polynomial_flightplan::Coefficients ca, cb;
        for (auto& c : ca) c = random_vector(rng, 2);
        for (auto& c : cb) c = random_vector(rng, 2);
        const Polynomial_flightplan a(ca, origin_a), b(cb, origin_b);
        const int axis = int(PCCD::uniform_index(rng, 3));
        // Truth: d(t) = a(t) - b(t) in monomials of t, real roots of odd multiplicity in (-3, 3).
        Eigen::Vector4d d = Eigen::Vector4d::Zero();
        auto add = [&](const Polynomial_flightplan::Coefficients& c, double o, double sign) {
            const double p0 = c[0][axis], p1 = c[1][axis], p2 = c[2][axis], p3 = c[3][axis];
            d[0] += sign * (p0 - p1 * o + p2 * o * o - p3 * o * o * o);
            d[1] += sign * (p1 - 2 * p2 * o + 3 * p3 * o * o);
            d[2] += sign * (p2 - 3 * p3 * o);
            d[3] += sign * p3;
        };
        add(ca, origin_a, 1.0);
        add(cb, origin_b, -1.0);
        Eigen::PolynomialSolver<double, 3> solver(d);
        std::vector<double> roots;
        solver.realRoots(roots, 1e-10);
        std::sort(roots.begin(), roots.end());
        std::vector<double> expected;
        for (double r : roots)
            if (r > -3 && r < 3) {
                const double before = Eigen::poly_eval(d, r - 1e-6), after = Eigen::poly_eval(d, r + 1e-6);
                if ((before < 0) != (after < 0)) expected.push_back(r);
            }
        std::vector<double> got = enumerate_crossings(a, b, axis, -3.0);
        got.erase(std::remove_if(got.begin(), got.end(), [](double s) { return s >= 3.0; }), got.end());
        REQUIRE(got.size() == expected.size());
        for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-7));
        crossings += int(got.size());
    }
    CHECK(crossings > 1000);
}

TEST_CASE("Hermite key frames: C1 pieces, crossings match dense sampling", "[kinetic][flightplan]")
{
    PCCD::Random_engine rng(31);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<double> ts;
        std::vector<Eigen::Vector3d> pa, va, pb, vb;
        for (int k = 0; k < 8; ++k) {
            ts.push_back(0.5 * k);
            pa.push_back(random_vector(rng, 1));
            va.push_back(random_vector(rng, 1));
            pb.push_back(random_vector(rng, 1));
            vb.push_back(random_vector(rng, 1));
        }
        const auto a = Polynomial_flightplan::hermite(ts, pa, va);
        const auto b = Polynomial_flightplan::hermite(ts, pb, vb);
        for (std::size_t k = 0; k < ts.size(); ++k) CHECK((a.position(ts[k]) - pa[k]).norm() < 1e-12);
        const int axis = int(PCCD::uniform_index(rng, 3));
        const std::vector<double> got = enumerate_crossings(a, b, axis, -1.0);
        std::vector<double> expected;
        const int samples = 200000;
        double previous = a.coordinate(axis, -1.0) - b.coordinate(axis, -1.0);
        for (int i = 1; i <= samples; ++i) {
            const double t = -1.0 + 6.0 * i / samples;
            const double d = a.coordinate(axis, t) - b.coordinate(axis, t);
            if ((d < 0) != (previous < 0)) expected.push_back(t);
            previous = d;
        }
        REQUIRE(got.size() == expected.size());
        for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(6.0 / samples));
    }
}

TEST_CASE("from_pieces reproduces the other models", "[kinetic][flightplan]")
{
    const Piecewise_linear_flightplan pl(std::vector<double>{0, 1, 3},
                                         {Eigen::Vector3d(0, 1, 2), Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(4, 4, 4)});
    const auto poly = Polynomial_flightplan::from_pieces(pl);
    const Linear_flightplan lin({1, 2, 3}, {-1, 0, 1}, 0.5);
    const auto poly_lin = Polynomial_flightplan::from_pieces(lin);
    for (double t = -2; t < 5; t += 0.125) {
        CHECK(poly.position(t) == pl.position(t));
        CHECK(poly_lin.position(t) == lin.position(t));
    }
}

TEST_CASE("invalid flightplans are rejected with a message", "[kinetic][flightplan]")
{
    const std::vector<Eigen::Vector3d> two{Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()};
    CHECK_THROWS_AS(Piecewise_linear_flightplan(std::vector<double>{1, 1}, two), PCCD::Invalid_input);
    CHECK_THROWS_AS(Piecewise_linear_flightplan(std::vector<double>{0}, two), PCCD::Invalid_input);
    CHECK_THROWS_AS(Piecewise_linear_flightplan(std::vector<double>{}, {}), PCCD::Invalid_input);
    CHECK_THROWS_WITH(Piecewise_linear_flightplan(std::vector<double>{0, 1},
                                                  {Eigen::Vector3d::Zero(), Eigen::Vector3d(NAN, 0, 0)}),
                      Catch::Contains("key position 1"));
    CHECK_THROWS_AS(Linear_flightplan({0, 0, 0}, {INFINITY, 0, 0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(Polynomial_flightplan::hermite({0, 1}, two, {Eigen::Vector3d::Zero()}), PCCD::Invalid_input);
    const Eigen::Vector3d z = Eigen::Vector3d::Zero();
    CHECK_THROWS_WITH(Polynomial_flightplan({z, z, Eigen::Vector3d(0, NAN, 0), z}), Catch::Contains("c2"));
}

TEST_CASE("Cubic: evaluation, Taylor shift, difference and degree against direct polynomials", "[kinetic][flightplan]")
{
    PCCD::Random_engine engine(17);
    for (int k = 0; k < 200; ++k) {
        PCCD::Cubic p;
        for (double& c : p.c) c = PCCD::uniform_real(engine, -3.0, 3.0);
        const double u = PCCD::uniform_real(engine, -2.0, 2.0), delta = PCCD::uniform_real(engine, -2.0, 2.0);
        const double direct = p.c[0] + p.c[1] * u + p.c[2] * u * u + p.c[3] * u * u * u;
        CHECK(p(u) == Approx(direct).margin(1e-12));
        // The shifted cubic at v equals the original at v + delta.
        CHECK(p.shifted(delta)(u) == Approx(p(u + delta)).margin(1e-9));
        PCCD::Cubic q;
        for (double& c : q.c) c = PCCD::uniform_real(engine, -3.0, 3.0);
        CHECK((p - q)(u) == Approx(p(u) - q(u)).margin(1e-12));
    }
    PCCD::Cubic line;
    line.c = {1.0, 2.0, 0.0, 0.0};
    CHECK(line.degree() == 1);
    CHECK(PCCD::Cubic{}.degree() == -1);
    CHECK((line - line).degree() == -1);
    CHECK(line.shifted(0.0).c == line.c);
}
