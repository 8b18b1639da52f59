// tools/render/render.cpp -- the splat renderer of tools/render/render.h.
#include "render.h"

#include "../parse_number.h"

#include <Eigen/Geometry>

#include <PCCD/Error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <utility>

namespace pccd_render {
namespace {

constexpr double degrees = std::numbers::pi / 180.0;

/// The shading of a splat: ambient plus diffuse light from above the camera's left shoulder; the
/// normal is turned towards the eye first (orientation does not matter), so both sides of a sheet
/// are lit alike.
struct Light {
    Eigen::Vector3d direction;  // towards the light
    double ambient = 0.3;

    explicit Light(const Camera& camera)
        : direction((camera.toward_eye + 0.5 * camera.up - 0.35 * camera.right).normalized()) {}

    double intensity(const Eigen::Vector3d& normal, const Camera& camera) const
    {
        const double length = normal.norm();
        if (!(length > 0.0) || !std::isfinite(length)) return 0.75;  // no normal: flat
        Eigen::Vector3d n = normal / length;
        if (n.dot(camera.toward_eye) < 0.0) n = -n;
        return ambient + (1.0 - ambient) * std::max(0.0, n.dot(direction));
    }
};

std::uint8_t scale_channel(std::uint8_t c, double s)
{
    return std::uint8_t(std::clamp(std::lround(double(c) * s), 0L, 255L));
}

bool finite(const Eigen::Vector3d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

/// The frame buffer: colour and depth per pixel.
struct Frame {
    Image image;
    std::vector<double> depth;

    Frame(int width, int height, Rgb background)
        : depth(std::size_t(width) * std::size_t(height), -std::numeric_limits<double>::infinity())
    {
        image.width = width;
        image.height = height;
        image.rgb.resize(3 * depth.size());
        for (std::size_t i = 0; i < depth.size(); ++i) {
            image.rgb[3 * i] = background.r;
            image.rgb[3 * i + 1] = background.g;
            image.rgb[3 * i + 2] = background.b;
        }
    }

    /// A disc of radius `radius` pixels around `centre` at depth `z`, where it is nearer than what
    /// is there; the pixel containing the centre is always covered.
    void disc(const Eigen::Vector2d& centre, double radius, double z, Rgb colour)
    {
        const int x0 = std::max(0, int(std::floor(centre.x() - radius)));
        const int x1 = std::min(image.width - 1, int(std::floor(centre.x() + radius)));
        const int y0 = std::max(0, int(std::floor(centre.y() - radius)));
        const int y1 = std::min(image.height - 1, int(std::floor(centre.y() + radius)));
        const int cx = int(std::floor(centre.x())), cy = int(std::floor(centre.y()));
        const double r2 = radius * radius;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double dx = x + 0.5 - centre.x(), dy = y + 0.5 - centre.y();
                if (dx * dx + dy * dy > r2 && !(x == cx && y == cy)) continue;
                const std::size_t i = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
                if (z <= depth[i]) continue;
                depth[i] = z;
                image.rgb[3 * i] = colour.r;
                image.rgb[3 * i + 1] = colour.g;
                image.rgb[3 * i + 2] = colour.b;
            }
    }
};

Camera oriented_camera(const View& view)
{
    const double az = view.azimuth * degrees, el = view.elevation * degrees;
    Camera camera;
    camera.toward_eye = Eigen::Vector3d(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
    camera.right = Eigen::Vector3d(std::cos(az), 0.0, -std::sin(az));
    camera.up = camera.toward_eye.cross(camera.right).normalized();
    return camera;
}

double parse_double(const std::string& text, const std::string& what)
{
    return pccd_tool::parse_finite_number(text, what);
}

} // namespace

View parse_view(const std::string& text)
{
    if (text == "front") return {0.0, 0.0};
    if (text == "back") return {180.0, 0.0};
    if (text == "side") return {90.0, 0.0};
    if (text == "top") return {0.0, 90.0};
    if (text == "iso") return {45.0, 35.0};
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos)
        throw PCCD::Invalid_input("view \"" + text +
                                  "\": expected AZIMUTH,ELEVATION in degrees (e.g. 30,20) or front, back, side, top, iso");
    const View view{parse_double(text.substr(0, comma), "view azimuth"),
                    parse_double(text.substr(comma + 1), "view elevation")};
    if (view.elevation < -90.0 || view.elevation > 90.0)
        throw PCCD::Invalid_input("view \"" + text + "\": the elevation must lie in [-90, 90] degrees");
    return view;
}

std::pair<int, int> parse_size(const std::string& text)
{
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string::npos) throw PCCD::Invalid_input("size \"" + text + "\": expected WIDTHxHEIGHT, e.g. 800x600");
    const double w = parse_double(text.substr(0, x), "size width"), h = parse_double(text.substr(x + 1), "size height");
    if (w != std::floor(w) || h != std::floor(h) || w < 16 || h < 16 || w > 8192 || h > 8192)
        throw PCCD::Invalid_input("size \"" + text + "\": width and height must be whole numbers in [16, 8192]");
    return {int(w), int(h)};
}

Eigen::Vector2d Camera::project(const Eigen::Vector3d& p) const
{
    const Eigen::Vector2d q(p.dot(right) - centre.x(), p.dot(up) - centre.y());
    return {0.5 * width + pixels_per_unit * q.x(), 0.5 * height - pixels_per_unit * q.y()};
}

Camera fit_camera(const Scene& scene, const View& view, int width, int height, double margin)
{
    if (width <= 0 || height <= 0) throw PCCD::Invalid_input("fit_camera: the image size must be positive");
    if (!(margin >= 0.0 && margin < 0.5)) throw PCCD::Invalid_input("fit_camera: the margin must lie in [0, 0.5)");
    Camera camera = oriented_camera(view);
    camera.width = width;
    camera.height = height;
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    std::size_t count = 0;
    const auto add = [&](const Eigen::Matrix3Xd& points, double radius) {
        for (Eigen::Index i = 0; i < points.cols(); ++i) {
            const Eigen::Vector3d p = points.col(i);
            if (!finite(p)) throw PCCD::Invalid_input("fit_camera: a point of the scene is not finite");
            const Eigen::Vector2d q(p.dot(camera.right), p.dot(camera.up));
            lo = lo.cwiseMin(q - Eigen::Vector2d::Constant(radius));
            hi = hi.cwiseMax(q + Eigen::Vector2d::Constant(radius));
            ++count;
        }
    };
    for (const Cloud_layer& c : scene.clouds) add(c.points, c.splat_radius);
    for (const Marker_layer& m : scene.markers) add(m.points, m.radius);
    if (count == 0) throw PCCD::Invalid_input("fit_camera: the scene has no point to frame");
    camera.centre = 0.5 * (lo + hi);
    const Eigen::Vector2d extent = (hi - lo).cwiseMax(Eigen::Vector2d::Constant(1e-12));
    const double usable = 1.0 - 2.0 * margin;
    camera.pixels_per_unit = std::min(usable * width / extent.x(), usable * height / extent.y());
    return camera;
}

namespace {

/// Draws the clouds of `scene` into `frame`; returns the largest splat radius (world units).
double draw_clouds(Frame& frame, const Scene& scene, const Camera& camera)
{
    const Light light(camera);
    double largest_splat = 0.0;
    for (const Cloud_layer& cloud : scene.clouds) {
        if (cloud.normals.cols() != 0 && cloud.normals.cols() != cloud.points.cols())
            throw PCCD::Invalid_input("render: a cloud has " + std::to_string(cloud.normals.cols()) + " normals for " +
                                      std::to_string(cloud.points.cols()) + " points");
        if (!(std::isfinite(cloud.splat_radius) && cloud.splat_radius > 0.0))
            throw PCCD::Invalid_input("render: the splat radius must be finite and > 0");
        largest_splat = std::max(largest_splat, cloud.splat_radius);
        const double radius_px = cloud.splat_radius * camera.pixels_per_unit;
        for (Eigen::Index i = 0; i < cloud.points.cols(); ++i) {
            const Eigen::Vector3d p = cloud.points.col(i);
            if (!finite(p)) continue;
            const double s = cloud.normals.cols() == 0 ? 0.75 : light.intensity(cloud.normals.col(i), camera);
            const Rgb shaded{scale_channel(cloud.colour.r, s), scale_channel(cloud.colour.g, s),
                             scale_channel(cloud.colour.b, s)};
            frame.disc(camera.project(p), radius_px, camera.depth(p), shaded);
        }
    }
    return largest_splat;
}

/// The marker radius in pixels and the depth by which a marker is lifted towards the eye. A marker
/// lies on the surfaces, and so do the centres of the splats around it: a splat that covers the
/// marker's pixel has its centre within a splat radius of it on the screen, which on a surface
/// tilted by 60 degrees from the screen (normal at 60 degrees from the view direction) is two splat
/// radii away on the surface and up to 1.73 radii nearer to the eye; the marker's own disc spans
/// its radius. Lifting the marker by two splat radii and its own keeps it in front of the surfaces
/// it lies on wherever they face the eye at less than 60 degrees, and still behind any surface
/// farther in front (another part of an object, more than two splats away).
std::pair<double, double> marker_radius_and_lift(const Marker_layer& markers, const Camera& camera, double largest_splat)
{
    if (!(std::isfinite(markers.radius) && markers.radius >= 0.0 && std::isfinite(markers.min_pixels) &&
          markers.min_pixels > 0.0))
        throw PCCD::Invalid_input("render: marker radii must be finite, the world radius >= 0 and the pixel radius > 0");
    const double radius_px = std::max(markers.radius * camera.pixels_per_unit, markers.min_pixels);
    return {radius_px, 2.0 * largest_splat + radius_px / camera.pixels_per_unit};
}

} // namespace

Image render(const Scene& scene, const Camera& camera, Rgb background)
{
    Frame frame(camera.width, camera.height, background);
    const double largest_splat = draw_clouds(frame, scene, camera);
    for (const Marker_layer& markers : scene.markers) {
        const auto [radius_px, lift] = marker_radius_and_lift(markers, camera, largest_splat);
        for (Eigen::Index i = 0; i < markers.points.cols(); ++i) {
            const Eigen::Vector3d p = markers.points.col(i);
            if (!finite(p)) continue;
            frame.disc(camera.project(p), radius_px, camera.depth(p) + lift, markers.colour);
        }
    }
    return std::move(frame.image);
}

std::size_t visible_markers(const Scene& scene, const Camera& camera)
{
    Frame frame(camera.width, camera.height, colour_background);
    const double largest_splat = draw_clouds(frame, scene, camera);
    std::size_t visible = 0;
    for (const Marker_layer& markers : scene.markers) {
        const double lift = marker_radius_and_lift(markers, camera, largest_splat).second;
        for (Eigen::Index i = 0; i < markers.points.cols(); ++i) {
            const Eigen::Vector3d p = markers.points.col(i);
            if (!finite(p)) continue;
            const Eigen::Vector2d q = camera.project(p);
            const int x = int(std::floor(q.x())), y = int(std::floor(q.y()));
            if (x < 0 || y < 0 || x >= camera.width || y >= camera.height) continue;
            if (camera.depth(p) + lift >= frame.depth[std::size_t(y) * std::size_t(camera.width) + std::size_t(x)])
                ++visible;
        }
    }
    return visible;
}

View choose_view(const Scene& scene, int width, int height, const View& preferred)
{
    std::size_t count = 0;
    for (const Marker_layer& m : scene.markers) count += std::size_t(m.points.cols());
    if (count == 0) return preferred;
    const auto angle_to_preferred = [&](const View& v) {
        const Eigen::Vector3d a = oriented_camera(v).toward_eye, b = oriented_camera(preferred).toward_eye;
        return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    };
    // Half the resolution is enough to tell which markers are hidden.
    const int w = std::max(16, width / 2), h = std::max(16, height / 2);
    std::vector<std::pair<View, std::size_t>> candidates{{preferred, 0}};
    for (double elevation = -30.0; elevation <= 60.0; elevation += 15.0)
        for (double azimuth = 0.0; azimuth < 360.0; azimuth += 15.0) candidates.push_back({{azimuth, elevation}, 0});
    std::size_t most = 0;
    for (auto& [view, visible] : candidates) {
        visible = visible_markers(scene, fit_camera(scene, view, w, h));
        most = std::max(most, visible);
    }
    // Among the views that show at least 90 % of the most markers seen, the nearest to the preferred.
    View best = preferred;
    double best_angle = std::numeric_limits<double>::infinity();
    for (const auto& [view, visible] : candidates)
        if (10 * visible >= 9 * most && angle_to_preferred(view) < best_angle) {
            best = view;
            best_angle = angle_to_preferred(view);
        }
    return best;
}

} // namespace pccd_render
