// test/Hierarchy/hierarchy_test_helpers.h -- random clouds, reaches and poses for the tests of the
// point cloud hierarchy and its traversals.
#pragma once

#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/testing/pose_generator.h>

#include <Eigen/Core>

#include <cstdint>

namespace pccd_test {

/// n points uniform in [-1, 1]^2 x [-flat, flat].
inline Eigen::Matrix3Xd hierarchy_points(std::size_t n, std::uint64_t seed, double flat = 1.0)
{
    PCCD::Random_engine engine(seed);
    Eigen::Matrix3Xd p(3, static_cast<Eigen::Index>(n));
    for (Eigen::Index i = 0; i < p.cols(); ++i)
        p.col(i) = Eigen::Vector3d(PCCD::uniform_real(engine, -1, 1), PCCD::uniform_real(engine, -1, 1),
                                   flat * PCCD::uniform_real(engine, -1, 1));
    return p;
}

/// n reaches uniform in [low, high].
inline Eigen::VectorXd hierarchy_reaches(std::size_t n, std::uint64_t seed, double low, double high)
{
    PCCD::Random_engine engine(seed);
    Eigen::VectorXd r(static_cast<Eigen::Index>(n));
    for (Eigen::Index i = 0; i < r.size(); ++i) r(i) = PCCD::uniform_real(engine, low, high);
    return r;
}

/// A uniformly random rotation and a translation uniform in [-shift, shift]^3.
inline PCCD::Rigid_transform_3<double> hierarchy_pose(std::uint64_t seed, double shift)
{
    PCCD::Random_engine engine(seed);
    const Eigen::Matrix3d r = PCCD::testing::uniform_random_rotation(engine);
    const Eigen::Vector3d t(PCCD::uniform_real(engine, -shift, shift), PCCD::uniform_real(engine, -shift, shift),
                            PCCD::uniform_real(engine, -shift, shift));
    return PCCD::Rigid_transform_3<double>(r, t);
}

} // namespace pccd_test
