// test/fuzz/fuzz_read_off.cpp -- libFuzzer target: the fuzzed bytes as a OFF file, read by
// PCCD::IO::read_points and PCCD::IO::read_triangle_mesh (both take a path only, so the bytes go
// through a per-process scratch file). Outcomes are classified by fuzz_support.h.
#include "fuzz_support.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/IO/read_triangle_mesh.h>

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static PCCD::fuzz::Scratch_input input("off", ".off");
    const std::string& path = input.write(data, size);
    PCCD::fuzz::expect_file_errors(
        [&] { PCCD::fuzz::check_point_data(PCCD::IO::read_points(path, PCCD::IO::Format::off)); });
    PCCD::fuzz::expect_file_errors(
        [&] { PCCD::fuzz::check_mesh_data(PCCD::IO::read_triangle_mesh(path, PCCD::IO::Format::off)); });
    return 0;
}
