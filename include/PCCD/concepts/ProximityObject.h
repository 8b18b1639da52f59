// PCCD/concepts/ProximityObject.h -- concept of the objects the proximity queries (distance,
// penetration depth, contacts, clearance; doc/manual/proximity.md) work on: a CollisionObject that
// also exposes its points' oriented normals, which tell inside from outside where a point lies
// deeper in the other object than its surface is defined (doc/algorithms.md "Proximity queries").
#pragma once

#include <concepts>

#include <Eigen/Core>

#include <PCCD/concepts/CollisionObject.h>

namespace PCCD {

/// \concept ProximityObject
/// A CollisionObject whose oriented point normals can be read: for `const O& o`,
/// `o.normals()` is a 3 x N `Eigen::Matrix3Xd` (column i the unit normal of point i, pointing out
/// of the object; a zero column for a point without a normal), held by the object.
/// Models: PCCD::Point_cloud_object<K>, PCCD::Deforming_point_cloud_object<K> and
/// PCCD::Euclidean_point_cloud_object<K> for every kernel K.
template <class O>
concept ProximityObject = CollisionObject<O> && requires(const O& o) {
    { o.normals() } -> std::convertible_to<const Eigen::Matrix3Xd&>;
};

} // namespace PCCD
