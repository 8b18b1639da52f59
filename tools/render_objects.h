// tools/render_objects.h -- from PCCD's objects to the renderer's layers (tools/render/render.h):
// a preprocessed object under a pose becomes a cloud of shaded splats, the points of an
// intersection query become markers, and render_to_png() frames, draws and writes the scene. Used
// by `pccd render`, `pccd demo` and `pccd collide --png`.
#pragma once

#include "render/render.h"

#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Rigid_transform_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace pccd_tool {

/// The splat radius of a cloud: 2 mean spacings. A disc of area A / N has radius 0.56 sqrt(A / N)
/// while the nearest-neighbour distance of a uniform random sample averages 0.5 sqrt(A / N), so
/// discs of about one spacing would cover the surface only if the sample were regular; the gaps of
/// a random one need twice that to close.
inline double splat_radius(const PCCD::Point_cloud<>& cloud)
{
    return cloud.size() >= 2 ? 2.0 * cloud.mean_spacing() : 0.01;
}

/// The object's points and oriented normals under `pose`, in one colour.
template <class Object>
pccd_render::Cloud_layer cloud_layer(const Object& object, const PCCD::Rigid_transform_3<double>& pose,
                                     pccd_render::Rgb colour)
{
    pccd_render::Cloud_layer layer;
    layer.points = pose.transform_points(object.cloud().coordinates());
    layer.normals = pose.rotation() * object.normals();
    layer.colour = colour;
    layer.splat_radius = splat_radius(object.cloud());
    return layer;
}

/// The positions of intersection points (world coordinates) as markers of radius `radius`.
inline pccd_render::Marker_layer curve_layer(const std::vector<PCCD::Intersection_point>& points, double radius)
{
    pccd_render::Marker_layer layer;
    layer.points.resize(3, Eigen::Index(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) layer.points.col(Eigen::Index(i)) = points[i].position;
    layer.radius = radius;
    return layer;
}

/// Frames `scene` from `view` (none: the automatic view, pccd_render::choose_view), draws it at
/// `width` x `height` and writes it to `path` (PNG); returns the view used.
inline pccd_render::View render_to_png(const pccd_render::Scene& scene, const std::optional<pccd_render::View>& view,
                                       int width, int height, const std::string& path)
{
    const pccd_render::View used = view ? *view : pccd_render::choose_view(scene, width, height);
    const pccd_render::Camera camera = pccd_render::fit_camera(scene, used, width, height);
    pccd_render::write_png(path, pccd_render::render(scene, camera));
    return used;
}

/// The --view option: "auto" (none), else pccd_render::parse_view.
inline std::optional<pccd_render::View> view_option(const std::string& text)
{
    if (text == "auto") return std::nullopt;
    return pccd_render::parse_view(text);
}

} // namespace pccd_tool
