// PCCD/Surface/surface_options.h -- what the surface's preprocessing can be told: the kernel's
// bandwidth (Bandwidth_options), the local shape fitted (Surface_fit), the domain radii
// (Surface_domain_options) and the outlier test (Outlier_options) (doc/algorithms.md "WLS
// surface", doc/manual/surface.md). Options only: it includes no implementation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace PCCD {

/// How the Gaussian kernel of the surface is chosen. Defaults measured in doc/manual/surface.md
/// ("Choosing eta and theta_eps").
struct Bandwidth_options {
    /// eta: the support radius in units of the sampling radius r(P), independent of the sampling
    /// density. Default 3. Must be finite and > 0.
    double eta = 3.0;
    /// theta_eps: weights below it are ignored. Default 1e-2. Must lie in (0, 1).
    double theta_eps = 1e-2;
    /// A bandwidth h given by the user (length unit of the cloud), used as it is: eta, r(P) and
    /// noise_factor are then ignored. Unset (default): automatic, eta r(P) / sqrt(-ln theta_eps).
    /// When set: finite and > 0.
    std::optional<double> bandwidth = std::nullopt;
    /// Noise-aware support (automatic bandwidth only): the support radius is at least
    /// noise_factor * sigma, sigma the cloud's noise estimate (noise_estimate()), so that the fit
    /// keeps averaging over enough points when the noise is heavy. Default 15, measured with the
    /// sphere fit (Surface_fit::sphere, Point_cloud_object's default) on noisy area samples of the
    /// bunny and the elephant (doc/benchmarks.md "Accuracy on scans"): with sigma = 0.6 mean spacings
    /// it widens the support from eta r(P) (8 spacings) to about 10 spacings and brings the curves'
    /// median distance from 0.32 to 0.28 spacings and their p95 from 1.15 to 0.98 (bunny); 20 is
    /// worse again (the sphere no longer follows the shape). Up to sigma = 0.3 spacings the rule
    /// leaves eta r(P) alone. With the plane fit, whose shrinkage on curved parts grows with the
    /// kernel, 10 is the better value. At sigma = 1 spacing eta r(P) leaves about 3 % of the surface
    /// with flipped normals, a support of about 4 r(P) 0.1 %. 0 disables it. Must be finite and >= 0.
    double noise_factor = 15.0;
};

/// The local shape WLS_surface fits at each evaluation point x.
enum class Surface_fit : std::uint8_t {
    /// The published surface: the plane through the weighted mean a(x) normal to the smallest
    /// eigenvector n(x) of the weighted covariance; f(x) = n(x) . (x - a(x)). On a curved surface
    /// a(x) lies on the concave side, so the zero set is shrunk by about kappa h^2 / 2.
    plane = 0,
    /// An algebraic sphere (a plane in the limit of zero curvature) fitted to the weighted points
    /// and their oriented normals; f(x) = the signed distance from x to that sphere, n(x) = its
    /// gradient direction at x. Exact on spheres and planes; where the sphere is not determined
    /// (no spread of the normals' positions, or the fitted normals disagree with the nearest
    /// point's), the plane answers.
    sphere = 1,
    /// Implicit moving least squares (IMLS; Kolluri, "Provably good moving least squares", ACM TALG
    /// 2008; the non-robust form of Oztireli, Guennebaud and Gross's RIMLS, Eurographics 2009): the
    /// weighted mean of the signed distances from x to the neighbours' own tangent planes,
    /// f(x) = sum theta_i n_i . (x - p_i) / sum theta_i, divided by the length of the weighted mean
    /// normal m(x) = sum theta_i n_i / sum theta_i so that f grows like a distance; n(x) = m(x) /
    /// |m(x)|. Exact on planes; where two faces meet at an edge or a corner, x on both tangent planes
    /// gives f = 0, so the zero set keeps the edge instead of cutting it (the plane and the sphere
    /// fit put it inside: by 1.3 and 0.7 spacings at a sampled cube's edges and corners), as far as the stored
    /// normals themselves are sharp there (Point_cloud_object_options::normal_bandwidth). On convex
    /// curved parts its zero set lies a little outside the points (by about kappa h^2 / 2, the
    /// plane's shrinkage with the opposite sign). Where m(x) is shorter than 0.1 or points against the
    /// nearest point's normal, the plane answers. Measured against the exact meshes in
    /// doc/manual/surface.md ("Sharp features").
    imls = 2,
};

/// Options of surface_domain_radii(). Defaults measured in doc/benchmarks.md "Accuracy on scans".
struct Surface_domain_options {
    /// k: the local spacing l_i of point i is its distance to its k-th nearest other point. Default
    /// 6 (on a uniformly sampled surface l_i is then about 2.7 mean spacings, a little above the
    /// 0.99-quantile sampling radius r(P), so 99 % of the surface lies within l of a point). Must
    /// be >= 1.
    unsigned neighbors = 6;
    /// D_i = factor * l_i. Default 1. Must be finite and > 0. +infinity is not allowed here; use
    /// `enabled = false` for a surface without a domain.
    double factor = 1.0;
    /// False: no domain (f is defined wherever the kernel's support holds a determined fit, the
    /// behaviour of the published method). Default true.
    bool enabled = true;
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

/// Options of find_outliers() and of Point_cloud_object's outlier removal.
struct Outlier_options {
    /// Remove the outliers before building the surface (Point_cloud_object). Default true.
    bool remove = true;
    /// k of the local spacing l_i (distance to the k-th nearest other point). Default 6. >= 1.
    unsigned neighbors = 6;
    /// Point i is an outlier when l_i > ratio * median of l_j over its k nearest neighbours j (the
    /// upper median for even k). Default 4: measured on uniform samples of a sphere, a torus and a
    /// plane patch, l_i / median(l_j) stays at 1.6-2.2, and at 2.3-3.1 across a 16-fold step in
    /// density. A single stray point is caught by this test once it is about 12 spacings off a
    /// plane; stray points closer to the surface stay and act as noise, which the fit and the
    /// verified contacts absorb. Must be finite and > 1.
    double ratio = 4.0;
    /// Point i is also an outlier when l_i > global_ratio * the median of l over the whole cloud:
    /// the local test alone misses stray points whose nearest neighbours are other stray points (a
    /// scatter of outliers away from the surface). Default 8: a local spacing 8 times the typical
    /// one. Measured on a plane patch with one half sparser: 8 times fewer points there flag nothing,
    /// 16 times fewer flag 1-2 legitimate points of the sparse half on some seeds; set it higher, or
    /// to 0 to disable this test, for scans whose density varies more than 8-fold. Must be finite and
    /// 0 or > 1.
    double global_ratio = 8.0;
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

} // namespace PCCD
