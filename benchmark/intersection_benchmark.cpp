// intersection_benchmark: WSCG05's evaluation figures for PCCD's do_intersect, on
// the benchmark poses of doc/manual/sampling.md. Two copies of the Stanford bunny (libcgal-demo's
// bunny00.off), normalized into [-1, 1]^3; A at [R_A | 0], B at [R_B | (d, 0, 0)]. The cloud is the
// mesh's vertices, or --points N area-uniform samples of the mesh. Every query runs on one thread,
// one at a time, stops at the first intersection, and is timed with steady_clock as the median of
// --repetitions runs with the same seed. The truth per pose is CGAL's exact answer on the mesh
// (exact_separation); a pose whose gap or penetration is below the cloud's sampling radius r(P) is
// grazing (classify_pose) and counted apart.
//
//   --figure 10   (or 11, the same run) per distance d = 0 .. 3 step 0.25: interpolation search
//                 ("isearch") and randomized sampling ("rst"), each in Overlap_region::object_boxes
//                 (WSCG05's setting: no hierarchy) and leaf_boxes (PCCD's default), beside FCL
//                 (OBBRSS hierarchies of the mesh) and the nearest-neighbour threshold test on the
//                 cloud (benchmark/collision_baselines.h): mean and median query time, mean f
//                 evaluations, colliding answers, false negatives and positives. Then the averages
//                 over d in [0, 1.5], where the copies can meet.
//   --figure 7    error rate per distance of Interpolation_search{.samples = n}, n = 20, 50, 100,
//                 150, 200 (and the default sample count), in both regions.
//   --figure 9    time and f evaluations vs cloud size (--sizes, resampled bunny, fixed seed),
//                 averaged over d in [0, 1.5] with --rotations-fig9 rotation pairs per distance; no
//                 exact truth.
//
//   intersection_benchmark --figure 7|9|10|11 [--points N] [--rotations 20] [--rotations-fig9 10]
//                          [--seed 1] [--repetitions 3] [--sizes 10000,30000,...] [--csv FILE]
//                          [--trace 1] (each PCCD query's counters on stderr)
//
//
// The program is split by concern under benchmark/intersection/: arguments, setup (bunny, cloud,
// preprocessing), runner (methods, timing, exact truth, tallies), baselines (FCL and the threshold
// test as methods) and one file per figure with its tables and CSV.
#include "intersection/arguments.h"
#include "intersection/figures.h"
#include "intersection/setup.h"

#include <exception>
#include <iostream>
#include <optional>

int main(int argc, char** argv)
try {
    using namespace pccd_bench::intersection;
    const Arguments args = parse(argc, argv);
    std::optional<PCCD::Triangle_mesh_data> mesh = read_bunny();
    if (!mesh) {
        std::cerr << "# bunny00.off not found (install libcgal-demo): the figures need the bunny; nothing to do\n";
        return 0;
    }
    if (args.figure == 9) return figure_9(args, *mesh);
    Bunny_setup bunny{*mesh, cloud_points(*mesh, args.points, args.seed)};
    return args.figure == 7 ? figure_7(args, bunny) : figure_10_11(args, bunny);
} catch (const std::exception& e) {
    std::cerr << "intersection_benchmark: " << e.what() << '\n';
    return 1;
}
