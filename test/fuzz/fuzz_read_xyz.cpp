// test/fuzz/fuzz_read_xyz.cpp -- libFuzzer target: the fuzzed bytes as an XYZ/PWN file, read by
// PCCD::IO::read_points (which takes a path only, so the bytes go through a per-process scratch
// file). XYZ holds no faces: read_triangle_mesh must refuse it with a File_error whatever the
// bytes. Outcomes are classified by fuzz_support.h.
#include "fuzz_support.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/IO/read_triangle_mesh.h>

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static PCCD::fuzz::Scratch_input input("xyz", ".xyz");
    const std::string& path = input.write(data, size);
    PCCD::fuzz::expect_file_errors(
        [&] { PCCD::fuzz::check_point_data(PCCD::IO::read_points(path, PCCD::IO::Format::xyz)); });
    bool refused = false;
    try {
        PCCD::IO::read_triangle_mesh(path, PCCD::IO::Format::xyz);
    } catch (const PCCD::File_error&) {
        refused = true;
    }
    PCCD::fuzz::require(refused, "read_triangle_mesh accepted an XYZ file");
    return 0;
}
