// world_reference: the brute force that `pccd world --json` must equal, computed with the library's
// API directly and without a Collision_world: every distinct file of the scene read
// (PCCD::IO::read_points) and preprocessed with the defaults of the object the JSON names
// (Point_cloud_object, or Euclidean_point_cloud_object for "kernel": "euclidean"), then
// PCCD::do_intersect on every pair of instances (i, j), i < j, whose filters agree, seeded by the
// documented rule pair_seed(seed, world_pair_key(i, j)). Used by run_cli_test.cmake:
//
//   world_reference SCENE.csv CLI.json
//
// SCENE.csv: rows "file, 12 numbers[, group, mask]" ('#' lines and a header skipped), instance i
// being row i; CLI.json: what `pccd world SCENE.csv --json` printed (its "seed" is used). Checks
// the "pairs" array -- the same pairs in the same order, the same status, the points bit for bit
// (null where the C++ point is NaN) -- and prints what it compared; exits with 1 and names every
// difference otherwise, with 2 when the scene has no intersecting pair (nothing was checked).
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/World/Collision_world.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Row {
    std::string file;
    PCCD::Rigid_transform_3<double> pose;
    PCCD::Collision_filter filter;
};

std::vector<Row> read_scene(const std::string& path)
{
    std::ifstream in(path);
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        for (char& c : line)
            if (c == ',') c = ' ';
        std::istringstream fields(line);
        Row row;
        if (!(fields >> row.file) || row.file.front() == '#') continue;
        std::array<double, 12> m{};
        bool numbers = true;
        for (double& x : m) numbers = numbers && bool(fields >> x);
        if (!numbers) continue; // the header
        row.pose = PCCD::Rigid_transform_3<double>(m);
        std::string group, mask;
        if (fields >> group >> mask)
            row.filter = {std::uint32_t(std::stoull(group, nullptr, 0)), std::uint32_t(std::stoull(mask, nullptr, 0))};
        rows.push_back(row);
    }
    return rows;
}

bool same_number(const nlohmann::json& value, double expected)
{
    if (!std::isfinite(expected)) return value.is_null();
    return value.is_number() && value.get<double>() == expected;
}

struct Pair {
    std::uint32_t a, b;
    PCCD::Intersection_status status;
    Eigen::Vector3d point;
};

/// do_intersect on every pair of instances whose filters agree, each file preprocessed once into an
/// `Object` with its defaults: the pairs that are not separate, in order.
template <class Object>
std::vector<Pair> brute_force(const std::vector<Row>& rows, const PCCD::Intersection_options& options)
{
    std::map<std::string, Object> objects;
    for (const Row& row : rows)
        if (!objects.contains(row.file)) objects.emplace(row.file, Object(PCCD::IO::read_points(row.file)));
    std::vector<Pair> truth;
    for (std::uint32_t i = 0; i < rows.size(); ++i)
        for (std::uint32_t j = i + 1; j < rows.size(); ++j) {
            if (!PCCD::may_collide(rows[i].filter, rows[j].filter)) continue;
            PCCD::Intersection_options o = options;
            o.seed = PCCD::pair_seed(options.seed, PCCD::world_pair_key(i, j));
            const PCCD::Intersection_result r =
                PCCD::do_intersect(objects.at(rows[i].file), rows[i].pose, objects.at(rows[j].file), rows[j].pose, o);
            if (r.status == PCCD::Intersection_status::separate) continue;
            truth.push_back({i, j, r.status,
                             r.points.empty() ? Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN())
                                              : r.points.front().position});
        }
    return truth;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: world_reference SCENE.csv CLI.json\n";
        return 1;
    }
    const std::vector<Row> rows = read_scene(argv[1]);
    std::ifstream json_file(argv[2]);
    const nlohmann::json cli = nlohmann::json::parse(json_file);
    PCCD::Intersection_options options;
    options.seed = cli.at("seed").get<std::uint64_t>();

    // The objects the tool made: Point_cloud_object, or the lean one when it says "euclidean".
    const std::vector<Pair> truth = cli.at("objects").at(0).at("kernel") == "euclidean"
                                        ? brute_force<PCCD::Euclidean_point_cloud_object<>>(rows, options)
                                        : brute_force<PCCD::Point_cloud_object<>>(rows, options);

    int differences = 0;
    const nlohmann::json& pairs = cli.at("pairs");
    if (pairs.size() != truth.size()) {
        std::cerr << "differs: pccd world printed " << pairs.size() << " pairs, brute force finds " << truth.size() << '\n';
        ++differences;
    }
    for (std::size_t k = 0; k < std::min(pairs.size(), truth.size()); ++k) {
        const nlohmann::json& p = pairs[k];
        const Pair& t = truth[k];
        const nlohmann::json& point = p.at("point");
        const bool same_point = point.is_null() ? !t.point.allFinite()
                                                : point.size() == 3 && same_number(point[0], t.point.x()) &&
                                                      same_number(point[1], t.point.y()) && same_number(point[2], t.point.z());
        if (p.at("a") != t.a || p.at("b") != t.b || p.at("status") != PCCD::to_string(t.status) || !same_point) {
            std::cerr << "differs: pair " << k << ": pccd world " << p.dump() << ", brute force " << t.a << ' ' << t.b << ' '
                      << PCCD::to_string(t.status) << ' ' << t.point.transpose() << '\n';
            ++differences;
        }
    }
    std::cout << "compared " << truth.size() << " intersecting pairs of " << rows.size() << " instances ("
              << rows.size() * (rows.size() - 1) / 2 << " pairs by brute force): " << differences << " differences\n";
    if (differences) return 1;
    return truth.empty() ? 2 : 0;
}
