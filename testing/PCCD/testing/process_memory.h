// PCCD/testing/process_memory.h -- the resident memory of the running process, for the benchmarks
// that report bytes per point (doc/benchmarks.md, "Reading large point files", "Memory per point,
// and where it goes", "Clearance through a scanned tunnel"): fields of /proc/self/status and the
// reset of the peak (Linux).
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

#include <malloc.h>

namespace PCCD::testing {

/// A field of /proc/self/status in bytes ("VmRSS": the resident set, "VmHWM": its peak); 0 when
/// the field or the file is missing.
inline long long status_bytes(const char* field)
{
    std::ifstream in("/proc/self/status");
    const std::string key = std::string(field) + ":";
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key, 0) == 0) return std::atoll(line.c_str() + key.size()) * 1024;
    return 0;
}

/// Resets the peak (VmHWM) to the current resident set ("5" to /proc/self/clear_refs, Linux 4.0 or
/// later), so that the next peak is that of what follows. With `trim_heap`, the heap's free pages
/// are first returned to the system, so that what follows cannot reuse resident pages uncounted.
/// False when the reset was not allowed.
inline bool reset_peak(bool trim_heap = false)
{
    if (trim_heap) malloc_trim(0);
    std::ofstream out("/proc/self/clear_refs");
    out << "5";
    out.flush();
    return bool(out);
}

} // namespace PCCD::testing
