// Shared helpers of the tests that write files: a scratch folder per test program under
// PCCD_TEST_TMP_DIR, and whole files written and read back byte for byte.
#pragma once

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace pccd_test {

/// The path of `name` in the scratch folder `directory` under PCCD_TEST_TMP_DIR (created when missing).
inline std::string scratch_path(const std::string& directory, const std::string& name)
{
    const std::filesystem::path dir = std::filesystem::path(PCCD_TEST_TMP_DIR) / directory;
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

/// The whole content of the file at `path` (empty when it cannot be read).
inline std::string read_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Writes `bytes` to a fresh file at `path`; the test fails when that does not succeed.
inline void write_bytes(const std::string& path, const std::string& bytes)
{
    // Removed first: on ext4, truncating and rewriting a file forces a flush to the disk on close.
    std::filesystem::remove(path);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    REQUIRE(out.good());
}

} // namespace pccd_test
