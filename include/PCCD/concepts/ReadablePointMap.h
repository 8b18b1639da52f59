// PCCD/concepts/ReadablePointMap.h -- concept of the property maps that give the point of an item.
// Boost.PropertyMap protocol: `get(map, item)` found by argument-dependent lookup.
#pragma once

#include <type_traits>

#include <PCCD/Point_traits.h>

namespace PCCD {

/// Concept helper: a `Point3` after removing references and cv-qualifiers.
template <class T>
concept Point3_value = Point3<std::remove_cvref_t<T>>;

/// \concept ReadablePointMap
/// A property map `PM` from items of type `Item` to 3D points.
///
/// Requirements, for `const PM& pm` and `const Item& item`:
/// - `get(pm, item)` is valid (found by ADL, as in Boost.PropertyMap) and returns a type that
///   models `Point3` (by value or by reference).
///
/// Models: PCCD::Identity_point_map<P> for any Point3 P (the default), Boost.PropertyMap maps
/// (e.g. boost::typed_identity_property_map, iterator_property_map over points),
/// CGAL::Identity_property_map, CGAL::First_of_pair_property_map, and user maps such as the one in
/// examples/custom_point_type.cpp.
template <class PM, class Item>
concept ReadablePointMap = requires(const PM& pm, const Item& item) {
    { get(pm, item) } -> Point3_value;
};

} // namespace PCCD
