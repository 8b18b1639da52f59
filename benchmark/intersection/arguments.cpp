// benchmark/intersection/arguments.cpp -- parsing intersection_benchmark's command line.
#include "arguments.h"

#include <sstream>
#include <stdexcept>

namespace pccd_bench::intersection {
namespace {

std::vector<std::size_t> parse_sizes(const std::string& text)
{
    std::vector<std::size_t> sizes;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) sizes.push_back(std::stoul(item));
    if (sizes.empty()) throw std::invalid_argument("--sizes needs a comma-separated list of point counts");
    return sizes;
}

} // namespace

Arguments parse(int argc, char** argv)
{
    Arguments a;
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--figure") a.figure = std::stoi(value);
        else if (key == "--points") a.points = std::stoul(value);
        else if (key == "--rotations") a.rotations = std::stoul(value);
        else if (key == "--rotations-fig9") a.rotations_fig9 = std::stoul(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--repetitions") a.repetitions = std::stoi(value);
        else if (key == "--sizes") a.sizes = parse_sizes(value);
        else if (key == "--csv") a.csv = value;
        else if (key == "--trace") a.trace = value != "0";
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.figure != 7 && a.figure != 9 && a.figure != 10 && a.figure != 11)
        throw std::invalid_argument("--figure must be 7, 9, 10 or 11");
    if (a.repetitions < 1) throw std::invalid_argument("--repetitions must be >= 1");
    if (a.rotations == 0 || a.rotations_fig9 == 0) throw std::invalid_argument("rotation counts must be >= 1");
    return a;
}

} // namespace pccd_bench::intersection
