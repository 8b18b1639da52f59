// PCCD/Surface/WLS_surface.h -- the implicit surface over a point cloud (doc/algorithms.md, "The
// implicit surface"): f(x) = n(x) . (x - a(x)), with a(x) the weighted mean of the cloud points
// near x, n(x) the eigenvector of the smallest eigenvalue of their weighted covariance, oriented
// like the normal stored at x's nearest cloud point. The distance (Euclidean or geodesic) and the
// weight (Gaussian with bounded support) are policies. f is undefined far from the cloud, and says
// so.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <utility>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Surface/Gaussian_weight.h>
#include <PCCD/Surface/Surface_fit.h>
#include <PCCD/Surface/internal/wls_fit.h>
#include <PCCD/concepts/SurfaceDistance.h>
#include <PCCD/concepts/SurfaceWeight.h>
#include <PCCD/internal/parallel.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// What an evaluation of the implicit surface found.
enum class Surface_status : std::uint8_t {
    /// f, n and a are defined.
    defined = 0,
    /// No cloud point lies within the kernel's support (no weight >= theta_eps): f, n and a are
    /// undefined. This is the state of every point far from the cloud.
    outside_support = 1,
    /// Some points carry weight, so a(x) is defined, but n(x) is not: fewer than three non-collinear
    /// points (or an isotropic neighbourhood) leave the smallest eigenvector of B undetermined, or
    /// the nearest cloud point has no normal to orient n(x) by.
    degenerate = 2,
    /// x lies farther from its nearest cloud point p* than p*'s domain radius (the surface's
    /// domain, doc/manual/surface.md "Scans: where the surface is defined"): the fit may still be
    /// computable there, but its zero set would be a spurious sheet far from the data, so f, n and
    /// a are undefined.
    outside_domain = 3,
};

/// "defined", "outside_support", "degenerate" or "outside_domain".
inline const char* to_string(Surface_status status)
{
    switch (status) {
    case Surface_status::defined: return "defined";
    case Surface_status::outside_support: return "outside_support";
    case Surface_status::degenerate: return "degenerate";
    case Surface_status::outside_domain: return "outside_domain";
    }
    return "unknown";
}

/// One evaluation of the implicit surface at a point x. Fields that the status leaves undefined are
/// NaN (never a fabricated 0).
struct Surface_evaluation {
    static constexpr std::uint32_t no_point = std::numeric_limits<std::uint32_t>::max();

    Surface_status status = Surface_status::outside_support;
    /// f(x): n(x) . (x - a(x)) for the plane fit, the signed distance from x to the fitted sphere
    /// for the sphere fit, the mean of the neighbours' tangent-plane distances for the IMLS fit
    /// (Surface_fit); NaN unless defined.
    double value = std::numeric_limits<double>::quiet_NaN();
    /// n(x), unit length, oriented like the stored normal of `nearest` (the sphere fit: the sphere's
    /// gradient direction at x; the IMLS fit: the weighted mean normal's); NaN unless defined.
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    /// a(x), the weighted mean; NaN when outside_support.
    Eigen::Vector3d centroid = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    /// Sum of the weights (0 when outside_support).
    double weight_sum = 0.0;
    /// Number of cloud points with weight >= theta_eps.
    std::uint32_t neighbor_count = 0;
    /// The cloud point nearest to x (x's own index at a cloud point); no_point when outside_support.
    std::uint32_t nearest = no_point;
    /// |x - p*| / D_{p*}: how deep in the surface's domain x lies (0 at a cloud point, 1 at the
    /// domain's edge); 0 for a surface without a domain; NaN when outside_support.
    double domain_fraction = std::numeric_limits<double>::quiet_NaN();

    bool defined() const { return status == Surface_status::defined; }
    /// f(x) when defined, std::nullopt otherwise.
    std::optional<double> value_if_defined() const { return defined() ? std::optional<double>(value) : std::nullopt; }
};

/// The implicit surface f(x) = n(x) . (x - a(x)) of a point cloud (doc/algorithms.md, "The implicit
/// surface"): a(x) = sum theta(d(x, p_i)) p_i / sum theta(d(x, p_i)), B(x) = sum theta(d(x, p_i))
/// (p_i - a(x)) (p_i - a(x))^T,  n(x) = eigenvector of B's smallest eigenvalue, with the sign of
/// the normal stored at x's nearest cloud point. Only the points with d(x, p_i) <=
/// weight.support_radius() take part. With Surface_fit::sphere, f(x) is instead the signed distance
/// from x to the algebraic sphere fitted to the same weighted points and their stored normals
/// (doc/manual/surface.md, "The fit: plane or sphere"); with Surface_fit::imls the weighted mean of
/// the distances from x to the neighbours' tangent planes ("Sharp features").
///
/// \tparam Distance a model of SurfaceDistance: Euclidean_distance or Geodesic_distance.
/// \tparam Weight a model of SurfaceWeight (Gaussian_weight by default).
///
/// The stored normals (one per cloud point) orient n(x); only their sign matters. Compute them with
/// estimate_normals() and orient them with orient_normals() or orient_normals_like(), or let
/// Point_cloud_object do all of it.
///
/// Immutable; copies are cheap (the normals are shared). Thread safety: every member function is
/// const and safe to call concurrently.
template <SurfaceDistance Distance, SurfaceWeight Weight = Gaussian_weight>
class WLS_surface {
public:
    using Distance_policy = Distance;
    using Weight_policy = Weight;
    using Index = std::uint32_t;

    /// \param normals 3 x N, column i the oriented normal of point i (N = distance.size()); a zero
    ///        column means point i has no normal (evaluations whose nearest point it is are
    ///        degenerate).
    /// \param domain_radii the surface's domain: empty (the default: f is defined wherever the
    ///        kernel's support holds a determined fit), or N radii D_i > 0 (+infinity allowed): f is
    ///        defined at x only when |x - p*| <= D_{p*}, p* the cloud point nearest to x (see
    ///        surface_domain_radii()).
    /// \throws Invalid_input if `normals` has the wrong size or a non-finite entry, if
    ///         `domain_radii` is neither empty nor of size N or holds a radius that is NaN or <= 0, or
    ///         if the weight's support radius exceeds `distance.max_radius()` by more than a relative
    ///         1e-12 (e.g. a CPSP map built for a smaller bound than the kernel needs).
    /// \param fit the local shape fitted at each x (default: the published plane). The sphere and
    ///        IMLS fits read the stored normals of the neighbours, so they must be consistently
    ///        oriented.
    WLS_surface(Distance distance, Weight weight, Eigen::Matrix3Xd normals, Eigen::VectorXd domain_radii = {},
                Surface_fit fit = Surface_fit::plane)
        : WLS_surface(std::move(distance), std::move(weight), std::make_shared<const Eigen::Matrix3Xd>(std::move(normals)),
                      std::make_shared<const Eigen::VectorXd>(std::move(domain_radii)), fit)
    {
    }

    /// The same surface over another distance policy of the same points (a Euclidean_distance for a
    /// Geodesic_distance, say): the same weight, fit, normals and domain radii, shared by the two
    /// surfaces instead of copied.
    /// \throws Invalid_input as the constructor: a distance over another number of points, or one
    ///         whose max_radius() is below the weight's support radius.
    template <SurfaceDistance Other>
    WLS_surface<Other, Weight> with_distance(Other distance) const
    {
        return WLS_surface<Other, Weight>(std::move(distance), m_weight, m_normals, m_domain, m_fit);
    }

    /// \name Evaluation
    /// @{

    /// f, n and a at an arbitrary point x (see Surface_status for when they are undefined).
    /// Complexity: that of `Distance::for_each_neighbor` (one kd-tree query) plus O(k) for the k
    /// points in the support and O(1) for the 3 x 3 eigenproblem.
    Surface_evaluation evaluate(const Eigen::Vector3d& x) const
    {
        Sums sums;
        const std::optional<Index> nearest =
            m_distance.for_each_neighbor(x, m_support, [&](Index j, double d) { add(sums, x, j, d); });
        return finish(x, nearest, sums);
    }

    /// f, n and a at cloud point i. With Geodesic_distance this reads i's CPSP list only: O(k), no
    /// kd-tree query. \pre i < size()
    Surface_evaluation evaluate_at(Index i) const
    {
        PCCD_precondition_msg(i < size(), "WLS surface: point index out of range");
        const Eigen::Vector3d x = m_distance.position(i);
        Sums sums;
        m_distance.for_each_neighbor_of_point(i, m_support, [&](Index j, double d) { add(sums, x, j, d); });
        return finish(x, sums.plane.count > 0 ? std::optional<Index>(i) : std::nullopt, sums);
    }

    /// f(x), or std::nullopt where it is undefined.
    std::optional<double> value(const Eigen::Vector3d& x) const { return evaluate(x).value_if_defined(); }
    /// f(p_i), or std::nullopt where it is undefined. \pre i < size()
    std::optional<double> value_at(Index i) const { return evaluate_at(i).value_if_defined(); }

    /// Evaluates every point of `points` into `out` (out[k] for points[k]), in parallel when TBB is
    /// available (`threads` workers >= 1, unset: all). \pre out.size() == points.size()
    void evaluate(std::span<const Eigen::Vector3d> points, std::span<Surface_evaluation> out,
                  std::optional<unsigned> threads = std::nullopt) const
    {
        PCCD_precondition_msg(out.size() == points.size(), "WLS surface: batch output size differs from input size");
        for_blocks(points.size(), threads, [&](std::size_t k) { out[k] = evaluate(points[k]); });
    }

    /// Evaluates every cloud point of `indices` into `out`. \pre out.size() == indices.size() and
    /// every index < size()
    void evaluate_at(std::span<const Index> indices, std::span<Surface_evaluation> out,
                     std::optional<unsigned> threads = std::nullopt) const
    {
        PCCD_precondition_msg(out.size() == indices.size(), "WLS surface: batch output size differs from input size");
        for_blocks(indices.size(), threads, [&](std::size_t k) { out[k] = evaluate_at(indices[k]); });
    }
    /// @}

    /// \name Access
    /// @{
    std::size_t size() const { return m_distance.size(); }
    const Distance& distance() const { return m_distance; }
    const Weight& weight() const { return m_weight; }
    /// The support radius R: only points with d(x, p) <= R take part.
    double support_radius() const { return m_support; }
    /// The stored (oriented) normals, 3 x N.
    const Eigen::Matrix3Xd& normals() const { return *m_normals; }
    /// The local shape fitted at each evaluation point.
    Surface_fit fit() const { return m_fit; }
    /// The domain radii D_i (empty when the surface has no domain restriction).
    const Eigen::VectorXd& domain_radii() const { return *m_domain; }
    /// |x - p*| / D_{p*} for x whose nearest cloud point is `nearest` (0 without a domain): x lies
    /// in the surface's domain when it is <= 1.
    double domain_fraction(const Eigen::Vector3d& x, Index nearest) const
    {
        if (m_domain->size() == 0) return 0.0;
        return (m_distance.position(nearest) - x).norm() / (*m_domain)(Eigen::Index(nearest));
    }
    /// @}

private:
    template <SurfaceDistance, SurfaceWeight>
    friend class WLS_surface;

    /// The constructor's work, with the normals and domain radii already held (and maybe shared).
    WLS_surface(Distance distance, Weight weight, std::shared_ptr<const Eigen::Matrix3Xd> normals,
                std::shared_ptr<const Eigen::VectorXd> domain_radii, Surface_fit fit)
        : m_distance(std::move(distance)),
          m_weight(std::move(weight)),
          m_support(double(m_weight.support_radius())),
          m_normals(std::move(normals)),
          m_domain(std::move(domain_radii)),
          m_fit(fit)
    {
        if (fit != Surface_fit::plane && fit != Surface_fit::sphere && fit != Surface_fit::imls)
            throw Invalid_input(internal::concat("WLS surface: unknown surface fit ", int(fit)));
        if (m_domain->size() != 0 && std::size_t(m_domain->size()) != m_distance.size())
            throw Invalid_input(internal::concat("WLS surface: ", m_domain->size(), " domain radii given for ",
                                                 m_distance.size(), " points"));
        for (Eigen::Index i = 0; i < m_domain->size(); ++i)
            if (!std::isgreater((*m_domain)(i), 0.0))
                throw Invalid_input(internal::concat("WLS surface: the domain radius of point ", i, " is ",
                                                     (*m_domain)(i), "; it must be > 0"));
        if (std::size_t(m_normals->cols()) != m_distance.size())
            throw Invalid_input(internal::concat("WLS surface: ", m_normals->cols(), " normals given for ",
                                                 m_distance.size(), " points"));
        if (!internal::all_finite(*m_normals))
            for (Eigen::Index i = 0; i < m_normals->cols(); ++i)
                if (!internal::all_finite(m_normals->col(i)))
                    throw Invalid_input(internal::concat("WLS surface: the normal of point ", i, " is not finite"));
        if (!(std::isfinite(m_support) && m_support > 0.0))
            throw Invalid_input(internal::concat("WLS surface: support radius ", m_support, " must be finite and > 0"));
        // The relative slack absorbs rounding: h sqrt(-ln theta_eps) with h = eta r / sqrt(-ln theta_eps)
        // may exceed eta r, the bound of a CPSP map, by an ulp.
        if (m_support > double(m_distance.max_radius()) * (1.0 + 1e-12))
            throw Invalid_input(internal::concat("WLS surface: the kernel's support radius ", m_support,
                                                 " exceeds the largest radius the distance policy answers (",
                                                 double(m_distance.max_radius()),
                                                 "); build the geodesic map with a bound >= the support radius"));
    }

    struct Sums {
        internal::Wls_sums plane;
        internal::Sphere_sums sphere;
    };

    void add(Sums& sums, const Eigen::Vector3d& x, Index j, double d) const
    {
        const Eigen::Vector3d offset = m_distance.position(j) - x;
        const double w = double(m_weight(d));
        sums.plane.add(offset, w);
        if (m_fit != Surface_fit::plane) {
            const auto normal = m_normals->col(Eigen::Index(j));
            // A point without a normal (zero column) takes part in the plane only.
            if (!normal.isZero(0.0)) sums.sphere.add(offset, w, normal);
        }
    }

    Surface_evaluation finish(const Eigen::Vector3d& x, std::optional<Index> nearest, const Sums& all) const
    {
        const internal::Wls_sums& sums = all.plane;
        Surface_evaluation result;
        if (!nearest || sums.count == 0 || !(sums.weight > 0.0)) return result;
        result.nearest = *nearest;
        result.domain_fraction = domain_fraction(x, *nearest);
        if (!(result.domain_fraction <= 1.0)) {
            result.status = Surface_status::outside_domain;
            return result;
        }
        result.neighbor_count = sums.count;
        result.weight_sum = sums.weight;
        const internal::Wls_fit fit = internal::finish_fit(x, sums);
        result.centroid = fit.centroid;
        const Eigen::Vector3d reference = m_normals->col(Eigen::Index(*nearest));
        if (!fit.determined || reference.isZero(0.0)) {
            result.status = Surface_status::degenerate;
            return result;
        }
        result.status = Surface_status::defined;
        result.normal = fit.normal.dot(reference) < 0.0 ? Eigen::Vector3d(-fit.normal) : fit.normal;
        result.value = result.normal.dot(x - fit.centroid);
        if (m_fit != Surface_fit::plane)
            if (const auto other = m_fit == Surface_fit::sphere ? internal::fit_sphere(all.sphere, reference)
                                                                : internal::fit_imls(all.sphere, reference)) {
                result.value = other->value;
                result.normal = other->normal;
            }
        return result;
    }

    template <class Body>
    static void for_blocks(std::size_t n, std::optional<unsigned> threads, const Body& body)
    {
        internal::with_threads(threads, [&] {
            internal::parallel_for_ranges(n, 256, [&](std::size_t begin, std::size_t end) {
                for (std::size_t k = begin; k < end; ++k) body(k);
            });
        });
    }

    Distance m_distance;
    Weight m_weight;
    double m_support;
    std::shared_ptr<const Eigen::Matrix3Xd> m_normals;
    std::shared_ptr<const Eigen::VectorXd> m_domain;
    Surface_fit m_fit;
};

} // namespace PCCD
