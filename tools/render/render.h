// tools/render/render.h -- the small software renderer of `pccd render`, `pccd demo` and
// `pccd collide --png`: point clouds drawn as shaded splats (screen-aligned discs) with a z-buffer,
// one colour per cloud, marker points (e.g. the intersection curve) in a flat contrasting colour,
// an orthographic camera framing the whole scene automatically, and PNG output through stb's
// stb_image_write.h (Debian's libstb-dev). Tool code, not part of the library.
//
// Conventions: world y is up. The view direction is given by an azimuth around y and an elevation
// above the xz-plane (degrees); the camera looks from direction e(azimuth, elevation) towards the
// scene. Pixel (0, 0) is the top-left corner.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pccd_render {

/// An 8-bit RGB colour.
struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// The default palette: two objects, the intersection curve, the background.
inline constexpr Rgb colour_a{70, 130, 200};     // blue
inline constexpr Rgb colour_b{240, 190, 60};     // gold
inline constexpr Rgb colour_curve{220, 20, 30};  // red
inline constexpr Rgb colour_background{255, 255, 255};

/// A point cloud to draw, in world coordinates: each point a disc of radius `splat_radius` (world
/// units) facing the camera, shaded by its normal (a zero column: flat, unshaded).
struct Cloud_layer {
    Eigen::Matrix3Xd points;
    Eigen::Matrix3Xd normals;  // 3 x N, or empty for no shading
    Rgb colour = colour_a;
    double splat_radius = 0.0;  // world units, > 0
};

/// Marker points (e.g. on the intersection curve), in world coordinates: flat discs of radius
/// max(`radius` in world units, `min_pixels`), drawn over the clouds they lie on but still hidden
/// behind surfaces in front of them.
struct Marker_layer {
    Eigen::Matrix3Xd points;
    Rgb colour = colour_curve;
    double radius = 0.0;       // world units, >= 0
    double min_pixels = 2.5;   // pixels, > 0
};

/// What to draw.
struct Scene {
    std::vector<Cloud_layer> clouds;
    std::vector<Marker_layer> markers;
};

/// The direction the camera looks from, in degrees.
struct View {
    double azimuth = 30.0;
    double elevation = 20.0;
};

/// "AZ,EL" in degrees, or one of front (0,0), back (180,0), side (90,0), top (0,90), iso (45,35).
/// \throws PCCD::Invalid_input for anything else, or an elevation outside [-90, 90].
View parse_view(const std::string& text);

/// "WxH", each in [16, 8192]. \throws PCCD::Invalid_input otherwise.
std::pair<int, int> parse_size(const std::string& text);

/// An orthographic camera: world point -> pixel coordinates and depth.
struct Camera {
    Eigen::Vector3d right, up, toward_eye;  // orthonormal; toward_eye points from the scene to the eye
    Eigen::Vector2d centre;                 // (right, up) coordinates of the image centre
    double pixels_per_unit = 1.0;
    int width = 0, height = 0;

    /// Pixel coordinates (x to the right, y down; pixel (i, j) covers [i, i+1) x [j, j+1)).
    Eigen::Vector2d project(const Eigen::Vector3d& p) const;
    /// Larger is nearer to the eye.
    double depth(const Eigen::Vector3d& p) const { return p.dot(toward_eye); }
};

/// The camera looking from `view` that frames every point of `scene` (splats and markers included)
/// in a `width` x `height` image with a margin of `margin` (fraction of the image) on each side.
/// \throws PCCD::Invalid_input when the scene has no point, a size is not positive, or a coordinate
///         is not finite.
Camera fit_camera(const Scene& scene, const View& view, int width, int height, double margin = 0.05);

/// An RGB image, row-major from the top-left corner.
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // 3 bytes a pixel

    Rgb at(int x, int y) const
    {
        const std::size_t i = 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

/// Draws `scene` through `camera` over `background`.
/// \throws PCCD::Invalid_input when a cloud's normals are neither empty nor 3 x N, or a splat radius
///         is not finite and > 0.
Image render(const Scene& scene, const Camera& camera, Rgb background = colour_background);

/// How many markers of `scene` are visible through `camera` (not hidden behind a splat).
std::size_t visible_markers(const Scene& scene, const Camera& camera);

/// The automatic view: among `preferred` and the directions every 15 degrees in azimuth and
/// elevation (-30 to 60), those from which at least 90 % of the most markers seen are visible, the
/// one nearest to `preferred`; `preferred` itself when the scene has no marker.
View choose_view(const Scene& scene, int width, int height, const View& preferred = View{});

/// Writes `image` as a PNG file. \throws PCCD::File_error when it cannot be written.
void write_png(const std::string& path, const Image& image);

} // namespace pccd_render
