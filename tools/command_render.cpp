// pccd render A [B] [--transform-a 12 numbers] [--transform-b 12 numbers] [--normalize]
//   [--points P.ply] [--intersect] [--out F.png] [--size WxH] [--view auto|AZ,EL|front|back|side|top|iso]:
// a picture of one or two posed point clouds (shaded splats, A blue, B gold) and of points on their
// intersection (red): read from a file (e.g. written by `pccd collide --mode all --out`) or computed
// with --intersect (intersection_points, as `pccd collide --mode all`). The camera frames the whole
// scene from the given direction, or (auto) from one that shows the intersection points. Point files
// make geodesic objects; prepared object files (pccd prepare) are loaded as their kind. Implements
// doc/manual/cli_collide.md, "Pictures".
#include "commands.h"
#include "intersection_support.h"
#include "render_objects.h"
#include "transform_options.h"

#include <PCCD/IO/read_points.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace pccd_tool {
namespace {

struct Render_options {
    std::string file_a;
    std::string file_b;
    std::vector<std::string> transform_a;
    std::vector<std::string> transform_b;
    bool normalize = false;
    std::string points;
    bool intersect = false;
    std::string out = "pccd-render.png";
    std::string size = "800x600";
    std::string view = "auto";
};

/// The picture of A (and B when `b` is not null) and its summary line.
template <class A, class B>
void draw(const Render_options& o, const std::optional<pccd_render::View>& requested_view, int width, int height,
          const PCCD::Rigid_transform_3<double>& pose_a, const PCCD::Rigid_transform_3<double>& pose_b,
          const std::optional<PCCD::Point_data>& markers, const Prepared_object<A>& a, const Prepared_object<B>* b)
{
    pccd_render::Scene scene;
    scene.clouds.push_back(cloud_layer(a.object, pose_a, pccd_render::colour_a));
    if (b) scene.clouds.push_back(cloud_layer(b->object, pose_b, pccd_render::colour_b));
    const double marker_radius = 0.5 * scene.clouds.front().splat_radius;
    std::size_t curve_points = 0;
    if (markers) {
        pccd_render::Marker_layer layer;
        layer.points.resize(3, Eigen::Index(markers->points.size()));
        for (std::size_t i = 0; i < markers->points.size(); ++i) layer.points.col(Eigen::Index(i)) = markers->points[i];
        layer.radius = marker_radius;
        curve_points += markers->points.size();
        scene.markers.push_back(std::move(layer));
    }
    if (o.intersect) {
        const PCCD::Intersection_result result =
            PCCD::intersection_points(a.object, pose_a, b->object, pose_b, PCCD::Intersection_options{});
        curve_points += result.points.size();
        scene.markers.push_back(curve_layer(result.points, marker_radius));
        std::printf("intersection_points: %s, %zu points\n", result.intersects ? "intersecting" : "separate",
                    result.points.size());
    }
    const pccd_render::View view = render_to_png(scene, requested_view, width, height, o.out);
    std::printf("wrote %s (%dx%d, view %g,%g): A %s (%zu points, blue)", std::filesystem::absolute(o.out).c_str(),
                width, height, view.azimuth, view.elevation, o.file_a.c_str(), a.object.size());
    if (b) std::printf(", B %s (%zu points, gold)", o.file_b.c_str(), b->object.size());
    if (!scene.markers.empty()) std::printf(", %zu intersection points (red)", curve_points);
    std::printf("\n");
}

void run_render(const Render_options& o)
{
    // Everything that can be checked is checked before the (slow) preprocessing.
    const std::optional<pccd_render::View> requested_view = view_option(o.view);
    const auto [width, height] = pccd_render::parse_size(o.size);
    const PCCD::Rigid_transform_3<double> pose_a = option_transform(o.transform_a, "--transform-a");
    const PCCD::Rigid_transform_3<double> pose_b = option_transform(o.transform_b, "--transform-b");
    if (o.file_b.empty() && !o.transform_b.empty())
        throw PCCD::Invalid_input("--transform-b given without a second object B");
    if (o.intersect && o.file_b.empty()) throw PCCD::Invalid_input("--intersect needs two objects, A and B");
    std::optional<PCCD::Point_data> markers;
    if (!o.points.empty()) markers = PCCD::IO::read_points(o.points);

    // Point files make geodesic objects; a prepared object file (pccd prepare) is loaded as its kind.
    const Object_input input_a = read_object_input(o.file_a, o.normalize);
    std::optional<Object_input> input_b;
    if (!o.file_b.empty()) input_b = read_object_input(o.file_b, o.normalize);
    with_kernel(input_a.kernel_or("geodesic"), input_a.size(), [&]<class A>(std::type_identity<A>) {
        const Prepared_object<A> a = make_object<A>(input_a, {});
        if (!input_b) {
            draw(o, requested_view, width, height, pose_a, pose_b, markers, a, static_cast<const Prepared_object<A>*>(nullptr));
            return;
        }
        with_kernel(input_b->kernel_or("geodesic"), input_b->size(), [&]<class B>(std::type_identity<B>) {
            const Prepared_object<B> b = make_object<B>(*input_b, {});
            draw(o, requested_view, width, height, pose_a, pose_b, markers, a, &b);
        });
    });
}

} // namespace

void register_render(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "render", "Draw one or two posed point clouds and their intersection points into a PNG picture");
    auto o = std::make_shared<Render_options>();
    cmd->add_option("A", o->file_a,
                    "First point file (.ply, .off, .xyz, .pwn; a mesh gives its vertices), or a prepared object file")
        ->required();
    cmd->add_option("B", o->file_b, "Optional second point file or prepared object file");
    cmd->add_option("--transform-a", o->transform_a,
                    "Pose of A: 12 numbers, the 3x4 matrix [R | t] row by row (default: identity)")
        ->expected(1, 12);
    cmd->add_option("--transform-b", o->transform_b, "Pose of B, as --transform-a")->expected(1, 12);
    cmd->add_flag("--normalize", o->normalize,
                  "Centre and scale each object into [-1,1]^3 (bounding box) before preprocessing");
    cmd->add_option("--points", o->points,
                    "Intersection points to draw in red (.ply, .off, .xyz), e.g. from pccd collide --mode all --out");
    cmd->add_flag("--intersect", o->intersect, "Compute the intersection points of A and B and draw them in red");
    cmd->add_option("--out", o->out, "PNG file to write (default pccd-render.png)");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default 800x600)");
    cmd->add_option("--view", o->view,
                    "Direction the camera looks from: AZIMUTH,ELEVATION in degrees (y is up), front, back, side, top, "
                    "iso, or auto (default: near 30,20, turned to show the intersection points)");
    cmd->callback([o] { run_render(*o); });
}

} // namespace pccd_tool
