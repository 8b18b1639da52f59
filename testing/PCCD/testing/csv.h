// PCCD/testing/csv.h -- opening the CSV file a benchmark writes (--csv FILE): the stream, its
// number precision, and an error naming the file when it cannot be created. Part of no manual
// chapter: the CSV files and their columns are described in doc/benchmarks.md.
#pragma once

#include <fstream>
#include <ios>
#include <stdexcept>
#include <string>

namespace PCCD::testing {

/// `path` opened for writing (truncated), numbers written with `precision` significant digits (6,
/// the stream default, unless asked).
/// \throws std::runtime_error("cannot write <path>") when the file cannot be opened.
inline std::ofstream open_csv(const std::string& path, std::streamsize precision = 6)
{
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write " + path);
    out.precision(precision);
    return out;
}

} // namespace PCCD::testing
