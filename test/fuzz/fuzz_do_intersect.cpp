// test/fuzz/fuzz_do_intersect.cpp -- libFuzzer target: do_intersect() and intersection_points() on
// two small clouds, two poses, options and a policy, all decoded deterministically from the bytes.
//
// Input layout (bytes past the end read as zero, so every input decodes):
//   byte 0      query flags: bit 0 policy (0 Interpolation_search, 1 Randomized_sampling), bit 1
//               mode (0 do_intersect, 1 intersection_points), bit 2 symmetric, bit 3 region
//               (object_boxes), bits 4-5 refinement (3: an undefined enumerator, must be refused),
//               bit 6 epsilon set, bit 7 budget set
//   byte 1      more flags: bit 0 point_spacing set, bit 1 k-NN graph for both objects (else
//               r-SIG), bit 2 random partner choice, bit 3 policy `samples` set, bits 4-7 unused
//   8 bytes     seed
//   options     epsilon (1 + 8 bytes), budget (2), point_spacing (1 + 8), refinement_samples (1)
//   policy      isearch: min_samples, max_samples, samples (1 byte each), partner_candidates
//               (1 byte, modulo 16); RST: max_samples (2 bytes, modulo 1024)
//   object opts leaf_size (1), sampling-radius samples (1: 64 to 1084 Monte-Carlo points)
//   cloud A, cloud B   see decode_cloud(): a kind byte, a count (at most 200), then points
//   pose A, pose B     see decode_pose(): a kind byte, then a rotation and a translation
//
// Scalars given "as a value" are a selector byte and 8 bytes: selector 255 takes the 8 bytes as
// a raw double (NaN, infinities, negatives: the rejections), any other selector s gives
// 2^(s / 8 - 16), from 1.5e-5 to 2.6e4 (the useful range).
//
// Expected outcomes: PCCD::Invalid_input from building an object (too few points, a non-finite
// coordinate, a degenerate cloud, a leaf size of 0), from a pose that is not a rigid motion, or
// from the query when the options or the policy break a documented rule (mirrored by
// options_valid() below: the query must refuse exactly those), or when the automatic epsilon of a
// tiny cloud underflows. Otherwise a result, whose invariants are checked (check_result()), and
// which the same call must reproduce bit for bit. Findings (abort, see fuzz_support.h): any other
// exception, an Invalid_input from valid arguments, acceptance of invalid ones, a broken
// invariant, and what the sanitizers and libFuzzer's -timeout report.
//
// Each execution stays in the milliseconds: at most 200 points per cloud (so at most 200 samples
// per role for the interpolation search) and 1023 samples for RST, a reduced Monte-Carlo sampling
// radius, one thread.
#include "fuzz_support.h"
#include "../intersection_test_helpers.h"

#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Rigid_transform_3.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace {

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;
using PCCD::fuzz::require;

constexpr std::size_t max_points = 200;

/// Reads the fuzzed bytes front to back; past the end every read gives zero.
class Byte_source {
public:
    Byte_source(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

    // Every read is its own statement: the order in which function arguments or the operands of
    // `|` are evaluated is unspecified, and an input must decode alike with every compiler.
    std::uint8_t u8() { return m_at < m_size ? m_data[m_at++] : 0; }
    std::int8_t i8() { return std::bit_cast<std::int8_t>(u8()); }
    /// Little-endian unsigned integer of `bytes` bytes.
    std::uint64_t little_endian(int bytes)
    {
        std::uint64_t x = 0;
        for (int k = 0; k < bytes; ++k) x |= std::uint64_t(u8()) << (8 * k);
        return x;
    }
    std::uint16_t u16() { return std::uint16_t(little_endian(2)); }
    std::int16_t i16() { return std::bit_cast<std::int16_t>(u16()); }
    std::uint64_t u64() { return little_endian(8); }
    float f32() { return std::bit_cast<float>(std::uint32_t(little_endian(4))); }
    double f64() { return std::bit_cast<double>(u64()); }
    /// Three values of `read()`, read in order x, y, z.
    template <class Read>
    Eigen::Vector3d vector(Read read)
    {
        Eigen::Vector3d v;
        for (int d = 0; d < 3; ++d) v(d) = double(read());
        return v;
    }
    /// A raw double (selector 255) or a power of two in [2^-16, 2^15.875] (see the file comment).
    double value()
    {
        const std::uint8_t selector = u8();
        const double raw = f64();
        return selector == 255 ? raw : std::exp2(double(selector) / 8.0 - 16.0);
    }

private:
    const std::uint8_t* m_data;
    std::size_t m_size;
    std::size_t m_at = 0;
};

/// A cloud. Kind byte: bits 0-2 the shape, bit 3 one corrupted point (index and value from the
/// bytes: NaN, +-infinity, 1e300 or the largest double), bit 4 duplicates every point once (as far
/// as the count allows). Shapes:
///   0 raw doubles (24 bytes a point)          1 raw floats (12 bytes a point)
///   2 a lattice: int8 coordinates times 2^(e - 40) (duplicates, collinear and flat sets come easily)
///   3 a Fibonacci sphere: centre int8 / 16, radius 0.25 + u8 / 64, a radial jitter byte per point
///   4 a square patch in z = 0, spacing 0.05 + u8 / 256, a height jitter byte per point
///   5-7 a segment (collinear points): direction from 3 int8, spacing u8 / 64
std::vector<Eigen::Vector3d> decode_cloud(Byte_source& in)
{
    const std::uint8_t kind = in.u8();
    const std::size_t n = std::min<std::size_t>(in.u8(), max_points);
    std::vector<Eigen::Vector3d> points;
    points.reserve(n);
    switch (kind & 7) {
    case 0:
        for (std::size_t i = 0; i < n; ++i) points.push_back(in.vector([&] { return in.f64(); }));
        break;
    case 1:
        for (std::size_t i = 0; i < n; ++i) points.push_back(in.vector([&] { return in.f32(); }));
        break;
    case 2: {
        const double scale = std::exp2(double(in.u8() % 64) - 40.0);
        for (std::size_t i = 0; i < n; ++i) points.push_back(scale * in.vector([&] { return in.i8(); }));
        break;
    }
    case 3: {
        const Eigen::Vector3d centre = in.vector([&] { return in.i8(); }) / 16.0;
        const double radius = 0.25 + in.u8() / 64.0;
        const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
        for (std::size_t i = 0; i < n; ++i) {
            const double z = 1.0 - (2.0 * double(i) + 1.0) / double(n);
            const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
            const double jitter = 1.0 + in.i8() / 1024.0;
            points.push_back(centre + radius * jitter *
                                          Eigen::Vector3d(ring * std::cos(golden * double(i)),
                                                          ring * std::sin(golden * double(i)), z));
        }
        break;
    }
    case 4: {
        const double spacing = 0.05 + in.u8() / 256.0;
        const auto side = std::size_t(std::ceil(std::sqrt(double(n))));
        for (std::size_t i = 0; i < n; ++i)
            points.emplace_back(spacing * double(i % side), spacing * double(i / side), in.i8() * spacing / 512.0);
        break;
    }
    default: {
        const Eigen::Vector3d direction = in.vector([&] { return in.i8(); });
        const double spacing = in.u8() / 64.0;
        for (std::size_t i = 0; i < n; ++i) points.push_back(spacing * double(i) * direction);
        break;
    }
    }
    if ((kind & 16) != 0)
        for (std::size_t i = 0, m = points.size(); i < m && points.size() < max_points; ++i) points.push_back(points[i]);
    if ((kind & 8) != 0 && !points.empty()) {
        const std::size_t at = in.u8() % points.size();
        const int axis = in.u8() % 3;
        constexpr double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(), 1e300,
                                  std::numeric_limits<double>::max()};
        points[at](axis) = bad[in.u8() % 5];
    }
    return points;
}

/// A pose. Kind byte % 4: 0 and 1 a unit quaternion (four int16, the identity when they are all
/// near zero) and a translation; 2 the same rotation with each entry perturbed by int8 * 2^-(19 + k)
/// (around the rigidity tolerance 1e-5); 3 twelve raw doubles (row-major [R | t]). Translation:
/// three int16 / 4096 times 2^(e - 8), e from a byte (0..31).
/// \throws PCCD::Invalid_input when the matrix is not a rigid motion.
Pose decode_pose(Byte_source& in)
{
    const std::uint8_t kind = in.u8() % 4;
    if (kind == 3) {
        std::array<double, 12> m;
        for (double& x : m) x = in.f64();
        return Pose(m);
    }
    Eigen::Vector4d q;
    for (int k = 0; k < 4; ++k) q(k) = in.i16();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    if (q.norm() > 16.0) rotation = Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
    const double scale = std::exp2(double(in.u8() % 32) - 8.0) / 4096.0;
    const Eigen::Vector3d translation = scale * in.vector([&] { return in.i16(); });
    if (kind == 2) {
        const double perturbation = std::exp2(-19.0 - double(in.u8() % 8));
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) rotation(i, j) += in.i8() * perturbation;
    }
    return Pose(rotation, translation);
}

/// The query's options and policy, and the mode.
struct Query {
    bool rst = false;
    bool first_hit = true;
    bool knn_graph = false;
    PCCD::Intersection_options options;
    PCCD::Interpolation_search isearch;
    PCCD::Randomized_sampling sampling;
};

Query decode_query(Byte_source& in)
{
    Query q;
    const std::uint8_t flags = in.u8();
    const std::uint8_t more = in.u8();
    q.rst = (flags & 1) != 0;
    q.first_hit = (flags & 2) == 0;
    q.options.symmetric = (flags & 4) != 0;
    q.options.region = (flags & 8) != 0 ? PCCD::Overlap_region::object_boxes : PCCD::Overlap_region::leaf_boxes;
    q.options.refinement = PCCD::Refinement((flags >> 4) & 3);
    q.knn_graph = (more & 2) != 0;
    q.options.seed = in.u64();
    const double epsilon = in.value();
    if ((flags & 64) != 0) q.options.epsilon = epsilon;
    const std::uint16_t budget = in.u16();
    if ((flags & 128) != 0) q.options.max_f_evaluations = budget;
    const double spacing = in.value();
    if ((more & 1) != 0) q.options.point_spacing = spacing;
    q.options.refinement_samples = in.u8();
    q.isearch.min_samples = in.u8();
    q.isearch.max_samples = in.u8();
    const std::uint8_t samples = in.u8();
    if ((more & 8) != 0) q.isearch.samples = samples;
    q.isearch.partner_candidates = in.u8() % 16;
    q.isearch.partner_choice = (more & 4) != 0 ? PCCD::Partner_choice::random : PCCD::Partner_choice::predicted;
    q.sampling.max_samples = in.u16() % 1024;
    return q;
}

/// The documented rules of Intersection_options and of the policy (Intersection_options.h,
/// Interpolation_search::check(), Randomized_sampling::check()), written out independently.
bool options_valid(const Query& q)
{
    const PCCD::Intersection_options& o = q.options;
    const auto positive = [](const std::optional<double>& x) { return !x || (std::isfinite(*x) && *x > 0.0); };
    if (!positive(o.epsilon) || !positive(o.point_spacing)) return false;
    if (o.max_f_evaluations && *o.max_f_evaluations == 0) return false;
    if (int(o.refinement) > 2) return false;
    if (o.refinement == PCCD::Refinement::sampling && o.refinement_samples == 0) return false;
    if (q.rst) return q.sampling.max_samples >= 1;
    const PCCD::Interpolation_search& p = q.isearch;
    return p.min_samples >= 1 && p.max_samples >= p.min_samples && (!p.samples || *p.samples >= 1) &&
           p.partner_candidates >= 1;
}

/// The invariants of a result (do_intersect.h, Intersection_result.h, the policies' code).
void check_result(const PCCD::Intersection_result& r, const Query& q, const Object& a, const Object& b)
{
    const PCCD::Intersection_options& o = q.options;
    const PCCD::Intersection_counters& c = r.counters;
    const double r_min = std::min(a.sampling_radius(), b.sampling_radius());
    const double epsilon =
        o.epsilon.value_or(q.rst ? q.sampling.default_epsilon(r_min) : q.isearch.default_epsilon(r_min));

    require(r.intersects == !r.points.empty(), "intersects != !points.empty()");
    require(bool(r) == r.intersects, "operator bool differs from intersects");
    require((r.status == PCCD::Intersection_status::intersecting) == r.intersects,
            "status intersecting differs from intersects");
    if (r.status == PCCD::Intersection_status::undecided)
        require(o.max_f_evaluations.has_value(), "undecided without a budget");
    if (o.max_f_evaluations) require(c.f_evaluations <= *o.max_f_evaluations, "more f evaluations than the budget");
    // With verified contacts (the default) every point is a projected, refined one, and the
    // verification's steps count as refinement samples; without, the published behaviour.
    const bool verified = o.verify_contacts;
    const double tolerance = o.contact_tolerance.value_or(0.05 * r_min);
    // "Separate" is earned (certify_separation): a search of the rest of the region (after which the
    // policies' own sample caps and RST's counters no longer describe the query), and at most one
    // crossing the verification rejected as the answer's point.
    const bool certified = c.certification_passes > 0;
    require(c.certification_passes <= 1 && c.unverified_crossings <= 1, "more than one certification or crossing");
    if (certified || c.unverified_crossings > 0)
        require(verified && o.certify_separation, "certification without verification or with certify_separation off");
    if (c.unverified_crossings > 0)
        require(r.intersects && r.points.size() == 1, "an unverified crossing that is not the one answer");
    if (q.first_hit) {
        require(r.points.size() <= 1, "do_intersect returned more than one point");
        if (!verified) require(c.refinement_samples == 0, "do_intersect refined");
    }
    if (!verified && o.refinement == PCCD::Refinement::none)
        require(c.refinement_samples == 0, "refinement none but refinement samples");
    if (!verified) require(c.candidates_rejected == 0, "candidates rejected without verification");

    for (const PCCD::Intersection_point& p : r.points) {
        require(p.position.allFinite(), "a non-finite intersection point");
        if (verified && c.unverified_crossings > 0) {
            require(p.kind == PCCD::Intersection_point_kind::approximate, "a crossing that is not approximate");
            require(std::isfinite(p.f_a) && std::isfinite(p.f_b), "a crossing without both surfaces defined");
            continue;
        }
        if (verified) {
            require(p.kind == PCCD::Intersection_point_kind::refined, "a verified point that is not refined");
            require(std::max(std::abs(p.f_a), std::abs(p.f_b)) <= tolerance, "a verified point with |f| > tolerance");
            continue;
        }
        switch (p.kind) {
        case PCCD::Intersection_point_kind::approximate:
            require(!q.rst, "an approximate point from randomized sampling");
            require(std::isnan(p.f_a) && std::isnan(p.f_b), "an approximate point with f values");
            break;
        case PCCD::Intersection_point_kind::refined:
            require(!q.rst && !q.first_hit && o.refinement != PCCD::Refinement::none, "an unexpected refined point");
            require(std::max(std::abs(p.f_a), std::abs(p.f_b)) <= epsilon, "a refined point with |f| > epsilon");
            break;
        case PCCD::Intersection_point_kind::sampled:
            require(q.rst, "a sampled point from the interpolation search");
            require(std::abs(p.f_a) < epsilon && std::abs(p.f_b) < epsilon, "a sampled point with |f| >= epsilon");
            break;
        default: PCCD::fuzz::finding("broken postcondition", "an intersection point of unknown kind");
        }
    }
    // Kept points are farther apart than the spacing (refinement moves them afterwards).
    if (!q.first_hit && (verified || q.rst || o.refinement == PCCD::Refinement::none)) {
        const double spacing = o.point_spacing.value_or(std::max(a.sampling_radius(), b.sampling_radius()));
        for (std::size_t i = 0; i < r.points.size(); ++i)
            for (std::size_t j = i + 1; j < r.points.size(); ++j)
                require((r.points[i].position - r.points[j].position).norm() > spacing * (1.0 - 1e-12),
                        "two intersection points closer than the point spacing");
    }

    require(c.leaf_pairs <= c.node_pairs, "more leaf pairs than node pairs");
    if (q.rst && certified) {
        require(c.samples <= q.sampling.max_samples + c.candidate_points, "RST and its certification drew too many samples");
    } else if (q.rst) {
        require(std::isnan(r.closest_estimate) == false && r.closest_estimate >= 0.0,
                "RST closest_estimate is NaN or negative");
        if (r.intersects) require(r.closest_estimate < epsilon, "RST intersects but closest_estimate >= epsilon");
        require(c.samples <= q.sampling.max_samples, "RST drew more than max_samples");
        require(c.samples <= c.f_evaluations && c.f_evaluations <= 2 * c.samples + 2 * c.refinement_samples,
                "RST: f evaluations not between samples and twice the samples and verification steps");
        require(c.brackets_tried == 0 && c.partner_candidates == 0 && c.brackets_found == 0 && c.search_steps == 0 &&
                    c.bisection_steps == 0 && c.candidate_points == 0,
                "RST reported interpolation-search counters");
        if (!verified) require(c.refinement_samples == 0, "unverified RST refined");
    } else {
        // The smallest |f_T| over the samples: >= 0, never NaN; +infinity when no sample had f_T
        // defined (in particular when the separation test decided before any evaluation).
        require(!std::isnan(r.closest_estimate) && r.closest_estimate >= 0.0, "interpolation search closest_estimate NaN or < 0");
        if (c.samples == 0) require(std::isinf(r.closest_estimate), "interpolation search estimated without samples");
        if (c.f_evaluations == 0) require(std::isinf(r.closest_estimate), "interpolation search estimated without evaluations");
        // Per role at most `samples` when set, else max_samples for a first hit; intersection_points()
        // takes the full covering count, bounded by the region (samples <= candidate_points below).
        if ((q.isearch.samples || q.first_hit) && !certified) {
            const std::size_t per_role = q.isearch.samples ? *q.isearch.samples : q.isearch.max_samples;
            require(c.samples <= 2 * per_role, "interpolation search drew more than its sample cap");
        }
        require(c.samples <= c.candidate_points, "more samples than candidate points");
        require(c.brackets_tried <= c.samples, "more brackets tried than samples");
        require(c.partner_candidates <= c.brackets_tried * q.isearch.partner_candidates,
                "more partner candidates than partner_candidates per bracket");
        require(c.brackets_found <= c.partner_candidates, "more brackets found than partner candidates");
        require(c.bisection_steps <= c.search_steps, "more bisection steps than search steps");
        const std::size_t searched = c.partner_candidates + c.search_steps;
        if (q.first_hit && !verified)
            require(c.f_evaluations == c.samples + searched,
                    "do_intersect: f evaluations != samples + partner candidates + search steps");
        else
            require(searched + c.refinement_samples <= c.f_evaluations &&
                        c.f_evaluations <= c.samples + searched + 2 * c.refinement_samples,
                    "intersection_points: f evaluations outside the accounting bounds");
    }
}

template <class Classify>
void expect_invalid_input(Classify&& on_invalid_input, const auto& run)
{
    try {
        run();
    } catch (const PCCD::Invalid_input& e) {
        on_invalid_input(e);
    } catch (const PCCD::Error& e) {
        PCCD::fuzz::finding("PCCD exception other than Invalid_input", e.what());
    } catch (const std::exception& e) {
        PCCD::fuzz::finding("non-PCCD exception", e.what());
    } catch (...) {
        PCCD::fuzz::finding("unknown exception", "(not derived from std::exception)");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Byte_source in(data, size);
    const Query q = decode_query(in);
    PCCD::Point_cloud_object_options object_options;
    object_options.graph = q.knn_graph ? PCCD::Graph_kind::knn : PCCD::Graph_kind::sphere_of_influence;
    object_options.hierarchy.leaf_size = in.u8() % 32;
    object_options.sampling_radius.samples = 64 + 4 * std::size_t(in.u8());
    object_options.threads = 1;
    const std::vector<Eigen::Vector3d> points_a = decode_cloud(in);
    const std::vector<Eigen::Vector3d> points_b = decode_cloud(in);

    // Rejections while building objects and poses end the input; nothing else is expected there.
    bool rejected = false;
    const auto reject = [&](const PCCD::Invalid_input&) { rejected = true; };
    std::optional<Object> a, b;
    std::optional<Pose> pose_a, pose_b;
    expect_invalid_input(reject, [&] {
        a.emplace(points_a, PCCD::Identity_point_map<Eigen::Vector3d>(), object_options);
        b.emplace(points_b, PCCD::Identity_point_map<Eigen::Vector3d>(), object_options);
    });
    if (rejected) return 0;
    expect_invalid_input(reject, [&] {
        pose_a.emplace(decode_pose(in));
        pose_b.emplace(decode_pose(in));
    });
    if (rejected) return 0;

    const bool valid = options_valid(q);
    const auto query = [&] {
        if (q.rst)
            return q.first_hit ? PCCD::do_intersect(*a, *pose_a, *b, *pose_b, q.options, q.sampling)
                               : PCCD::intersection_points(*a, *pose_a, *b, *pose_b, q.options, q.sampling);
        return q.first_hit ? PCCD::do_intersect(*a, *pose_a, *b, *pose_b, q.options, q.isearch)
                           : PCCD::intersection_points(*a, *pose_a, *b, *pose_b, q.options, q.isearch);
    };
    std::optional<PCCD::Intersection_result> first;
    expect_invalid_input(
        [&](const PCCD::Invalid_input& e) {
            rejected = true;
            if (valid && std::strstr(e.what(), "automatic epsilon") == nullptr)
                PCCD::fuzz::finding("Invalid_input from valid options", e.what());
        },
        [&] { first.emplace(query()); });
    if (rejected) return 0;
    require(valid, "the query accepted invalid options or policy parameters");
    check_result(*first, q, *a, *b);
    expect_invalid_input([](const PCCD::Invalid_input& e) { PCCD::fuzz::finding("second call threw", e.what()); },
                         [&] { require(pccd_test::result_difference(*first, query()).empty(), "the same query gave a different result"); });
    return 0;
}
