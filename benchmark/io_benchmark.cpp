// benchmark/io_benchmark.cpp -- the time and memory of PCCD::IO::read_points on large scans
// (doc/benchmarks.md, "Reading large point files"). For each size N (default 10^6 and 10^7) it
// writes N random points (fixed seed) as: binary PLY of doubles with and without normals and an
// XYZ file with normals (PCCD::IO::write_points), a binary PLY of floats and a binary PLY of floats
// with three uchar colour properties (written here: PCCD's writer writes doubles only), then times
// read_points on each: the median of 3 reads with the file in the page cache ("warm": wall time,
// and the process's CPU time, user and system, which other processes on the machine disturb
// less), and one read after the file's pages were dropped from the cache with
// posix_fadvise(POSIX_FADV_DONTNEED) ("cold"). Memory: the peak resident set (VmHWM of
// /proc/self/status, reset before each read by writing 5 to /proc/self/clear_refs) minus the
// resident set before the read, per point, glibc's mmap threshold fixed at 1 MiB so that freed
// blocks leave the resident set; 24 bytes per point (48 with normals) is the size of the result
// itself. The files are synced to the disk before the reads.
//
// Usage: io_benchmark [--sizes 1000000,10000000] [--dir /tmp/pccd_io_benchmark] [--keep]
//        (the files are removed at the end unless --keep)
#include <PCCD/IO/read_points.h>
#include <PCCD/IO/write_points.h>
#include <PCCD/Random.h>

#include <PCCD/testing/timing.h>

#include <fcntl.h>
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <PCCD/testing/process_memory.h>
#include <string>
#include <vector>

namespace {

using PCCD::testing::reset_peak;
using PCCD::testing::status_bytes;

/// The CPU time of the process (user and system) in ms.
double cpu_ms()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return 1e3 * double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-3 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// Drops the file's pages from the page cache.
void drop_from_cache(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) return;
    ::fdatasync(fd);
    ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
    ::close(fd);
}

/// A binary little-endian PLY of floats x, y, z (and red, green, blue as uchar if `colours`).
void write_float_ply(const std::string& path, const PCCD::Point_data& data, bool colours)
{
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << data.points.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n";
    if (colours) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    out << "end_header\n";
    std::vector<char> buffer;
    for (std::size_t i = 0; i < data.points.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const float v = float(data.points[i][k]);
            char bytes[4];
            std::memcpy(bytes, &v, 4); // x86: little endian already
            buffer.insert(buffer.end(), bytes, bytes + 4);
        }
        if (colours)
            for (int k = 0; k < 3; ++k) buffer.push_back(char(i * 7 + std::size_t(k)));
        if (buffer.size() > (1u << 20)) {
            out.write(buffer.data(), std::streamsize(buffer.size()));
            buffer.clear();
        }
    }
    out.write(buffer.data(), std::streamsize(buffer.size()));
    if (!out) throw std::runtime_error("cannot write " + path);
}

struct Measure {
    double warm_ms = 0;
    double warm_cpu_ms = 0;
    double cold_ms = 0;
    double bytes_per_point = 0;
};

Measure measure(const std::string& path, std::size_t n, std::size_t expected_normals)
{
    Measure m;
    std::vector<double> times, cpu;
    for (int r = 0; r < 4; ++r) {
        const bool cold = r == 3;
        if (cold) drop_from_cache(path);
        const bool peak = reset_peak();
        const long long before = status_bytes("VmRSS");
        const double cpu_start = cpu_ms();
        const auto start = PCCD::testing::Clock::now();
        PCCD::Point_data data = PCCD::IO::read_points(path);
        const double ms = PCCD::testing::ms_since(start);
        const double cpu_used = cpu_ms() - cpu_start;
        const long long high = status_bytes("VmHWM");
        if (data.points.size() != n || data.normals.size() != expected_normals) {
            std::fprintf(stderr, "%s: read %zu points and %zu normals\n", path.c_str(), data.points.size(),
                         data.normals.size());
            std::exit(1);
        }
        if (cold)
            m.cold_ms = ms;
        else {
            times.push_back(ms);
            cpu.push_back(cpu_used);
        }
        if (r == 0) m.bytes_per_point = peak ? double(high - before) / double(n) : -1.0;
    }
    std::sort(times.begin(), times.end());
    std::sort(cpu.begin(), cpu.end());
    m.warm_ms = times[1];
    m.warm_cpu_ms = cpu[1];
    return m;
}

} // namespace

int main(int argc, char** argv)
{
    // A fixed mmap threshold: every large block is mapped and returned to the system when freed
    // (glibc's adaptive threshold would keep a freed 24 MB block in the heap, resident, and the next
    // read would reuse it without growing the resident set).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    std::vector<std::size_t> sizes{1000000, 10000000};
    std::string dir = "/tmp/pccd_io_benchmark";
    bool keep = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--keep") {
            keep = true;
        } else if (a == "--sizes" && i + 1 < argc) {
            sizes.clear();
            std::stringstream in(argv[++i]);
            for (std::string item; std::getline(in, item, ',');) sizes.push_back(std::size_t(std::atoll(item.c_str())));
        } else if (a == "--dir" && i + 1 < argc) {
            dir = argv[++i];
        } else {
            std::fprintf(stderr, "usage: io_benchmark [--sizes 1000000,10000000] [--dir DIR] [--keep]\n");
            return 2;
        }
    }
    std::filesystem::create_directories(dir);
    std::printf("%-10s %-22s %10s %10s %10s %10s %14s\n", "points", "file", "MB", "warm ms", "warm cpu", "cold ms",
                "peak B/point");
    for (const std::size_t n : sizes) {
        PCCD::Random_engine engine(3);
        PCCD::Point_data data;
        data.points.reserve(n);
        data.normals.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            data.points.emplace_back(PCCD::uniform_real(engine, -1.0, 1.0), PCCD::uniform_real(engine, -1.0, 1.0),
                                     PCCD::uniform_real(engine, -1.0, 1.0));
            data.normals.emplace_back(PCCD::uniform_real(engine, -1.0, 1.0), PCCD::uniform_real(engine, -1.0, 1.0),
                                      PCCD::uniform_real(engine, -1.0, 1.0));
        }
        PCCD::Point_data bare;
        bare.points = data.points;
        struct File {
            std::string name;
            std::size_t normals;
        };
        const std::string stem = dir + "/n" + std::to_string(n) + "_";
        std::vector<File> files{{"ply_double.ply", 0}, {"ply_double_normals.ply", n}, {"ply_float.ply", 0},
                                {"ply_float_colours.ply", 0}, {"xyz_normals.xyz", n}};
        PCCD::IO::write_points(stem + files[0].name, bare, PCCD::IO::Write_options{.binary = true});
        PCCD::IO::write_points(stem + files[1].name, data, PCCD::IO::Write_options{.binary = true});
        write_float_ply(stem + files[2].name, bare, false);
        write_float_ply(stem + files[3].name, bare, true);
        PCCD::IO::write_points(stem + files[4].name, data);
        bare = {};
        data = {};
        ::sync(); // no writeback of the files while they are read
        for (const File& f : files) {
            const std::string path = stem + f.name;
            const Measure m = measure(path, n, f.normals);
            std::printf("%-10zu %-22s %10.1f %10.0f %10.0f %10.0f %14.1f\n", n, f.name.c_str(),
                        double(std::filesystem::file_size(path)) / 1e6, m.warm_ms, m.warm_cpu_ms, m.cold_ms,
                        m.bytes_per_point);
            std::fflush(stdout);
            if (!keep) std::filesystem::remove(path);
        }
    }
}
