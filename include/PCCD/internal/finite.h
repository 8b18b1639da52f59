// PCCD/internal/finite.h -- trap-free finiteness tests for Eigen objects. Eigen's allFinite()
// computes x - x == 0 on every coefficient, which raises the FE_INVALID flag (and traps, when
// floating-point exceptions are enabled as in the Debug test builds) on the very infinities it is
// meant to detect. Validation of caller input therefore uses all_finite() instead: std::isfinite is
// a classification, not arithmetic, and never raises a floating-point exception.
#pragma once

#include <cmath>

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

} // namespace PCCD::internal
