// test/fuzz/fuzz_load_object.cpp -- libFuzzer target: the fuzzed bytes as a Point_cloud_object file
// (Point_cloud_object::load) or a geodesic file (read_geodesic_data); both take a path only, so the
// bytes go through a per-process scratch file.
//
// Input layout: one mode byte, then the file. Mode bit 0 picks the reader (0: object, 1:
// geodesic). Mode bit 1 repairs the checksums before the file is written: the trailing FNV-1a word
// of a geodesic file, or, for an object file, the checksum of its embedded geodesic section (where
// the header places it) and then its own. Without the repair almost every mutation dies at the
// checksum test; with it the fuzzer reaches the structural checks behind it. Outcomes are
// classified by fuzz_support.h.
#include "fuzz_support.h"

#include <PCCD/Geodesic/geodesic_io.h>
#include <PCCD/Point_cloud_object.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

/// Overwrites the last 8 bytes of `bytes[begin, end)` with the checksum of the bytes before them.
void repair_checksum(std::vector<std::uint8_t>& bytes, std::size_t begin, std::size_t end)
{
    if (end - begin < sizeof(std::uint64_t)) return;
    PCCD::internal::Word_checksum checksum;
    checksum.update(bytes.data() + begin, end - begin - sizeof(std::uint64_t));
    const std::uint64_t sum = checksum.value();
    std::memcpy(bytes.data() + end - sizeof sum, &sum, sizeof sum);
}

/// The offset of the u64 geodesic-section size in an object file of `n` points (see the format
/// comment above Point_cloud_object::save).
constexpr std::uint64_t object_geodesic_size_offset(std::uint64_t n)
{
    return 8 + 4 + 4 + 8 + 3 * 8 + 1 + 3 * 8 + 5 * 8 + 6 * 8 * n;
}

void repair_object_checksums(std::vector<std::uint8_t>& bytes)
{
    const std::uint64_t size = bytes.size();
    std::uint64_t n = 0, g = 0;
    if (size >= 24 + 8) {
        std::memcpy(&n, bytes.data() + 16, sizeof n);
        if (n < (std::uint64_t(1) << 32)) {
            const std::uint64_t at = object_geodesic_size_offset(n);
            if (at + 8 <= size) {
                std::memcpy(&g, bytes.data() + at, sizeof g);
                if (g <= size - (at + 8)) repair_checksum(bytes, at + 8, at + 8 + g);
            }
        }
    }
    repair_checksum(bytes, 0, bytes.size());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0) return 0;
    const std::uint8_t mode = data[0];
    const bool geodesic = (mode & 1) != 0;
    std::vector<std::uint8_t> file(data + 1, data + size);
    if ((mode & 2) != 0) {
        if (geodesic)
            repair_checksum(file, 0, file.size());
        else
            repair_object_checksums(file);
    }
    static PCCD::fuzz::Scratch_input input("object", ".pccd");
    const std::string& path = input.write(file.data(), file.size());
    if (geodesic) {
        PCCD::fuzz::expect_file_errors([&] {
            const PCCD::Geodesic_data loaded = PCCD::read_geodesic_data(path);
            PCCD::fuzz::require(loaded.graph.num_vertices() == loaded.cpsp.size(),
                                "read_geodesic_data: graph and CPSP map differ in size");
        });
    } else {
        PCCD::fuzz::expect_file_errors([&] {
            const auto object = PCCD::Point_cloud_object<>::load(path);
            PCCD::fuzz::require(object.size() >= 2, "Point_cloud_object::load: fewer than two points");
            PCCD::fuzz::require(object.graph().num_vertices() == object.size() && object.cpsp().size() == object.size(),
                                "Point_cloud_object::load: graph or CPSP map of the wrong size");
        });
    }
    return 0;
}
