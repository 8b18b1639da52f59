// PCCD/Proximity/internal/surface_reach.h -- how far from a cloud point its implicit surface can lie
// (doc/algorithms.md "Continuous collision", the advancement's bound; doc/manual/proximity.md "The
// interval"): the point's domain radius, capped by the kernel's support radius, since f is defined
// nowhere else. The certified lower bounds of the surfaces' distance (time_of_contact()'s
// advancement, distance()'s lower_bound) subtract it from point pair distances.
#pragma once

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/Reach_rule.h>

namespace PCCD::internal {

/// How far from a cloud point its surface can lie: the point's stored reach (its domain radius)
/// mapped by `rule` (capped by the support radius: f needs a cloud point that close), plus `extra`.
/// A hierarchy without reaches (an object without a domain) gets reach 0 and extra = the support
/// radius, so the bound holds for it too.
struct Surface_reach {
    Reach_rule rule;
    double extra = 0.0;

    double operator()(double stored) const { return rule(stored) + extra; }
};

/// The surface reach of an object whose surface has support radius `support`.
inline Surface_reach surface_reach(const Point_cloud_hierarchy& h, double support)
{
    return Surface_reach{Reach_rule{.scale = 1.0, .cap = support}, h.has_reach() ? 0.0 : support};
}

} // namespace PCCD::internal
