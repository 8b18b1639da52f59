// benchmark/intersection/setup.h -- the data of intersection_benchmark: the Stanford bunny
// normalized into [-1, 1]^3 and its cloud (the mesh's vertices or area-uniform samples), as the
// benchmark procedure of doc/manual/sampling.md prescribes, and the preprocessed object
// (doc/manual/surface.md) with its preprocessing time.
#pragma once

#include "arguments.h"

#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/Point_cloud_object.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace pccd_bench::intersection {

/// The bunny mesh normalized into [-1, 1]^3 (the benchmark procedure, doc/manual/sampling.md), or
/// nothing without the data.
std::optional<PCCD::Triangle_mesh_data> read_bunny();

/// The cloud: the mesh's vertices (n = 0) or n area-uniform samples of the mesh drawn with `seed`.
std::vector<Eigen::Vector3d> cloud_points(const PCCD::Triangle_mesh_data& mesh, std::size_t n, std::uint64_t seed);

struct Prepared {
    PCCD::Point_cloud_object<> object;
    double preprocess_ms;
};

/// The object of `points` with Point_cloud_object's defaults, and the wall time that took.
Prepared prepare(const std::vector<Eigen::Vector3d>& points);

struct Bunny_setup {
    PCCD::Triangle_mesh_data mesh;
    std::vector<Eigen::Vector3d> points;
};

/// The line describing the mesh, the cloud and the run that opens figures 7, 10 and 11.
void print_setup(const Bunny_setup& bunny, const Prepared& prepared, const Arguments& args);

} // namespace pccd_bench::intersection
