// PCCD/internal/finite.h -- trap-free finiteness tests for Eigen objects. Eigen's allFinite()
// computes x - x == 0 on every coefficient, which raises the FE_INVALID flag (and traps, when
// floating-point exceptions are enabled as in the Debug test builds) on the very infinities it is
// meant to detect. Validation of caller input therefore uses all_finite() instead: std::isfinite is
// a classification, not arithmetic, and never raises a floating-point exception. Also: whether a
// conversion to a narrower floating-point type would overflow.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

namespace PCCD::internal {

/// True when every coefficient of `m` is neither NaN nor infinite (true for an empty `m`).
/// Raises no floating-point exception. Complexity: O(rows * cols).
template <class Derived>
bool all_finite(const Eigen::DenseBase<Derived>& m)
{
    const auto& e = m.derived().eval();
    for (Eigen::Index j = 0; j < e.cols(); ++j)
        for (Eigen::Index i = 0; i < e.rows(); ++i)
            if (!std::isfinite(e.coeff(i, j))) return false;
    return true;
}

/// True when `value`, of an arithmetic type wider than FT, is finite but beyond FT's range, so
/// converting it would overflow to infinity (raising FE_OVERFLOW); false for any other type.
/// Raises no floating-point exception.
template <class FT, class T>
bool overflows_on_conversion(const T& value)
{
    if constexpr (std::is_arithmetic_v<T> && (sizeof(T) > sizeof(FT)))
        return std::isfinite(value) && std::isgreater(std::fabs(value), T(std::numeric_limits<FT>::max()));
    else
        return false;
}

} // namespace PCCD::internal
