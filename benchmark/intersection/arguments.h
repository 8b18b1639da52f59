// benchmark/intersection/arguments.h -- the command line of intersection_benchmark (usage in
// benchmark/intersection_benchmark.cpp) and the seed of each PCCD query. The benchmark measures the
// queries of doc/manual/intersection.md on the poses of doc/manual/sampling.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pccd_bench::intersection {

struct Arguments {
    int figure = 10;
    std::size_t points = 0; // 0: the mesh's vertices
    std::size_t rotations = 20;
    std::size_t rotations_fig9 = 10;
    std::uint64_t seed = 1;
    int repetitions = 3;
    std::vector<std::size_t> sizes = {10000, 30000, 100000, 300000, 1000000};
    std::string csv;
    bool trace = false;
};

/// The arguments of `argv` ("--key value" pairs). \throws std::invalid_argument on a bad option.
Arguments parse(int argc, char** argv);

/// The seed of the PCCD queries on pose number k (the same for every method and repetition).
inline std::uint64_t query_seed(const Arguments& args, std::size_t k) { return args.seed * 1000003ULL + k; }

} // namespace pccd_bench::intersection
