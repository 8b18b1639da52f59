// tools/progress.h -- the preprocessing progress that the pccd commands print on stderr while they
// build objects, only when stderr is a terminal (doc/manual/cli_collide.md, "Progress"): the stage
// running now on one line rewritten in place, and a line that stays for every stage that took a
// second or more. Redirected or piped, stderr gets nothing, so scripts see only the commands' own
// output.
#pragma once

#include <PCCD/Point_cloud_object_options.h>

#include <cstdio>
#include <string>
#include <utility>

#include <unistd.h>

namespace pccd_tool {

/// True when stderr is a terminal (isatty), asked once.
inline bool stderr_is_terminal()
{
    static const bool terminal = ::isatty(::fileno(stderr)) != 0;
    return terminal;
}

/// `options` with a progress printer for the object called `name` when stderr is a terminal;
/// `options` unchanged otherwise.
inline PCCD::Point_cloud_object_options with_progress(PCCD::Point_cloud_object_options options, std::string name)
{
    if (!stderr_is_terminal()) return options;
    options.progress = [name = std::move(name)](const PCCD::Preprocessing_progress& p) {
        // "\r\033[K": back to the start of the line and clear it (VT100, every terminal emulator).
        if (!p.finished)
            std::fprintf(stderr, "\r\033[Kpccd: %s (%zu points): %s ...", name.c_str(), p.points, PCCD::to_string(p.stage));
        else if (p.milliseconds >= 1000.0)
            std::fprintf(stderr, "\r\033[Kpccd: %s (%zu points): %s %.1f s\n", name.c_str(), p.points,
                         PCCD::to_string(p.stage), p.milliseconds / 1000.0);
        else
            std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    };
    return options;
}

} // namespace pccd_tool
