// contact_time_reference: the C++ answer that `pccd contact-time` must print, computed with the
// library's API directly (PCCD::IO::read_points, Point_cloud_object<> with its defaults,
// PCCD::Linear_motion / Screw_motion, PCCD::time_of_contact), and compared with what the tool
// printed. Used by run_cli_test.cmake:
//
//   contact_time_reference json A B CLI.json [--from-a P] [--to-a P] [--from-b P] [--to-b P] [options]
//   contact_time_reference cases A B CASES.csv CLI.csv [options]
//   options: [--motion linear|screw] [--centre-a C] [--centre-b C] [--tolerance D] [--time-accuracy D]
//            [--near-step S] [--max-steps N] [--seed S]
//
// P: 12 numbers in one argument, separated by spaces or commas (3x4 row-major; default identity);
// C: 3 numbers likewise. `json` checks every result field of the JSON object (numbers bit for bit,
// null where the C++ value is NaN, the counters by name); `cases` recomputes every row of a cases
// file (plain rows of 48 comma-separated numbers after one header line) and checks the CSV rows.
// Prints what it compared; exits with 1 and names every difference otherwise.
#include <PCCD/Continuous/Contact_time_names.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/Point_cloud_object.h>
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

Eigen::Vector3d point(const std::vector<double>& v)
{
    return Eigen::Vector3d(v.at(0), v.at(1), v.at(2));
}

std::string text(double x)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

void check_number(const nlohmann::json& j, const std::string& name, double expected)
{
    if (!j.contains(name)) return differ(name + ": missing");
    const nlohmann::json& v = j[name];
    if (!std::isfinite(expected)) {
        if (!v.is_null()) differ(name + ": " + v.dump() + ", expected null (C++ " + text(expected) + ")");
        return;
    }
    if (!v.is_number() || v.get<double>() != expected) differ(name + ": " + v.dump() + ", expected " + text(expected));
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

void check_counters(const nlohmann::json& j, const PCCD::Contact_time_counters& c)
{
    if (!j.contains("counters") || !j["counters"].is_object()) return differ("counters: missing");
    const nlohmann::json& counters = j["counters"];
    std::map<std::string, std::size_t> expected;
    PCCD::for_each_counter(c, [&](const char* name, std::size_t value) { expected.emplace(name, value); });
    for (const auto& [name, value] : expected)
        if (!counters.contains(name) || counters[name].get<std::size_t>() != value)
            differ("counters." + name + ", expected " + std::to_string(value));
    if (counters.size() != expected.size())
        differ("counters: " + std::to_string(counters.size()) + " names, expected " + std::to_string(expected.size()));
}

struct Arguments {
    std::string motion = "linear";
    PCCD::Rigid_transform_3<double> from_a, to_a, from_b, to_b;
    Eigen::Vector3d centre_a = Eigen::Vector3d::Zero(), centre_b = Eigen::Vector3d::Zero();
    PCCD::Contact_time_options options;
};

PCCD::Contact_time_result query(const PCCD::Point_cloud_object<>& a, const PCCD::Point_cloud_object<>& b,
                                const Arguments& x, const PCCD::Rigid_transform_3<double>& from_a,
                                const PCCD::Rigid_transform_3<double>& to_a, const PCCD::Rigid_transform_3<double>& from_b,
                                const PCCD::Rigid_transform_3<double>& to_b)
{
    if (x.motion == "screw")
        return PCCD::time_of_contact(a, PCCD::Screw_motion(from_a, to_a), b, PCCD::Screw_motion(from_b, to_b), x.options);
    return PCCD::time_of_contact(a, PCCD::Linear_motion(from_a, to_a, x.centre_a), b,
                                 PCCD::Linear_motion(from_b, to_b, x.centre_b), x.options);
}

int usage()
{
    std::cerr << "usage: contact_time_reference json A B CLI.json [--from-a P] [--to-a P] [--from-b P] [--to-b P] [options]\n"
                 "       contact_time_reference cases A B CASES.csv CLI.csv [options]\n"
                 "options: [--motion linear|screw] [--centre-a C] [--centre-b C] [--tolerance D] [--time-accuracy D] "
                 "[--near-step S] [--max-steps N] [--seed S]\n";
    return 2;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 5) return usage();
    const std::string mode = argv[1];
    const int first_option = mode == "cases" ? 6 : 5;
    if (argc < first_option) return usage();
    Arguments x;
    for (int i = first_option; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) return usage();
        const std::string v = argv[++i];
        if (a == "--motion") x.motion = v;
        else if (a == "--from-a") x.from_a = pose(numbers(v), 0);
        else if (a == "--to-a") x.to_a = pose(numbers(v), 0);
        else if (a == "--from-b") x.from_b = pose(numbers(v), 0);
        else if (a == "--to-b") x.to_b = pose(numbers(v), 0);
        else if (a == "--centre-a") x.centre_a = point(numbers(v));
        else if (a == "--centre-b") x.centre_b = point(numbers(v));
        else if (a == "--tolerance") x.options.tolerance = std::stod(v);
        else if (a == "--time-accuracy") x.options.time_accuracy = std::stod(v);
        else if (a == "--near-step") x.options.near_step = std::stod(v);
        else if (a == "--max-steps") x.options.max_steps = std::stoull(v);
        else if (a == "--seed") x.options.distance.intersection.seed = std::stoull(v);
        else return usage();
    }
    const PCCD::Point_cloud_object<> a(PCCD::IO::read_points(argv[2]));
    const PCCD::Point_cloud_object<> b(PCCD::IO::read_points(argv[3]));

    if (mode == "json") {
        std::ifstream in(argv[4]);
        const nlohmann::json j = nlohmann::json::parse(in); // throws (exit != 0) when it does not parse
        const PCCD::Contact_time_result r = query(a, b, x, x.from_a, x.to_a, x.from_b, x.to_b);
        if (j.value("status", std::string()) != PCCD::to_string(r.status)) differ("status");
        if (j.value("motion", std::string()) != x.motion) differ("motion");
        check_number(j, "t", r.t);
        check_number(j, "t_low", r.t_low);
        check_number(j, "t_high", r.t_high);
        check_vector(j, "point", r.point);
        check_vector(j, "normal", r.normal);
        check_counters(j, r.counters);
        std::printf("time_of_contact: status %s, t %.17g in [%.17g, %.17g]\n", PCCD::to_string(r.status), r.t, r.t_low,
                    r.t_high);
    } else if (mode == "cases") {
        std::ifstream cases(argv[4]);
        std::ifstream cli(argv[5]);
        std::string row, printed;
        std::getline(cases, row); // header
        if (!std::getline(cli, printed) || printed != "case,status,t,t_low,t_high,query_us")
            differ("the CSV header: " + printed);
        std::size_t n = 0;
        while (std::getline(cases, row)) {
            const std::vector<double> v = numbers(row);
            if (v.empty()) continue;
            ++n;
            const PCCD::Contact_time_result r = query(a, b, x, pose(v, 0), pose(v, 12), pose(v, 24), pose(v, 36));
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
            const auto same = [](const std::string& field, double expected) {
                const double value = std::strtod(field.c_str(), nullptr);
                return std::isnan(expected) ? std::isnan(value) : value == expected;
            };
            if (fields[0] != std::to_string(n) || fields[1] != PCCD::to_string(r.status) || !same(fields[2], r.t) ||
                !same(fields[3], r.t_low) || !same(fields[4], r.t_high))
                differ("row " + std::to_string(n) + ": " + printed + " (C++: " + PCCD::to_string(r.status) + "," +
                       text(r.t) + "," + text(r.t_low) + "," + text(r.t_high) + ")");
            std::printf("case %zu: %s %.17g\n", n, PCCD::to_string(r.status), r.t);
        }
        if (std::getline(cli, printed) && !printed.empty()) differ("an extra row: " + printed);
    } else
        return usage();
    if (differences != 0) {
        std::cerr << differences << " difference(s) between pccd contact-time and the C++ API\n";
        return 1;
    }
    std::cout << "pccd contact-time agrees with the C++ API\n";
    return 0;
}
