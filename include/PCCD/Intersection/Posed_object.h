// PCCD/Intersection/Posed_object.h -- one object of a query with its pose (local <-> world maps
// and the object's scalar properties), as the leaf intersector policies receive it
// (doc/manual/intersection.md, "Leaf intersectors"; the LeafIntersector concept).
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// One object of a query with its pose: evaluations of its surface at world or local points, with
/// the evaluation counted.
template <class Object>
struct Posed_object {
    const Object* object;
    Rigid_transform_3<double> to_world;
    Rigid_transform_3<double> from_world;

    Posed_object(const Object& o, const Rigid_transform_3<double>& pose)
        : object(&o), to_world(pose), from_world(pose.inverse())
    {
    }
    /// Local position of cloud point i.
    Eigen::Vector3d position(std::uint32_t i) const { return object->cloud().position(i).template cast<double>(); }
    std::size_t size() const { return object->size(); }
    double sampling_radius() const { return object->sampling_radius(); }
    double noise_estimate() const { return double(object->noise_estimate()); }
    double support_radius() const { return object->surface().support_radius(); }
};

} // namespace PCCD
