// PCCD/Rigid_transform_3.h -- a validated rigid motion x -> R x + t (R a proper rotation), the pose
// type taken by the collision queries and produced by the benchmark pose generator
// (doc/algorithms.md, "Benchmark procedure": T_A = [R_A | 0], T_B = [R_B | (d, 0, 0)]).
//
// Every constructor checks that its input really is rigid: a scaling, shear, reflection or a NaN /
// infinite entry throws PCCD::Invalid_input naming the problem. An accepted rotation is replaced by
// its nearest rotation matrix (the orthogonal polar factor), so inverse() == transpose is exact to
// rounding and long compositions stay rigid. CGAL's Aff_transformation_3 (and any type exposing
// `m(i, j)`) converts without this header including CGAL.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <PCCD/Error.h>
#include <PCCD/internal/finite.h>

namespace PCCD {
namespace internal {

/// Concept helper: a number that converts to `FT` directly, or through an ADL-found `to_double`
/// (CGAL's exact number types such as Lazy_exact_nt, Gmpq).
template <class N, class FT>
concept Convertible_number = std::convertible_to<N, FT> || requires(const N& n) {
    { to_double(n) } -> std::convertible_to<double>;
};

/// Concept helper: an affine transformation in CGAL's style, whose matrix entries `t.m(i, j)`
/// (row i in 0..2, column j in 0..3, column 3 the translation) convert to `FT`.
template <class T, class FT>
concept Affine_matrix_entries = requires(const T& t, int i, int j) {
    { t.m(i, j) } -> Convertible_number<FT>;
};

template <class FT, class N>
FT to_floating_point(const N& value)
{
    if constexpr (std::convertible_to<N, FT>)
        return static_cast<FT>(value);
    else
        return static_cast<FT>(to_double(value));
}

} // namespace internal

/// A rigid motion of 3-space, x -> R x + t, with R a proper rotation (R^T R = I, det R = +1).
///
/// \tparam FT_ `float` or `double`.
///
/// Validation (the one rule of the library, the `pccd` tool and the Python module): the rotation
/// part is accepted when every entry of R^T R - I is at most `tolerance` in absolute value (default
/// `default_tolerance`, 1e-5 for double) and det R > 0; it is then stored as its nearest rotation
/// matrix (orthogonal polar factor U V^T of the SVD R = U S V^T), which differs from the input by at
/// most about `tolerance`. Otherwise the constructor throws Invalid_input saying whether the matrix
/// scales, shears or reflects, or which entry is NaN or infinite, with the offending values in full
/// (shortest round-trip digits). A matrix further from a rotation can be repaired on purpose with
/// orthonormalize(), which says how far it moved it.
///
/// Immutable value type; all member functions are const and safe to call concurrently.
template <std::floating_point FT_ = double>
class Rigid_transform_3 {
public:
    using FT = FT_;
    using Matrix_3 = Eigen::Matrix<FT, 3, 3>;
    using Vector_3 = Eigen::Matrix<FT, 3, 1>;
    using Matrix_3x4 = Eigen::Matrix<FT, 3, 4>;
    using Coordinates = Eigen::Matrix<FT, 3, Eigen::Dynamic>;

    /// Default tolerance on the entries of R^T R - I: 1e-5 for double, so that a rotation printed
    /// with 6 decimals always passes (rounding each entry by at most 5e-7 changes an entry of R^T R
    /// by at most 2 sqrt(3) 5e-7 + 3 (5e-7)^2 < 1.8e-6), while one printed with 4 decimals may not;
    /// 100 machine epsilons (about 1.2e-5) for float.
    static constexpr FT default_tolerance = std::max(FT(1e-5), FT(100) * std::numeric_limits<FT>::epsilon());

    /// \name Construction
    /// @{

    /// The identity.
    Rigid_transform_3() : m_rotation(Matrix_3::Identity()), m_translation(Vector_3::Zero()) {}

    /// From a rotation matrix and a translation vector (any Eigen expressions, any scalar type).
    /// \throws Invalid_input if `rotation` is not 3 x 3 or `translation` not 3 x 1, if an entry is
    ///         NaN or infinite, if `rotation` is not a proper rotation within `tolerance` (scaling,
    ///         shear, reflection), or if `tolerance` is not in [0, 0.5).
    /// Complexity: O(1) (one 3 x 3 SVD).
    template <class Rotation, class Translation>
    Rigid_transform_3(const Eigen::MatrixBase<Rotation>& rotation, const Eigen::MatrixBase<Translation>& translation,
                      FT tolerance = default_tolerance)
    {
        if (rotation.rows() != 3 || rotation.cols() != 3)
            throw Invalid_input(internal::concat("rigid transform: the rotation is ", rotation.rows(), " x ",
                                                 rotation.cols(), ", not 3 x 3"));
        if (translation.rows() != 3 || translation.cols() != 1)
            throw Invalid_input(internal::concat("rigid transform: the translation is ", translation.rows(), " x ",
                                                 translation.cols(), ", not 3 x 1"));
        const auto r = rotation.derived().eval();
        const auto t = translation.derived().eval();
        Matrix_3x4 m;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) m(i, j) = narrowed(r.coeff(i, j), i, j);
            m(i, 3) = narrowed(t.coeff(i, 0), i, 3);
        }
        set_checked(m, tolerance);
    }

    /// From the 3 x 4 matrix [R | t] given row by row: {r00, r01, r02, t0, r10, ..., t2}.
    /// \throws Invalid_input as the constructor from Eigen matrices.
    explicit Rigid_transform_3(const std::array<FT, 12>& row_major_3x4, FT tolerance = default_tolerance)
    {
        set_checked(Eigen::Map<const Eigen::Matrix<FT, 3, 4, Eigen::RowMajor>>(row_major_3x4.data()), tolerance);
    }

    /// From an affine transformation exposing `m(i, j)` for rows 0..2 and columns 0..3 (column 3 is
    /// the translation), such as CGAL::Aff_transformation_3<K> for any kernel K; exact number types
    /// are converted with their `to_double`. The homogeneous last row is not read.
    /// \throws Invalid_input as the constructor from Eigen matrices.
    template <class Affine_transformation>
        requires internal::Affine_matrix_entries<Affine_transformation, FT_>
    explicit Rigid_transform_3(const Affine_transformation& transformation, FT tolerance = default_tolerance)
    {
        Matrix_3x4 m;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) m(i, j) = narrowed(internal::to_floating_point<double>(transformation.m(i, j)), i, j);
        set_checked(m, tolerance);
    }

    /// The identity.
    static Rigid_transform_3 identity() { return Rigid_transform_3(); }

private:
    /// Entry (i, j) of [R | t] as FT: a finite value of a wider type beyond FT's range (a double
    /// given to a float transform) is rejected by name instead of turning into infinity.
    template <class T>
    static FT narrowed(const T& value, int i, int j)
    {
        if (internal::overflows_on_conversion<FT>(value))
            throw Invalid_input(internal::concat("rigid transform: ", j == 3 ? "translation" : "rotation",
                                                 " entry (", i, ", ", j, ") = ", value, " is beyond the range of ",
                                                 sizeof(FT) == 4 ? "float" : "the number type"));
        return static_cast<FT>(value);
    }

public:
    /// @}

    /// \name Access
    /// @{
    /// The rotation R (orthonormal to rounding, det +1).
    const Matrix_3& rotation() const { return m_rotation; }
    /// The translation t.
    const Vector_3& translation() const { return m_translation; }
    /// The 3 x 4 matrix [R | t].
    Matrix_3x4 matrix() const
    {
        Matrix_3x4 m;
        m << m_rotation, m_translation;
        return m;
    }
    /// @}

    /// \name Application (O(1) per point)
    /// @{
    /// R p + t.
    template <class Derived>
    Vector_3 transform_point(const Eigen::MatrixBase<Derived>& p) const
    {
        return m_rotation * p.template cast<FT>() + m_translation;
    }
    /// R v (directions and normals: a rigid motion needs no inverse transpose).
    template <class Derived>
    Vector_3 transform_vector(const Eigen::MatrixBase<Derived>& v) const
    {
        return m_rotation * v.template cast<FT>();
    }
    /// R p + t for every column p of a 3 x N matrix. O(N).
    template <class Derived>
    Coordinates transform_points(const Eigen::MatrixBase<Derived>& points) const
    {
        return (m_rotation * points.template cast<FT>()).colwise() + m_translation;
    }
    /// @}

    /// \name Group operations
    /// @{
    /// The composition `a * b`: first `b`, then `a` (x -> a(b(x))).
    friend Rigid_transform_3 operator*(const Rigid_transform_3& a, const Rigid_transform_3& b)
    {
        return Rigid_transform_3(a.m_rotation * b.m_rotation, a.m_rotation * b.m_translation + a.m_translation,
                                 Unchecked{});
    }
    /// The inverse motion x -> R^T (x - t).
    Rigid_transform_3 inverse() const
    {
        const Matrix_3 rt = m_rotation.transpose();
        return Rigid_transform_3(rt, -(rt * m_translation), Unchecked{});
    }
    /// @}

    /// `value` with as many digits as it takes to read it back exactly (shortest round trip), for
    /// error messages: 1.0000000000010001, not 1.
    static std::string full_digits(FT value)
    {
        char text[64];
        const auto end = std::to_chars(text, text + sizeof text, value).ptr;
        return std::string(text, end);
    }

private:
    struct Unchecked {};
    Rigid_transform_3(const Matrix_3& rotation, const Vector_3& translation, Unchecked)
        : m_rotation(rotation), m_translation(translation)
    {
    }

    template <class Derived>
    void set_checked(const Eigen::MatrixBase<Derived>& m, FT tolerance)
    {
        if (!(std::isgreaterequal(tolerance, FT(0)) && std::isless(tolerance, FT(0.5))))
            throw Invalid_input(internal::concat("rigid transform: tolerance ", full_digits(tolerance),
                                                 " is not in [0, 0.5)"));
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j)
                if (!std::isfinite(m(i, j)))
                    throw Invalid_input(internal::concat("rigid transform: ", j < 3 ? "rotation" : "translation",
                                                         " entry (", i, ", ", j, ") is ", full_digits(m(i, j))));
        // Within a tolerance below 0.5 every column of a rotation has squared length below 1.5, so no
        // entry exceeds 2 in absolute value; rejecting larger entries here also keeps R^T R below
        // from overflowing (a trap in builds with floating-point exceptions enabled).
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (std::abs(m(i, j)) > FT(2))
                    throw Invalid_input(internal::concat("rigid transform: the rotation part scales: entry (", i, ", ",
                                                         j, ") is ", full_digits(m(i, j)), ", beyond any rotation's"));
        const Matrix_3 r = m.template leftCols<3>();
        const Matrix_3 gram = r.transpose() * r;
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j)
                if (std::abs(gram(i, j)) > tolerance)
                    throw Invalid_input(internal::concat("rigid transform: the rotation part shears: columns ", i,
                                                         " and ", j, " have dot product ", full_digits(gram(i, j)),
                                                         " (tolerance ", full_digits(tolerance), ")"));
        for (int i = 0; i < 3; ++i)
            if (std::abs(gram(i, i) - FT(1)) > tolerance)
                throw Invalid_input(internal::concat("rigid transform: the rotation part scales: column ", i,
                                                     " has length ", full_digits(std::sqrt(gram(i, i))),
                                                     ", not 1 (its square is off by ", full_digits(gram(i, i) - FT(1)),
                                                     ", tolerance ", full_digits(tolerance), ")"));
        const FT det = r.determinant();
        if (det < FT(0))
            throw Invalid_input(internal::concat("rigid transform: the rotation part is a reflection (determinant ",
                                                 full_digits(det), ")"));
        // Polar factor from the SVD, then one Newton-Schulz step Q <- Q (3 I - Q^T Q) / 2, which brings
        // the SVD's orthogonality error (a few 1e-15 for double) down to rounding level.
        const Eigen::JacobiSVD<Matrix_3> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Matrix_3 polar = svd.matrixU() * svd.matrixV().transpose();
        m_rotation = FT(1.5) * polar - FT(0.5) * polar * (polar.transpose() * polar);
        m_translation = m.col(3);
    }

    Matrix_3 m_rotation;
    Vector_3 m_translation;
};

/// What orthonormalize() returns: the rigid transform and how far its rotation moved from the
/// matrix given (the largest absolute change of an entry).
template <std::floating_point FT>
struct Orthonormalized_transform {
    Rigid_transform_3<FT> transform;
    FT moved = 0;
};

/// Opt-in repair of a pose whose rotation part is not quite a rotation (rounded when printed,
/// drifted by long products): the rigid transform with the same translation whose rotation is the
/// nearest rotation matrix to the 3 x 3 part of `row_major_3x4` in the Frobenius norm (its
/// orthogonal polar factor, from the SVD), however far that is, and the largest change of an entry
/// it took. The constructors refuse matrices beyond their tolerance instead; compare `moved` with
/// what the source's rounding explains before trusting the result.
/// 	hrows Invalid_input if an entry is NaN or infinite, or if the 3 x 3 part is singular or has a
///         negative determinant (no nearest proper rotation then: a reflection is not repaired).
template <std::floating_point FT>
Orthonormalized_transform<FT> orthonormalize(const std::array<FT, 12>& row_major_3x4)
{
    using Matrix_3 = Eigen::Matrix<FT, 3, 3>;
    const Eigen::Map<const Eigen::Matrix<FT, 3, 4, Eigen::RowMajor>> m(row_major_3x4.data());
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m(i, j)))
                throw Invalid_input(internal::concat("orthonormalize: ", j < 3 ? "rotation" : "translation", " entry (",
                                                     i, ", ", j, ") is ", Rigid_transform_3<FT>::full_digits(m(i, j))));
    const Matrix_3 r = m.template leftCols<3>();
    const Eigen::JacobiSVD<Matrix_3> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const FT largest = svd.singularValues()(0);
    const FT smallest = svd.singularValues()(2);
    if (!(smallest > largest * FT(16) * std::numeric_limits<FT>::epsilon()))
        throw Invalid_input(internal::concat("orthonormalize: the rotation part is singular (singular values ",
                                             Rigid_transform_3<FT>::full_digits(largest), " to ",
                                             Rigid_transform_3<FT>::full_digits(smallest), "): no nearest rotation"));
    const FT det = r.determinant();
    if (det < FT(0))
        throw Invalid_input(internal::concat("orthonormalize: the rotation part is a reflection (determinant ",
                                             Rigid_transform_3<FT>::full_digits(det), "): no nearest proper rotation"));
    Matrix_3 polar = svd.matrixU() * svd.matrixV().transpose();
    polar = FT(1.5) * polar - FT(0.5) * polar * (polar.transpose() * polar);
    std::array<FT, 12> entries = row_major_3x4;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) entries[std::size_t(4 * i + j)] = polar(i, j);
    return {Rigid_transform_3<FT>(entries), (polar - r).cwiseAbs().maxCoeff()};
}

} // namespace PCCD
