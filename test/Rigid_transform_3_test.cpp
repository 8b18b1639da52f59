// Rigid_transform_3 (PCCD/Rigid_transform_3.h): construction, application, composition and
// inverse against plain matrix algebra; the rotation tolerance; rejected matrices; conversion from
// CGAL's affine transformations.
#include <PCCD/Rigid_transform_3.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <Eigen/Geometry>

using Eigen::Vector3d;

namespace {

Eigen::Matrix3d some_rotation()
{
    return Eigen::AngleAxisd(0.7, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
}

} // namespace

TEST_CASE("Rigid_transform_3: construction, application, composition and inverse", "[sampling][transform]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(0.5, -1.0, 2.0);
    const PCCD::Rigid_transform_3<> a(r, t);
    CHECK((a.rotation() - r).norm() < 1e-15);
    CHECK(a.translation() == t);
    const Vector3d x(0.3, 0.2, -0.7);
    CHECK((a.transform_point(x) - (r * x + t)).norm() < 1e-15);
    CHECK((a.transform_vector(x) - r * x).norm() < 1e-15);

    // From 12 numbers, row-major [R | t].
    std::array<double, 12> rows{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) rows[4 * i + j] = r(i, j);
        rows[4 * i + 3] = t[i];
    }
    const PCCD::Rigid_transform_3<> from_rows(rows);
    CHECK((from_rows.matrix() - a.matrix()).norm() == 0.0);
    const PCCD::Rigid_transform_3<> shift({1, 0, 0, 4, 0, 1, 0, 5, 0, 0, 1, 6});
    CHECK(shift.transform_point(Vector3d(1, 1, 1)) == Vector3d(5, 6, 7));

    // Composition: (b * a)(x) = b(a(x)); inverse.
    const PCCD::Rigid_transform_3<> b(Eigen::AngleAxisd(-1.9, Vector3d::UnitZ()).toRotationMatrix(), Vector3d(3, 0, 1));
    CHECK(((b * a).transform_point(x) - b.transform_point(a.transform_point(x))).norm() < 1e-14);
    CHECK(((a * a.inverse()).matrix() - PCCD::Rigid_transform_3<>::identity().matrix()).norm() < 1e-14);
    CHECK(((a.inverse() * a).transform_point(x) - x).norm() < 1e-14);
    CHECK((a.inverse().inverse().matrix() - a.matrix()).norm() < 1e-14);
    CHECK(PCCD::Rigid_transform_3<>().matrix() == PCCD::Rigid_transform_3<>::identity().matrix());

    Eigen::Matrix3Xd many(3, 20);
    for (Eigen::Index i = 0; i < many.cols(); ++i) many.col(i) << 0.1 * double(i), 1.0 - 0.3 * double(i), 2.0;
    const Eigen::Matrix3Xd moved = a.transform_points(many);
    for (Eigen::Index i = 0; i < many.cols(); ++i) CHECK((moved.col(i) - a.transform_point(many.col(i))).norm() < 1e-15);

    // float.
    const PCCD::Rigid_transform_3<float> af(r.cast<float>(), t.cast<float>());
    CHECK((af.transform_point(x.cast<float>()) - (r * x + t).cast<float>()).norm() < 1e-5f);
}

TEST_CASE("Rigid_transform_3: accepts rotations up to the tolerance and projects them", "[sampling][transform]")
{
    const Eigen::Matrix3d r = some_rotation();
    Eigen::Matrix3d perturbed = r;
    perturbed(0, 1) += 1e-8;
    perturbed(2, 2) -= 2e-8;
    const PCCD::Rigid_transform_3<> a(perturbed, Vector3d::Zero());
    // Orthonormal and proper to a few ulps (the polar factor), where the input was off by 1e-8.
    CHECK((a.rotation().transpose() * a.rotation() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 2e-15);
    CHECK(std::abs(a.rotation().determinant() - 1.0) < 2e-15);
    CHECK((a.rotation() - r).norm() < 1e-7);
    perturbed(0, 1) += 1e-4;
    CHECK_THROWS_AS(PCCD::Rigid_transform_3<>(perturbed, Vector3d::Zero()), PCCD::Invalid_input);
    CHECK_NOTHROW(PCCD::Rigid_transform_3<>(perturbed, Vector3d::Zero(), 1e-3)); // explicit looser tolerance
}

TEST_CASE("Rigid_transform_3 rejects scaling, shear, reflection and non-finite entries", "[sampling][transform][errors]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(1, 2, 3);
    using T = PCCD::Rigid_transform_3<>;
    CHECK_THROWS_WITH(T(1.01 * r, t), Catch::Contains("scales"));
    CHECK_THROWS_WITH(T(Eigen::Matrix3d(Eigen::Vector3d(1, 1, 2).asDiagonal()), t), Catch::Contains("scales"));
    Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
    shear(0, 1) = 0.1;
    CHECK_THROWS_WITH(T(shear, t), Catch::Contains("shears"));
    CHECK_THROWS_WITH(T(Eigen::Matrix3d(Eigen::Vector3d(1, 1, -1).asDiagonal()), t), Catch::Contains("reflection"));
    CHECK_THROWS_WITH(T(-r, t), Catch::Contains("reflection"));
    Eigen::Matrix3d with_nan = r;
    with_nan(1, 2) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(T(with_nan, t), Catch::Contains("rotation entry (1, 2)"));
    CHECK_THROWS_WITH(T(r, Vector3d(0, std::numeric_limits<double>::infinity(), 0)),
                      Catch::Contains("translation entry (1, 3)"));
    CHECK_THROWS_WITH(T(Eigen::MatrixXd::Identity(2, 2), t), Catch::Contains("not 3 x 3"));
    CHECK_THROWS_WITH(T(r, t, -1.0), Catch::Contains("tolerance"));
    CHECK_THROWS_AS(T({2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}), PCCD::Invalid_input);
    static_assert(!std::is_constructible_v<T, int>);
    static_assert(!std::is_constructible_v<T, Eigen::Matrix3d>);
}

TEST_CASE("Rigid_transform_3 from CGAL::Aff_transformation_3 (inexact and exact kernels)", "[sampling][transform][cgal]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(0.25, -0.5, 4.0);
    using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
    const CGAL::Aff_transformation_3<Epick> rigid(r(0, 0), r(0, 1), r(0, 2), t[0], r(1, 0), r(1, 1), r(1, 2), t[1],
                                                  r(2, 0), r(2, 1), r(2, 2), t[2], 1.0);
    const PCCD::Rigid_transform_3<> a(rigid);
    CHECK((a.matrix() - PCCD::Rigid_transform_3<>(r, t).matrix()).norm() < 1e-15);
    const Epick::Point_3 p(0.3, 0.2, -0.7);
    const Epick::Point_3 q = rigid.transform(p);
    CHECK((a.transform_point(Vector3d(0.3, 0.2, -0.7)) - Vector3d(q.x(), q.y(), q.z())).norm() < 1e-14);

    CHECK_NOTHROW(PCCD::Rigid_transform_3<>(CGAL::Aff_transformation_3<Epick>(CGAL::TRANSLATION, Epick::Vector_3(1, 2, 3))));
    CHECK_THROWS_WITH(PCCD::Rigid_transform_3<>(CGAL::Aff_transformation_3<Epick>(CGAL::SCALING, 2.0)),
                      Catch::Contains("scales"));
    CHECK_THROWS_WITH(PCCD::Rigid_transform_3<>(CGAL::Aff_transformation_3<Epick>(-1, 0, 0, 0, 1, 0, 0, 0, 1)),
                      Catch::Contains("reflection"));

    // Exact kernel: entries converted with CGAL::to_double, found by ADL.
    const CGAL::Aff_transformation_3<Epeck> quarter_turn(0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0, 1);
    const PCCD::Rigid_transform_3<> b(quarter_turn);
    CHECK(b.transform_point(Vector3d(1, 0, 0)) == Vector3d(5, 1, 0));
}


namespace {

/// `r` with every entry rounded to `decimals` decimals, as a program printing it with %.6f would.
Eigen::Matrix3d rounded(const Eigen::Matrix3d& r, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    return r.unaryExpr([scale](double v) { return std::round(v * scale) / scale; });
}

std::array<double, 12> rows_of(const Eigen::Matrix3d& r, const Vector3d& t)
{
    std::array<double, 12> rows{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) rows[std::size_t(4 * i + j)] = r(i, j);
        rows[std::size_t(4 * i + 3)] = t(i);
    }
    return rows;
}

} // namespace

TEST_CASE("Rigid_transform_3: a rotation printed with 6 decimals is accepted", "[sampling][transform]")
{
    // The default tolerance (1e-5 on R^T R - I) admits every rotation rounded to 6 decimals: 200
    // random rotations (about 40 of which the former 1e-6 refused) and the worst case of the bound.
    std::uint64_t state = 12345;
    const auto uniform = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) * 0x1.0p-53;
    };
    int refused_before = 0;
    for (int k = 0; k < 200; ++k) {
        const Eigen::Quaterniond q(Eigen::Vector4d(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5, uniform() - 0.5).normalized());
        const Eigen::Matrix3d six = rounded(q.toRotationMatrix(), 6);
        CHECK_NOTHROW(PCCD::Rigid_transform_3<>(six, Vector3d::Zero()));
        if ((six.transpose() * six - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6) ++refused_before;
    }
    CHECK(refused_before > 0); // the case the former tolerance got wrong does occur in this sample
    CHECK(PCCD::Rigid_transform_3<>::default_tolerance == 1e-5);
    // Rounded to 4 decimals, a rotation is off by up to about 2e-4: refused, with the values in full.
    const Eigen::Matrix3d four = rounded(some_rotation(), 4);
    const double off = (four.transpose() * four - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (off > 1e-5) CHECK_THROWS_AS(PCCD::Rigid_transform_3<>(four, Vector3d::Zero()), PCCD::Invalid_input);
}

TEST_CASE("Rigid_transform_3: error messages print the values in full", "[sampling][transform][errors]")
{
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    r(1, 1) = 1.0000123456789; // its square is off by 2.469e-5; 6 digits would print "length 1.00001"
    try {
        PCCD::Rigid_transform_3<> t(r, Vector3d::Zero());
        FAIL("accepted");
    } catch (const PCCD::Invalid_input& e) {
        const std::string message = e.what();
        CHECK_THAT(message, Catch::Contains("column 1 has length 1.0000123456789,"));
        CHECK_THAT(message, Catch::Contains("off by 2.46915"));
        CHECK_THAT(message, Catch::Contains("tolerance 1e-05"));
        CHECK_THAT(message, !Catch::Contains("has length 1, not 1"));
    }
    CHECK(PCCD::Rigid_transform_3<>::full_digits(1.0 + 1e-12) == "1.000000000001");
    CHECK(PCCD::Rigid_transform_3<>::full_digits(0.1) == "0.1");
}

TEST_CASE("orthonormalize: the nearest rotation, and how far it moved", "[sampling][transform]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(1, 2, 3);
    // A rotation rounded to 3 decimals: refused by the constructor, repaired on request.
    const Eigen::Matrix3d three = rounded(r, 3);
    CHECK_THROWS_AS(PCCD::Rigid_transform_3<>(three, t), PCCD::Invalid_input);
    const auto fixed = PCCD::orthonormalize(rows_of(three, t));
    const Eigen::Matrix3d q = fixed.transform.rotation();
    CHECK((q.transpose() * q - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 2e-15);
    CHECK(std::abs(q.determinant() - 1.0) < 2e-15);
    CHECK(fixed.transform.translation() == t);
    CHECK(fixed.moved == Approx((q - three).cwiseAbs().maxCoeff()));
    CHECK(fixed.moved > 0.0);
    CHECK(fixed.moved < 1e-3);
    CHECK((q - r).cwiseAbs().maxCoeff() < 1e-3);
    // The nearest rotation: no other rotation nearby is closer in the Frobenius norm.
    for (int axis = 0; axis < 3; ++axis)
        for (const double angle : {-1e-4, 1e-4}) {
            const Eigen::Matrix3d other = q * Eigen::AngleAxisd(angle, Vector3d::Unit(axis)).toRotationMatrix();
            CHECK((other - three).norm() > (q - three).norm());
        }
    // An exact rotation does not move (beyond rounding).
    CHECK(PCCD::orthonormalize(rows_of(r, t)).moved < 1e-15);
    // Reflections, singular matrices and NaN are refused.
    CHECK_THROWS_WITH(PCCD::orthonormalize(rows_of(-r, t)), Catch::Contains("reflection"));
    Eigen::Matrix3d flat = r;
    flat.col(2).setZero();
    CHECK_THROWS_WITH(PCCD::orthonormalize(rows_of(flat, t)), Catch::Contains("singular"));
    Eigen::Matrix3d with_nan = r;
    with_nan(0, 0) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(PCCD::orthonormalize(rows_of(with_nan, t)), Catch::Contains("rotation entry (0, 0) is nan"));
}
