// distance_reference: the C++ answer that `pccd distance` must print, computed with the library's
// API directly (PCCD::IO::read_points, Point_cloud_object<> with its defaults, PCCD::distance /
// within_distance), and compared with what the tool printed. Used by run_cli_test.cmake:
//
//   distance_reference json A B POSE_B CLI.json [--seed S] [--penetration] [--max-distance D] [--margin M]
//                      [--tolerance T] [--max-node-pairs N] [--certified-lower-bound]
//   distance_reference cases A B CASES.csv CLI.csv [--seed S]
//
// POSE_B: 12 numbers in one argument, separated by spaces or commas (3x4 row-major); A is at the
// identity. `json` checks every result field of the JSON object (numbers bit for bit, null where
// the C++ value is NaN or infinite, the counters by name); `cases` recomputes every row of a cases
// file (here: plain rows of 24 comma-separated numbers after one header line) and checks the CSV
// rows. Prints what it compared; exits with 1 and names every difference otherwise.
#include <PCCD/IO/read_points.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Rigid_transform_3.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

int differences = 0;

void differ(const std::string& what)
{
    std::cerr << "differs: " << what << '\n';
    ++differences;
}

std::vector<double> numbers(std::string text)
{
    for (char& c : text)
        if (c == ',') c = ' ';
    std::istringstream in(text);
    std::vector<double> out;
    for (double x; in >> x;) out.push_back(x);
    return out;
}

PCCD::Rigid_transform_3<double> pose(const std::vector<double>& v, std::size_t first)
{
    std::array<double, 12> m{};
    for (std::size_t i = 0; i < 12; ++i) m[i] = v.at(first + i);
    return PCCD::Rigid_transform_3<double>(m);
}

/// A number of the JSON against the C++ value: null exactly when the value is NaN or infinite
/// (nlohmann writes those as null), else the same double.
void check_number(const nlohmann::json& j, const std::string& name, double expected)
{
    if (!j.contains(name)) return differ(name + ": missing");
    const nlohmann::json& v = j[name];
    if (!std::isfinite(expected)) {
        if (!v.is_null()) differ(name + ": " + v.dump() + ", expected null (C++ " + std::to_string(expected) + ")");
        return;
    }
    if (!v.is_number() || v.get<double>() != expected) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.17g", expected);
        differ(name + ": " + v.dump() + ", expected " + buffer);
    }
}

void check_vector(const nlohmann::json& j, const std::string& name, const Eigen::Vector3d& expected)
{
    if (!j.contains(name)) return differ(name + ": missing");
    const nlohmann::json& v = j[name];
    if (!expected.allFinite()) {
        if (!v.is_null()) differ(name + ": " + v.dump() + ", expected null (not computed)");
        return;
    }
    if (!v.is_array() || v.size() != 3) return differ(name + ": " + v.dump() + ", expected 3 numbers");
    for (int k = 0; k < 3; ++k)
        if (!v[k].is_number() || v[k].get<double>() != expected(k)) differ(name + "[" + std::to_string(k) + "]: " + v.dump());
}

/// The counters: the library's names (for_each_counter) and the intersection query's prefixed
/// "intersection_", each with its value, and no other name.
void check_counters(const nlohmann::json& j, const PCCD::Distance_counters& c)
{
    if (!j.contains("counters") || !j["counters"].is_object()) return differ("counters: missing");
    const nlohmann::json& counters = j["counters"];
    std::map<std::string, std::size_t> expected;
    PCCD::for_each_counter(c, [&](const char* name, std::size_t value) { expected.emplace(name, value); });
    PCCD::for_each_counter(c.intersection, [&](const char* name, std::size_t value) {
        expected.emplace(std::string("intersection_") + name, value);
    });
    for (const auto& [name, value] : expected)
        if (!counters.contains(name) || counters[name].get<std::size_t>() != value)
            differ("counters." + name + ", expected " + std::to_string(value));
    if (counters.size() != expected.size())
        differ("counters: " + std::to_string(counters.size()) + " names, expected " + std::to_string(expected.size()));
}

int usage()
{
    std::cerr << "usage: distance_reference json A B POSE_B CLI.json [--seed S] [--penetration] [--max-distance D] "
                 "[--margin M] [--tolerance T] [--max-node-pairs N] [--certified-lower-bound]\n       distance_reference cases A B CASES.csv CLI.csv [--seed S]\n";
    return 2;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 6) return usage();
    const std::string mode = argv[1];
    PCCD::Distance_options options;
    bool has_margin = false;
    double margin = 0.0;
    for (int i = 6; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--seed" && i + 1 < argc) options.intersection.seed = std::stoull(argv[++i]);
        else if (a == "--penetration") options.penetration = true;
        else if (a == "--max-distance" && i + 1 < argc) options.max_distance = std::stod(argv[++i]);
        else if (a == "--margin" && i + 1 < argc) has_margin = true, margin = std::stod(argv[++i]);
        else if (a == "--tolerance" && i + 1 < argc) options.absolute_tolerance = std::stod(argv[++i]);
        else if (a == "--max-node-pairs" && i + 1 < argc) options.max_node_pairs = std::stoull(argv[++i]);
        else if (a == "--certified-lower-bound") options.certified_lower_bound = true;
        else return usage();
    }
    const PCCD::Point_cloud_object<> a(PCCD::IO::read_points(argv[2]));
    const PCCD::Point_cloud_object<> b(PCCD::IO::read_points(argv[3]));

    if (mode == "json") {
        const PCCD::Rigid_transform_3<double> pose_b = pose(numbers(argv[4]), 0);
        std::ifstream in(argv[5]);
        const nlohmann::json j = nlohmann::json::parse(in); // throws (exit != 0) when it does not parse
        if (has_margin) {
            const PCCD::Clearance_result r = PCCD::within_distance(a, {}, b, pose_b, margin, options);
            if (j.value("within", !r.within) != r.within) differ("within");
            if (j.value("status", std::string()) != PCCD::to_string(r.status)) differ("status");
            check_number(j, "margin", r.margin);
            check_number(j, "lower_bound", r.lower_bound);
            check_number(j, "upper_bound", r.upper_bound);
            check_vector(j, "point_a", r.point_a);
            check_vector(j, "point_b", r.point_b);
            check_counters(j, r.counters);
            std::cout << "within_distance: within " << r.within << ", status " << PCCD::to_string(r.status) << '\n';
        } else {
            const PCCD::Distance_result r = PCCD::distance(a, {}, b, pose_b, options);
            if (j.value("status", std::string()) != PCCD::to_string(r.status)) differ("status");
            check_number(j, "distance", r.distance);
            check_number(j, "lower_bound", r.lower_bound);
            check_number(j, "upper_bound", r.upper_bound);
            check_vector(j, "point_a", r.point_a);
            check_vector(j, "point_b", r.point_b);
            check_vector(j, "normal_a", r.normal_a);
            check_vector(j, "normal_b", r.normal_b);
            check_number(j, "depth", r.depth);
            check_number(j, "depth_a", r.depth_a);
            check_number(j, "depth_b", r.depth_b);
            check_vector(j, "contact_normal", r.contact_normal);
            check_counters(j, r.counters);
            if (!j.contains("intersection_points") || j["intersection_points"].size() != r.intersection_points.size())
                differ("intersection_points: count");
            std::printf("distance: status %s, distance %.17g in [%.17g, %.17g]\n", PCCD::to_string(r.status), r.distance,
                        r.lower_bound, r.upper_bound);
        }
    } else if (mode == "cases") {
        std::ifstream cases(argv[4]);
        std::ifstream cli(argv[5]);
        std::string row, printed;
        std::getline(cases, row); // header
        if (!std::getline(cli, printed) || printed != "case,status,distance,lower_bound,upper_bound,query_us")
            differ("the CSV header: " + printed);
        std::size_t n = 0;
        while (std::getline(cases, row)) {
            const std::vector<double> v = numbers(row);
            if (v.empty()) continue;
            ++n;
            const PCCD::Distance_result r = PCCD::distance(a, pose(v, 0), b, pose(v, 12), options);
            if (!std::getline(cli, printed)) {
                differ("row " + std::to_string(n) + ": missing");
                continue;
            }
            std::vector<std::string> fields;
            std::istringstream fin(printed);
            for (std::string f; std::getline(fin, f, ',');) fields.push_back(f);
            if (fields.size() != 6) {
                differ("row " + std::to_string(n) + ": " + printed);
                continue;
            }
            const auto same = [](const std::string& text, double expected) {
                const double x = std::strtod(text.c_str(), nullptr);
                return std::isnan(expected) ? std::isnan(x) : x == expected;
            };
            if (fields[0] != std::to_string(n) || fields[1] != PCCD::to_string(r.status) || !same(fields[2], r.distance) ||
                !same(fields[3], r.lower_bound) || !same(fields[4], r.upper_bound))
                differ("row " + std::to_string(n) + ": " + printed);
            std::printf("case %zu: %s %.17g\n", n, PCCD::to_string(r.status), r.distance);
        }
        if (std::getline(cli, printed) && !printed.empty()) differ("an extra row: " + printed);
    } else
        return usage();
    if (differences != 0) {
        std::cerr << differences << " difference(s) between pccd distance and the C++ API\n";
        return 1;
    }
    std::cout << "pccd distance agrees with the C++ API\n";
    return 0;
}
