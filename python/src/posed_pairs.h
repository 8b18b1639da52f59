// python/src/posed_pairs.h -- the `pairs` argument of the batch functions (do_intersect_many,
// intersection_points_many, distance_many): an iterable of (object_a, pose_a, object_b, pose_b)
// tuples, read into PCCD's Posed_pair list (doc/manual/python.md, "Many pairs at once").
#pragma once

#include "pccd_python.h"

#include <PCCD/Intersection/do_intersect_many.h>

#include <vector>

namespace pccd_python {

/// The pairs of a batch call, and the Python objects that must stay alive while the GIL is
/// released (the pairs point into them).
struct Posed_pairs {
    std::vector<PCCD::Posed_pair<Object>> pairs;
    std::vector<py::object> keep;
};

/// Reads `pairs`. Raises ValueError for an item that is not a 4-sequence or has a bad pose (naming
/// the pair), TypeError when items 0 and 2 are not pccd.Object instances.
Posed_pairs posed_pairs(const py::iterable& pairs);

} // namespace pccd_python
