// Tests of Point_cloud_object (doc/design.md, "Map, in data-flow order": the whole preprocessed
// object): one-call preprocessing, its reported state, and saving and loading (bit-for-bit round
// trip, corrupted and foreign files rejected).
// Also covers Point_cloud_object_class.h, Point_cloud_object_file.h, Point_cloud_object_options.h, Point_cloud_object_preprocessing.h: the test cases below exercise what they declare.
#include "Hierarchy/hierarchy_compare.h"
#include "surface_test_helpers.h"

#include <PCCD/Point_cloud_object.h>
#include <PCCD/Point_cloud_object_class.h>
#include <PCCD/Point_cloud_object_file.h>
#include <PCCD/Point_cloud_object_options.h>
#include <PCCD/Point_cloud_object_preprocessing.h>
#include <PCCD/make_point_cloud_object.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

using namespace pccd_test;

namespace {

/// A readable property map from an index to a row of a table (points or normals).
struct Table_map {
    const std::vector<Eigen::Vector3d>* rows;
    friend const Eigen::Vector3d& get(const Table_map& m, std::size_t i) { return (*m.rows)[i]; }
};

} // namespace

TEST_CASE("the CPSP map's default bound is the surface's default support", "[surface]")
{
    // A map built with Cpsp_options{} serves a surface with the default bandwidth options.
    CHECK(PCCD::Cpsp_options{}.support == PCCD::Bandwidth_options{}.eta);
}

TEST_CASE("a point cloud object reports its preprocessed state", "[surface]")
{
    const auto sample = sample_shape(test_torus(), 3000, 0.1, 91);
    const PCCD::Point_cloud_object<> object(columns(sample.points));
    CHECK(object.size() == 3000);
    CHECK(object.graph().num_vertices() == 3000);
    CHECK(object.cpsp().size() == 3000);
    CHECK(object.sampling_radius() > 0.0);
    CHECK(object.eta() == Approx(3.0));
    CHECK(object.theta_eps() == 1e-2);
    CHECK(object.bandwidth() == Approx(3.0 * object.sampling_radius() / std::sqrt(-std::log(1e-2))));
    CHECK(object.cpsp().bound() >= object.weight().support_radius() * (1 - 1e-12));
    CHECK_FALSE(object.normals_given());
    CHECK(object.orientation().components >= 1);
    const auto& t = object.timings();
    for (double ms : {t.kd_tree, t.graph, t.sampling_radius, t.cpsp, t.normals}) CHECK(ms >= 0.0);
    // A user bandwidth is used as given; eta follows from it.
    const PCCD::Point_cloud_object<> given(columns(sample.points), PCCD::Identity_point_map<Eigen::Vector3d>(),
                                           {.graph = PCCD::Graph_kind::knn, .bandwidth = {.bandwidth = 0.05}});
    CHECK(given.bandwidth() == 0.05);
    CHECK(given.graph().kind() == PCCD::Graph_kind::knn);
    CHECK(given.eta() == Approx(0.05 * std::sqrt(-std::log(1e-2)) / given.sampling_radius()));
}

TEST_CASE("a saved point cloud object loads back identical", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 2000, 0.1, 93);
    const PCCD::Point_cloud_object<> object(columns(sample.points));
    const std::string path = std::string(PCCD_TEST_TMP_DIR) + "/sphere.pccdobj";
    object.save(path);
    const auto loaded = PCCD::Point_cloud_object<>::load(path);
    CHECK(loaded.size() == object.size());
    CHECK(loaded.cloud().coordinates() == object.cloud().coordinates());
    CHECK(loaded.normals() == object.normals());
    CHECK(loaded.graph() == object.graph());
    CHECK(loaded.cpsp() == object.cpsp());
    CHECK(loaded.sampling_radius() == object.sampling_radius());
    CHECK(loaded.bandwidth() == object.bandwidth());
    CHECK(loaded.theta_eps() == object.theta_eps());
    CHECK(loaded.orientation().flipped == object.orientation().flipped);
    CHECK(loaded.timings().graph == object.timings().graph);
    for (const Query& q : queries_near(unit_sphere(), 100, 0.05, 3)) {
        CHECK(loaded.surface().evaluate(q.x).value == object.surface().evaluate(q.x).value);
        CHECK(loaded.euclidean_surface().evaluate(q.x).value == object.euclidean_surface().evaluate(q.x).value);
    }
    // The hierarchy comes back from the stored layout: the same tree, boxes, reaches and slabs.
    using pccd_test::require_same_hierarchy;
    require_same_hierarchy(loaded.hierarchy(), object.hierarchy());
    // A sphere tree of 4-point leaves is stored as such; asked for other options, load() builds those.
    const PCCD::Point_cloud_hierarchy_options spheres{.leaf_size = 4, .volume = PCCD::Bounding_volume::sphere};
    const PCCD::Point_cloud_object<> sphere_object(columns(sample.points), {.hierarchy = spheres});
    sphere_object.save(path);
    const auto sphere_loaded = PCCD::Point_cloud_object<>::load(path);
    CHECK(sphere_loaded.hierarchy().volume() == PCCD::Bounding_volume::sphere);
    require_same_hierarchy(sphere_loaded.hierarchy(), sphere_object.hierarchy());
    require_same_hierarchy(PCCD::Point_cloud_object<>::load(path, spheres).hierarchy(), sphere_object.hierarchy());
    require_same_hierarchy(PCCD::Point_cloud_object<>::load(path, {}).hierarchy(), object.hierarchy());
    // A bad option is the caller's error, not the file's.
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>::load(path, {.leaf_size = 0}), Catch::Contains("leaf_size must be >= 1"));
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(path, {.threads = 0u}), PCCD::Invalid_input);
    object.save(path);

    // Corruption anywhere is caught by the checksum; a foreign or missing file is named.
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string bad = std::string(PCCD_TEST_TMP_DIR) + "/corrupt.pccdobj";
    for (std::size_t position : {std::size_t(100), bytes.size() / 2, bytes.size() - 20}) {
        std::string copy = bytes;
        copy[position] = char(copy[position] ^ 0x5a);
        std::ofstream(bad, std::ios::binary).write(copy.data(), std::streamsize(copy.size()));
        CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(bad), PCCD::File_error);
    }
    std::ofstream(bad, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 3));
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(bad), PCCD::File_error);
    std::ofstream(bad, std::ios::binary) << "OFF\n3 1 0\n";
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>::load(bad), Catch::Contains("not a PCCD object file"));
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(std::string(PCCD_TEST_TMP_DIR) + "/missing.pccdobj"),
                    PCCD::File_error);
}

TEST_CASE("a point cloud object from a point file's data uses its normals when it has them", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 1500, 0.0, 97);
    PCCD::Point_data data;
    data.points = columns(sample.points);
    // Without normals: the same object as from the points alone (normals propagated).
    const PCCD::Point_cloud_object<> from_points(data.points);
    const PCCD::Point_cloud_object<> from_data(data);
    CHECK_FALSE(from_data.normals_given());
    CHECK(from_data.normals() == from_points.normals());
    // With normals pointing inwards (a file whose normals point into the sphere): every normal of the
    // object takes that sign, the opposite of the propagated (outward) orientation.
    for (const Eigen::Vector3d& p : data.points) data.normals.push_back(-2.0 * p);
    const PCCD::Point_cloud_object<> oriented(data);
    CHECK(oriented.normals_given());
    std::size_t inward = 0;
    for (Eigen::Index i = 0; i < oriented.normals().cols(); ++i)
        inward += oriented.normals().col(i).dot(data.points[oriented.input_index(std::size_t(i))]) < 0.0;
    CHECK(inward == data.points.size());
    // Normals, but not one per point.
    data.normals.pop_back();
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>(data), PCCD::Invalid_input);
}

TEST_CASE("a point cloud object takes a file's normals as hints: zero or NaN normals are missing ones", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 1500, 0.0, 98);
    PCCD::Point_data data;
    data.points = columns(sample.points);
    const PCCD::Point_cloud_object<> from_points(data.points);
    // Every normal zero (as in files that store 0 0 0 for "unknown"): the object is built as without
    // normals, the normals propagated over the graph and facing outward.
    data.normals.assign(data.points.size(), Eigen::Vector3d::Zero());
    const PCCD::Point_cloud_object<> all_zero(data);
    CHECK(all_zero.normals_given());
    CHECK(all_zero.normals() == from_points.normals());
    CHECK(all_zero.orientation().hints_used == 0);
    CHECK(all_zero.orientation().hints_ignored == data.points.size());
    CHECK(all_zero.orientation().unhinted_components == all_zero.orientation().components);
    CHECK(all_zero.orientation().flipped == from_points.orientation().flipped);
    // Every 7th point with an inward normal (of any length), every 11th of the others NaN, the rest
    // zero: every normal of the object points inward, the hints' side, against the outward rule.
    std::size_t given = 0;
    for (std::size_t i = 0; i < data.points.size(); ++i) {
        if (i % 7 == 0) {
            data.normals[i] = -(0.5 + double(i % 5)) * data.points[i];
            ++given;
        } else if (i % 11 == 0) {
            data.normals[i] = Eigen::Vector3d(std::nan(""), 0.0, 1.0);
        }
    }
    // The same through the constructor with a normal map (items are indices into the tables).
    std::vector<std::size_t> items(data.points.size());
    std::iota(items.begin(), items.end(), std::size_t(0));
    for (const PCCD::Point_cloud_object<>& object :
         {PCCD::Point_cloud_object<>(data),
          PCCD::Point_cloud_object<>(items, Table_map{&data.points}, Table_map{&data.normals})}) {
        CHECK(object.normals_given());
        CHECK(object.orientation().hints_used == given);
        CHECK(object.orientation().hints_ignored == data.points.size() - given);
        CHECK(object.orientation().unhinted_components == 0);
        CHECK(object.orientation().unoriented == 0);
        std::size_t inward = 0;
        for (Eigen::Index i = 0; i < object.normals().cols(); ++i)
            inward += object.normals().col(i).dot(data.points[object.input_index(std::size_t(i))]) < 0.0;
        CHECK(inward == data.points.size());
        // f has the sign the hints chose: positive inside the sphere, negative outside.
        REQUIRE(object.surface().value(Eigen::Vector3d(0.0, 0.0, 0.95)).has_value());
        CHECK(*object.surface().value(Eigen::Vector3d(0.0, 0.0, 0.95)) > 0.0);
        REQUIRE(object.surface().value(Eigen::Vector3d(0.0, 0.0, 1.05)).has_value());
        CHECK(*object.surface().value(Eigen::Vector3d(0.0, 0.0, 1.05)) < 0.0);
    }
}

TEST_CASE("A thread count beyond what TBB can take is refused with a message, not a crash", "[surface][robustness]")
{
    const auto sample = pccd_test::sample_shape(pccd_test::unit_sphere(), 300, 0.0, 1);
    PCCD::Point_cloud_object_options options;
    options.threads = 1u << 20; // TBB's task_arena crashed on about 2^18
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>(pccd_test::columns(sample.points),
                                                 PCCD::Identity_point_map<Eigen::Vector3d>(), options),
                      Catch::Contains("threads = 1048576 exceeds"));
    options.threads = PCCD::internal::max_worker_threads; // the largest accepted value still works
    CHECK(PCCD::Point_cloud_object<>(pccd_test::columns(sample.points), PCCD::Identity_point_map<Eigen::Vector3d>(),
                                     options)
              .size() == 300);
}

TEST_CASE("Point_cloud_object stores its points in spatial order and maps them back", "[surface]")
{
    // A sample in random order (the samplers draw points independently), plus two stray points.
    const auto sample = sample_shape(unit_sphere(), 3000, 0.0, 77);
    std::vector<Eigen::Vector3d> given = columns(sample.points);
    given.insert(given.begin() + 1000, Eigen::Vector3d(40.0, 0.0, 0.0));
    given.push_back(Eigen::Vector3d(0.0, -40.0, 0.0));
    // One bandwidth for both: the automatic one rests on r(P), a Monte-Carlo estimate whose random
    // draws are point indices, and so differs (by about 1 %) between two orders of the points.
    const PCCD::Bandwidth_options bandwidth{.bandwidth = 0.08};
    const PCCD::Point_cloud_object<> object(given, PCCD::Identity_point_map<Eigen::Vector3d>(), {.bandwidth = bandwidth});
    const PCCD::Point_cloud_object<> unordered(given, PCCD::Identity_point_map<Eigen::Vector3d>(),
                                               {.bandwidth = bandwidth, .spatial_order = false});
    // The outliers are named by their index among the points given, in both.
    CHECK(object.scan().outliers == std::vector<std::uint32_t>{1000, 3001});
    CHECK(unordered.scan().outliers == object.scan().outliers);
    REQUIRE(object.size() == 3000);
    // input_index is a bijection onto the points kept, and each point is the one given.
    std::vector<bool> seen(given.size(), false);
    for (std::size_t i = 0; i < object.size(); ++i) {
        const std::uint32_t k = object.input_index(i);
        REQUIRE(k < given.size());
        CHECK_FALSE(seen[k]);
        seen[k] = true;
        CHECK(object.cloud().position(std::uint32_t(i)) == given[k]);
        CHECK(unordered.cloud().position(std::uint32_t(i)) != Eigen::Vector3d(40.0, 0.0, 0.0));
    }
    CHECK_FALSE(seen[1000]);
    CHECK_FALSE(seen[3001]);
    // Without the spatial order the points keep the order given (less the outliers).
    for (std::size_t i = 0; i < unordered.size(); ++i) CHECK(unordered.input_index(i) == (i < 1000 ? i : i + 1));
    // Spatial order: consecutive points are near (here 12x nearer on average than in the order given).
    auto mean_step = [](const PCCD::Point_cloud_object<>& o) {
        double sum = 0.0;
        for (std::uint32_t i = 1; i < o.size(); ++i) sum += (o.cloud().position(i) - o.cloud().position(i - 1)).norm();
        return sum / double(o.size() - 1);
    };
    INFO("mean step: spatial " << mean_step(object) << ", given " << mean_step(unordered));
    CHECK(mean_step(object) < 0.2 * mean_step(unordered));
    // The surface does not depend on the order of the points: same f (up to the rounding of sums in
    // another order) and normals at random points near the sphere.
    PCCD::Random_engine engine(5);
    for (int k = 0; k < 200; ++k) {
        const Eigen::Vector3d direction(PCCD::uniform_real(engine, -1, 1), PCCD::uniform_real(engine, -1, 1),
                                        PCCD::uniform_real(engine, -1, 1));
        const Eigen::Vector3d x = direction.normalized() * PCCD::uniform_real(engine, 0.95, 1.05);
        const auto e = object.surface().evaluate(x), u = unordered.surface().evaluate(x);
        REQUIRE(e.status == u.status);
        if (!e.defined()) continue;
        CHECK(e.value == Approx(u.value).margin(1e-12));
        CHECK(e.normal.dot(u.normal) > 1.0 - 1e-9);
        CHECK(object.input_index(e.nearest) == unordered.input_index(u.nearest));
    }
    // save() and load() keep the map.
    const std::string path = std::string(PCCD_TEST_TMP_DIR) + "/spatial_order.pccd";
    object.save(path);
    const auto loaded = PCCD::Point_cloud_object<>::load(path);
    CHECK(loaded.input_indices() == object.input_indices());
    CHECK(loaded.scan().outliers == object.scan().outliers);
}

TEST_CASE("a point cloud object from a coordinate matrix equals the one from a range of points", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 1200, 0.0, 41);
    const std::vector<Eigen::Vector3d> points = columns(sample.points);
    const PCCD::Point_cloud_object_options options{.graph = PCCD::Graph_kind::knn, .threads = 1};
    // The reference: the generic form, items and an explicit point map.
    const PCCD::Point_cloud_object<> reference(points, PCCD::Identity_point_map<Eigen::Vector3d>(), options);
    for (const PCCD::Point_cloud_object<>& object :
         {PCCD::Point_cloud_object<>(sample.points, options), PCCD::Point_cloud_object<>(points, options),
          PCCD::make_point_cloud_object(sample.points, options)}) {
        CHECK(object.cloud().coordinates() == reference.cloud().coordinates());
        CHECK(object.graph() == reference.graph());
        CHECK(object.normals() == reference.normals());
        CHECK_FALSE(object.normals_given());
    }
    // With normals as hints, pointing inwards: the matrix form, the two ranges, the factory and a
    // point file's data all give every normal that sign.
    const Eigen::Matrix3Xd inward = -sample.points;
    const std::vector<Eigen::Vector3d> inward_rows = columns(inward);
    PCCD::Point_data data;
    data.points = points;
    data.normals = inward_rows;
    const PCCD::Point_cloud_object<> from_data(data, options);
    for (const PCCD::Point_cloud_object<>& object :
         {PCCD::Point_cloud_object<>(sample.points, inward, options),
          PCCD::Point_cloud_object<>(points, inward_rows, options),
          PCCD::make_point_cloud_object(sample.points, inward, options)}) {
        CHECK(object.normals_given());
        CHECK(object.normals() == from_data.normals());
        std::size_t pointing_in = 0;
        for (Eigen::Index i = 0; i < object.normals().cols(); ++i)
            pointing_in += object.normals().col(i).dot(sample.points.col(object.input_index(std::size_t(i)))) < 0.0;
        CHECK(pointing_in == points.size());
    }
    // Not one normal per point; too few points; a point that is not finite.
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>(sample.points, Eigen::Matrix3Xd(3, 2)),
                      Catch::Contains("2 normals for 1200 points"));
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>(Eigen::Matrix3Xd(3, 1)), PCCD::Invalid_input);
    Eigen::Matrix3Xd bad = sample.points;
    bad(1, 7) = std::nan("");
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>(bad), PCCD::Invalid_input);
}

TEST_CASE("the bandwidth is automatic unless set, and a set bandwidth must be finite and > 0", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 800, 0.0, 43);
    const PCCD::Point_cloud_object<> automatic(sample.points);
    CHECK(automatic.bandwidth() == Approx(3.0 * automatic.sampling_radius() / std::sqrt(-std::log(1e-2))));
    CHECK(PCCD::kernel_bandwidth(2.0, {.eta = 3.0, .theta_eps = 1e-2}) == Approx(6.0 / std::sqrt(-std::log(1e-2))));
    CHECK(PCCD::kernel_bandwidth(2.0, {.bandwidth = 0.3}) == 0.3);
    // 0 no longer means "automatic": every value given is checked.
    for (const double h : {0.0, -0.1, std::nan(""), HUGE_VAL}) {
        INFO("h = " << h);
        CHECK_THROWS_WITH(PCCD::Point_cloud_object<>(sample.points, {.bandwidth = {.bandwidth = h}}),
                          Catch::Contains("the given bandwidth is") && Catch::Contains("leave it unset"));
    }
}

TEST_CASE("a stage's own thread count stands; an unset one takes the object's", "[surface][threads]")
{
    // The rule as a function: knn keeps its 1, every unset stage takes the object's 2.
    const PCCD::Point_cloud_object_options resolved = PCCD::resolve_threads({.knn = {.threads = 1}, .threads = 2});
    CHECK(resolved.knn.threads == 1u);
    CHECK(resolved.sphere_of_influence.threads == 2u);
    CHECK(resolved.sampling_radius.threads == 2u);
    CHECK(resolved.domain.threads == 2u);
    CHECK(resolved.outliers.threads == 2u);
    CHECK(resolved.threads == 2u);
    // Nothing set: every stage stays unset (all available threads).
    const PCCD::Point_cloud_object_options none = PCCD::resolve_threads({});
    CHECK_FALSE(none.knn.threads.has_value());
    CHECK_FALSE(none.domain.threads.has_value());

    // The object applies it: a stage's own (invalid) count is not replaced by the object's valid one.
    const auto sample = sample_shape(unit_sphere(), 600, 0.0, 44);
    CHECK_THROWS_WITH(
        PCCD::Point_cloud_object<>(sample.points, {.graph = PCCD::Graph_kind::knn, .knn = {.threads = 0}, .threads = 2}),
        Catch::Contains("threads = 0"));
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>(sample.points, {.threads = 0}), Catch::Contains("threads = 0"));
    // And the result never depends on the counts.
    const PCCD::Point_cloud_object<> one(sample.points, {.graph = PCCD::Graph_kind::knn, .threads = 1});
    const PCCD::Point_cloud_object<> mixed(sample.points,
                                           {.graph = PCCD::Graph_kind::knn, .knn = {.threads = 1}, .threads = 2});
    CHECK(mixed.graph() == one.graph());
    CHECK(mixed.normals() == one.normals());
}

TEST_CASE("the progress callback hears every stage start and end, in order", "[surface]")
{
    // Noise heavy enough that the noise estimate asks for a wider kernel: the CPSP map and the
    // normals then run twice.
    for (const double noise : {0.0, 0.6}) {
        INFO("noise " << noise << " spacings");
        const auto sample = sample_shape(test_torus(), 3000, noise, 45);
        std::vector<PCCD::Preprocessing_progress> heard;
        const PCCD::Point_cloud_object<> object(
            sample.points, {.progress = [&](const PCCD::Preprocessing_progress& p) { heard.push_back(p); }});
        using S = PCCD::Preprocessing_stage;
        std::vector<S> expected{S::kd_tree, S::outliers, S::graph, S::sampling_radius, S::cpsp_map, S::normals};
        const bool wider = object.eta() > 3.0 * (1.0 + 1e-9);
        if (wider) expected.insert(expected.end(), {S::cpsp_map, S::normals});
        expected.insert(expected.end(), {S::orientation, S::domain, S::hierarchy});
        REQUIRE(heard.size() == 2 * expected.size());
        double sum = 0.0;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            INFO("stage " << k << ": " << PCCD::to_string(expected[k]));
            const PCCD::Preprocessing_progress& start = heard[2 * k];
            const PCCD::Preprocessing_progress& end = heard[2 * k + 1];
            CHECK(start.stage == expected[k]);
            CHECK_FALSE(start.finished);
            CHECK(start.milliseconds == 0.0);
            CHECK(end.stage == expected[k]);
            CHECK(end.finished);
            CHECK(end.milliseconds >= 0.0);
            CHECK(start.points == end.points);
            CHECK(end.points == (k < 2 ? object.scan().input_points : object.size()));
            sum += end.milliseconds;
        }
        // The stages' times are the object's timings, split finer.
        const PCCD::Preprocessing_times& t = object.timings();
        CHECK(sum == Approx(t.kd_tree + t.outliers + t.graph + t.sampling_radius + t.cpsp + t.normals + t.hierarchy));
        if (noise > 0.0) CHECK(wider); // the case this loop is for
    }
}
