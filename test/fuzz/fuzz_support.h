// test/fuzz/fuzz_support.h -- what the fuzz targets of PCCD share: a per-process scratch file to
// hand fuzzed bytes to readers that take a path, and the policy that tells an expected outcome
// from a finding.
//
// Expected outcomes: the reader returns data that satisfies its documented postconditions, or it
// throws PCCD::File_error (the only exception the readers and loaders document). Findings, reported
// by abort() so that libFuzzer (and the replay driver) stop with the input and a stack: any other
// exception (another PCCD::Error, a standard or unknown exception), a File_error whose message says
// it is a PCCD bug (CGAL's reader disagreeing with PCCD's checks), a broken postcondition; crashes,
// sanitizer reports and hangs are caught by the tools themselves.
#pragma once

#include <PCCD/Error.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace PCCD::fuzz {

[[noreturn]] inline void finding(const char* what, const char* detail)
{
    std::fprintf(stderr, "PCCD fuzz finding: %s: %s\n", what, detail);
    std::fflush(stderr);
    std::abort();
}

/// Aborts unless `condition` holds (a postcondition of a successful read).
inline void require(bool condition, const char* what)
{
    if (!condition) finding("broken postcondition", what);
}

/// A file named `pccd_fuzz_<pid>_<tag><extension>` in the temporary directory, rewritten for
/// every input and removed at exit. One per process, so parallel fuzzing jobs do not collide.
class Scratch_input {
public:
    Scratch_input(const char* tag, const char* extension)
    {
        std::error_code error;
        std::filesystem::path directory = std::filesystem::temp_directory_path(error);
        if (error) directory = ".";
        m_path = (directory / ("pccd_fuzz_" + std::to_string(::getpid()) + '_' + tag + extension)).string();
    }
    Scratch_input(const Scratch_input&) = delete;
    Scratch_input& operator=(const Scratch_input&) = delete;
    ~Scratch_input()
    {
        std::error_code ignored;
        std::filesystem::remove(m_path, ignored);
    }

    /// Replaces the content of the file with `size` bytes at `data`; returns its path.
    const std::string& write(const std::uint8_t* data, std::size_t size)
    {
        std::ofstream out(m_path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        out.close();
        if (!out) finding("harness", ("cannot write the scratch file " + m_path).c_str());
        return m_path;
    }

private:
    std::string m_path;
};

/// The postconditions of PCCD::IO::read_points: at least one point, finite coordinates, and
/// either no normals or one finite normal per point. (Templates: this header needs no CGAL.)
template <class Point_data>
void check_point_data(const Point_data& data)
{
    require(!data.points.empty(), "read_points returned no points");
    require(data.normals.empty() || data.normals.size() == data.points.size(),
            "read_points returned a normal count different from the point count");
    for (const auto& p : data.points) require(p.allFinite(), "read_points returned a non-finite point");
    for (const auto& n : data.normals) require(n.allFinite(), "read_points returned a non-finite normal");
}

/// The postconditions of PCCD::IO::read_triangle_mesh: vertices and triangles, finite vertices,
/// every index in range.
template <class Triangle_mesh_data>
void check_mesh_data(const Triangle_mesh_data& mesh)
{
    require(!mesh.vertices.empty(), "read_triangle_mesh returned no vertices");
    require(!mesh.triangles.empty(), "read_triangle_mesh returned no triangles");
    for (const auto& v : mesh.vertices) require(v.allFinite(), "read_triangle_mesh returned a non-finite vertex");
    for (const auto& t : mesh.triangles)
        for (const auto i : t) require(i < mesh.vertices.size(), "read_triangle_mesh returned an out-of-range index");
}

/// Runs `read()` and classifies how it ends (see the header comment).
template <class Read>
void expect_file_errors(Read&& read)
{
    try {
        read();
    } catch (const PCCD::File_error& e) {
        if (std::strstr(e.what(), "please report this as a PCCD bug") != nullptr)
            finding("File_error reporting a PCCD bug", e.what());
    } catch (const PCCD::Error& e) {
        finding("PCCD exception other than File_error", e.what());
    } catch (const std::exception& e) {
        finding("non-PCCD exception", e.what());
    } catch (...) {
        finding("unknown exception", "(not derived from std::exception)");
    }
}

} // namespace PCCD::fuzz
