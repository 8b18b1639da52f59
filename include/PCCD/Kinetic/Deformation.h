// PCCD/Kinetic/Deformation.h -- the options, the per-frame report and the error of a deforming point
// cloud (Deforming_point_cloud_object): the stretch bound that states how far from an isometry the
// motion may go, what happens beyond it, and what a frame measured (doc/manual/kinetic.md,
// "Deforming point clouds"; doc/algorithms.md, "Deforming point clouds").
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <PCCD/Error.h>

namespace PCCD {

/// What a deforming object does when a frame stretches an edge of its proximity graph beyond the
/// bound (Deformation_options::stretch_bound).
enum class Stretch_action : std::uint8_t {
    /// Throw Deformation_error and keep the previous frame (the object stays usable).
    fail = 0,
    /// Rebuild the whole object from the frame's positions, which become the new rest pose.
    rebuild = 1,
};

/// How a deforming object gets the normals of a frame.
enum class Normal_update : std::uint8_t {
    /// Each rest normal carried by the local deformation gradient (least squares over the point's
    /// graph neighbours): (A t1) x (A t2) for a tangent basis (t1, t2) of the rest normal. O(degree).
    transport = 0,
    /// The rest pose's WLS fit redone over the kept CPSP list at the current positions, oriented
    /// like the transported normal: the normal a rebuild would compute from the same lists. O(k).
    refit = 1,
};

/// Options of Deforming_point_cloud_object.
struct Deformation_options {
    /// The near-isometry assumption: every edge of the proximity graph keeps its rest length within
    /// a factor 1 + stretch_bound, i.e. current / rest length lies in [1 / (1 + b), 1 + b]. The
    /// graph, the geodesic (CPSP) lists and the kernel stay those of the rest pose only while this
    /// holds. Finite and > 0; default 0.25.
    double stretch_bound = 0.25;
    /// What a frame beyond the bound does; default Stretch_action::fail.
    Stretch_action on_stretch = Stretch_action::fail;
    /// How the normals follow the motion; default Normal_update::transport (doc/benchmarks.md,
    /// "Deforming contact", measures both against a rebuild's normals).
    Normal_update normals = Normal_update::transport;
    /// Worker threads of a frame's update, 1 to 4096; unset (default): all available. Ignored
    /// without TBB. The frame does not depend on it.
    std::optional<unsigned> threads = std::nullopt;
};

/// What the last frame of a deforming object measured.
struct Deformation_report {
    /// Frames set since construction (0 for the rest pose).
    std::uint64_t frame = 0;
    /// Smallest and largest current / rest length over the graph's edges (1 at the rest pose;
    /// edges that are virtual or of rest length 0 are not measured).
    double min_stretch = 1.0;
    double max_stretch = 1.0;
    /// Points with an edge outside the bound (0 unless the frame caused a rebuild).
    std::size_t points_beyond = 0;
    /// True when this frame rebuilt the object (Stretch_action::rebuild): the rest pose is now this
    /// frame's.
    bool rebuilt = false;
    /// Rebuilds since construction.
    std::uint64_t rebuilds = 0;
    /// Wall-clock time of the update, in milliseconds.
    double milliseconds = 0.0;
};

/// Thrown when a frame breaks the near-isometry assumption under Stretch_action::fail: the message
/// names the worst edge, its stretch and the bound. An Invalid_input (the positions given are
/// outside what the object accepts).
class Deformation_error : public Invalid_input {
public:
    Deformation_error(const std::string& message, double stretch, std::uint32_t source, std::uint32_t target)
        : Invalid_input(message), m_stretch(stretch), m_source(source), m_target(target)
    {
    }
    /// current / rest length of the worst edge.
    double stretch() const { return m_stretch; }
    /// Its two points.
    std::uint32_t source() const { return m_source; }
    std::uint32_t target() const { return m_target; }

private:
    double m_stretch;
    std::uint32_t m_source;
    std::uint32_t m_target;
};

} // namespace PCCD
