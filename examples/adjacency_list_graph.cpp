// A proximity graph of the user's own, stored in a boost::adjacency_list, as the graph of the
// geodesic surface (doc/manual/graphs.md, "Your own graph"): every point is joined to the points
// within 4 mean spacings (a unit-disk graph, which PCCD does not build itself); the CPSP map,
// the normals and the WLS surface are then built from it exactly as from PCCD's r-SIG, and f is
// compared with the torus' exact signed distance.
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/testing/Torus_shape.h>
#include <PCCD/Surface/Gaussian_weight.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/Surface/orient_normals.h>
#include <PCCD/sampling_radius.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

using Cloud = PCCD::Point_cloud<>;
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, double>>;
using Cpsp = PCCD::Close_pairs_shortest_paths;
using Distance = PCCD::Geodesic_distance<>;
using Surface = PCCD::WLS_surface<Distance, PCCD::Gaussian_weight>;

int main()
{
    const PCCD::testing::Torus_shape torus(1.0, 0.4);
    PCCD::Random_engine engine(8);
    const Cloud cloud(torus.sample(6000, engine).points);

    // The user's graph: i -- j when |p_i - p_j| <= 4 mean spacings, weighted by that distance.
    const double reach = 4.0 * cloud.mean_spacing();
    Graph graph(cloud.size());
    for (std::uint32_t i = 0; i < cloud.size(); ++i)
        for (const auto& n : cloud.within_radius(cloud.position(i), reach))
            if (n.index > i) boost::add_edge(i, n.index, std::sqrt(n.squared_distance), graph);

    // What Point_cloud_object does with its own graph, here with the user's.
    const double r = PCCD::sampling_radius(cloud);
    const PCCD::Gaussian_weight weight = PCCD::gaussian_weight(r); // support eta r(P), eta = 3
    const auto cpsp = std::make_shared<const Cpsp>(graph, boost::get(boost::edge_weight, graph), r);
    const Distance distance(cloud, cpsp);
    Eigen::Matrix3Xd normals = PCCD::estimate_normals(distance, weight).normals;
    const PCCD::Orientation_report report = PCCD::orient_normals(graph, cloud.coordinates(), normals);
    const Surface surface(distance, weight, normals, {}, PCCD::Surface_fit::sphere);

    std::cout << boost::num_edges(graph) << " edges, " << report.components << " component(s), r(P) = " << r << ", "
              << cpsp->num_entries() << " CPSP entries\n";
    // f at points up to half a spacing off the surface, against the exact signed distance.
    const double spacing = cloud.mean_spacing();
    double worst = 0.0;
    std::size_t undefined = 0;
    for (const double offset : {-0.5 * spacing, 0.0, 0.5 * spacing})
        for (std::uint32_t i = 0; i < cloud.size(); i += 60) {
            const Eigen::Vector3d x = cloud.position(i) + offset * normals.col(i);
            if (const std::optional<double> f = surface.value(x))
                worst = std::max(worst, std::abs(*f - torus.signed_distance(x)));
            else
                ++undefined;
        }
    std::cout << "largest |f - exact signed distance| near the surface: " << worst / spacing << " mean spacings, "
              << undefined << " undefined\n";
    return worst < 0.25 * spacing && undefined == 0 ? 0 : 1;
}
