// PCCD/testing/scenes/Kinetic_scene.h -- the recorded animation that the kinetic tests, benchmarks,
// `pccd kinetic-bench` and the cloth example play (doc/manual/kinetic.md, "Scenes"): vertex
// trajectories recorded as key frames, i.e. piecewise-linear flightplans, the primitives over them,
// and an optional static obstacle. Not library code: PCCD's own programs reach testing/ through the
// CMake target PCCD::testing, and it is never installed.
#pragma once

#include <string>
#include <vector>

#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

namespace PCCD::testing {

/// A recorded animation over [start_time, end_time].
/// \tparam P the primitive type (Kinetic_triangle for the cloth, Kinetic_point for clouds).
template <KineticPrimitive P>
struct Kinetic_scene {
    std::string name;
    /// One flightplan per vertex; all share one vector of key times.
    std::vector<Piecewise_linear_flightplan> flightplans;
    std::vector<P> primitives;
    double start_time = 0.0;
    double end_time = 0.0;
    /// A static obstacle (the table of the cloth scene), empty when the scene has none.
    std::vector<Piecewise_linear_flightplan> obstacle_flightplans;
    std::vector<Kinetic_triangle> obstacle_triangles;
};

} // namespace PCCD::testing
