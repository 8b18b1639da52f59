// A table cloth falls onto a table: a kinetic AABB tree follows it through events and answers a
// collision query and a ray query at 30 frames per second (doc/manual/kinetic.md).
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/testing/scenes/Cloth_scene.h>

#include <iostream>
#include <utility>
#include <vector>

using Flightplan = PCCD::Piecewise_linear_flightplan;
using Tree = PCCD::Kinetic_AABB_tree<Flightplan, PCCD::Kinetic_triangle>;

int main()
{
    // A recorded animation: one key-framed flightplan per cloth vertex, plus the table (at rest).
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 1684, .duration = 2.0});
    Tree cloth(scene.flightplans, scene.primitives, scene.start_time);
    Tree table(scene.obstacle_flightplans, scene.obstacle_triangles, scene.start_time);

    std::vector<std::pair<Tree::Index, Tree::Index>> contacts;
    const PCCD::Kinetic_ray down{.origin = {0.1, 0.1, 1.0}, .direction = {0.0, 0.0, -1.0}};
    for (int frame = 1; frame <= 60; ++frame) {
        const double t = frame / 30.0;
        cloth.advance_to(t); // processes only the events before t, however often it is called
        table.advance_to(t);
        cloth.overlapping_pairs(table, contacts, 0.005);
        if (frame % 15 == 0) {
            const auto hit = cloth.first_hit(down);
            std::cout << "t = " << t << " s: " << contacts.size() << " cloth/table box contacts, ray hits "
                      << (hit ? "triangle " + std::to_string(hit->primitive) : std::string("nothing"))
                      << ", events so far " << cloth.statistics().events << '\n';
        }
    }
    // The tree is valid at every time: its root box is the cloth's bounding box now.
    const auto box = cloth.box(cloth.root());
    std::cout << "cloth spans z in [" << box.min().z() << ", " << box.max().z() << "] after "
              << cloth.statistics().bv_updates << " BV updates (a bottom-up refit would have done "
              << 60 * cloth.node_count() << ")\n";
}
