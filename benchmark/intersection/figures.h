// benchmark/intersection/figures.h -- the figures intersection_benchmark reproduces (WSCG05's
// Fig. 7, 9, 10 and 11, discussed in doc/benchmarks.md) for the queries of
// doc/manual/intersection.md. Each prints Markdown tables and, with --csv, writes one CSV file.
#pragma once

#include "arguments.h"
#include "setup.h"

namespace pccd_bench::intersection {

/// Fig. 10 and 11: query time and f evaluations per distance, with FCL and the threshold test beside
/// PCCD, then the averages over d in [0, 1.5] and over all distances. Returns the exit status.
int figure_10_11(const Arguments& args, const Bunny_setup& bunny);

/// Fig. 7: error rate per distance of Interpolation_search{.samples = n}, in both overlap regions.
int figure_7(const Arguments& args, const Bunny_setup& bunny);

/// Fig. 9: time and f evaluations vs cloud size, averaged over d in [0, 1.5]; no exact truth.
int figure_9(const Arguments& args, const PCCD::Triangle_mesh_data& mesh);

} // namespace pccd_bench::intersection
