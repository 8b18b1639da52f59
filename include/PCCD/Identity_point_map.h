// PCCD/Identity_point_map.h -- the default point map: an item is its own point.
// A Boost.PropertyMap readable property map (get(map, item) returns the item).
#pragma once

#include <boost/property_map/property_map.hpp>

namespace PCCD {

/// Readable property map returning its key: the default point map of every PCCD algorithm that
/// takes a range of points. Stateless; safe to share between threads.
template <class Point>
struct Identity_point_map {
    using key_type = Point;
    using value_type = Point;
    using reference = const Point&;
    using category = boost::readable_property_map_tag;

    friend const Point& get(const Identity_point_map&, const Point& item) { return item; }
};

} // namespace PCCD
