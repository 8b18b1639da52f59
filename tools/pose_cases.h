// tools/pose_cases.h -- the --cases files of `pccd collide` and `pccd distance` (CSV rows of 24
// numbers, the pose of A and then the pose of B, each a 3x4 [R | t] matrix row by row;
// doc/manual/cli_collide.md, "--cases FILE"), of `pccd contact-time` (rows of 48 numbers, the
// start and end poses of A and of B; doc/manual/continuous.md, "CLI and Python") and the --path
// files of `pccd clearance` (rows of 12 numbers, one pose each; doc/manual/proximity-cli-python.md,
// "pccd clearance").
#pragma once

#include "transform_options.h"

#include <PCCD/Error.h>
#include <PCCD/Rigid_transform_3.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace pccd_tool {

/// One pose pair of a --cases file and the line it came from.
struct Pose_case {
    std::size_t line;
    PCCD::Rigid_transform_3<double> pose_a;
    PCCD::Rigid_transform_3<double> pose_b;
};

/// Calls `row(fields, line)` for each data row of the CSV file `path` (`what`: "cases" or "path",
/// for the messages): blank lines and lines starting with '#' are skipped, and the first other
/// line too when its first field is not a number (a header). Throws File_error when the file
/// cannot be opened.
template <class Row>
void for_each_csv_row(const std::string& path, const char* what, Row&& row)
{
    std::ifstream in(path);
    if (!in)
        throw PCCD::File_error(path, std::filesystem::exists(path)
                                         ? std::string("cannot open the ") + what + " file"
                                         : std::string("cannot open the ") + what + " file: it does not exist (missing file)");
    bool first_row = true;
    std::string text;
    for (std::size_t line = 1; std::getline(in, text); ++line) {
        const std::vector<std::string> fields = split_fields(text);
        if (fields.empty() || fields.front().front() == '#') continue;
        const bool header = first_row && !parse_number(fields.front());
        first_row = false;
        if (header) continue;
        row(fields, line);
    }
}

/// The rows of a --cases CSV: 24 numbers each (T_A then T_B, 3x4 row-major); blank lines and lines
/// starting with '#' are skipped; the first other line may be a header (its first field is not a
/// number). Every other problem throws, naming the file and the line.
inline std::vector<Pose_case> read_cases(const std::string& path)
{
    std::vector<Pose_case> cases;
    for_each_csv_row(path, "cases", [&](const std::vector<std::string>& fields, std::size_t line) {
        const std::string where = path + ":" + std::to_string(line);
        if (fields.size() != 24)
            throw PCCD::Invalid_input(where + ": expected 24 numbers (T_A then T_B, 3x4 row-major each), got " +
                                      std::to_string(fields.size()) + " fields");
        PCCD::Rigid_transform_3<double> pose_a = make_transform(fields, 0, where + ": T_A");
        PCCD::Rigid_transform_3<double> pose_b = make_transform(fields, 12, where + ": T_B");
        cases.push_back({line, pose_a, pose_b});
    });
    if (cases.empty()) throw PCCD::Invalid_input(path + ": no cases (expected rows of 24 numbers)");
    return cases;
}

/// One row of a `pccd contact-time --cases` file: the start and end poses of A and of B.
struct Motion_case {
    std::size_t line;
    PCCD::Rigid_transform_3<double> from_a;
    PCCD::Rigid_transform_3<double> to_a;
    PCCD::Rigid_transform_3<double> from_b;
    PCCD::Rigid_transform_3<double> to_b;
};

/// The rows of a `pccd contact-time --cases` CSV: 48 numbers each (the poses of A at t = 0 and
/// t = 1, then those of B; 3x4 row-major each), with the rules of read_cases (comments, blank
/// lines, an optional header; every other problem throws, naming the file and the line).
inline std::vector<Motion_case> read_motion_cases(const std::string& path, bool orthonormalize = false)
{
    std::vector<Motion_case> cases;
    for_each_csv_row(path, "cases", [&](const std::vector<std::string>& fields, std::size_t line) {
        const std::string where = path + ":" + std::to_string(line);
        if (fields.size() != 48)
            throw PCCD::Invalid_input(where + ": expected 48 numbers (A at t = 0, A at t = 1, B at t = 0, B at t = 1; "
                                              "3x4 row-major each), got " + std::to_string(fields.size()) + " fields");
        cases.push_back({line, make_transform(fields, 0, where + ": A at t = 0", orthonormalize),
                         make_transform(fields, 12, where + ": A at t = 1", orthonormalize),
                         make_transform(fields, 24, where + ": B at t = 0", orthonormalize),
                         make_transform(fields, 36, where + ": B at t = 1", orthonormalize)});
    });
    if (cases.empty()) throw PCCD::Invalid_input(path + ": no cases (expected rows of 48 numbers)");
    return cases;
}

/// The rows of a `pccd clearance --path` CSV: 12 numbers each (one pose, 3x4 row-major), with the
/// rules of read_cases (comments, blank lines, an optional header; every other problem throws,
/// naming the file, the line and the pose's index). With `orthonormalize`, each rotation is
/// replaced by its nearest rotation (make_transform).
inline std::vector<PCCD::Rigid_transform_3<double>> read_path(const std::string& path, bool orthonormalize = false)
{
    std::vector<PCCD::Rigid_transform_3<double>> poses;
    for_each_csv_row(path, "path", [&](const std::vector<std::string>& fields, std::size_t line) {
        const std::string where = path + ":" + std::to_string(line) + ": pose " + std::to_string(poses.size());
        if (fields.size() != 12)
            throw PCCD::Invalid_input(where + ": expected 12 numbers (3x4 row-major [R | t]), got " +
                                      std::to_string(fields.size()) + " fields");
        poses.push_back(make_transform(fields, 0, where, orthonormalize));
    });
    if (poses.empty()) throw PCCD::Invalid_input(path + ": no poses (expected rows of 12 numbers)");
    return poses;
}

/// The poses of a query command: the rows of the --cases file when one is given (poses unset),
/// else the single pose pair of --transform-a and --transform-b.
struct Query_poses {
    std::optional<std::vector<Pose_case>> cases;
    PCCD::Rigid_transform_3<double> pose_a;
    PCCD::Rigid_transform_3<double> pose_b;
};

inline Query_poses read_query_poses(const std::string& cases_path, const std::vector<std::string>& transform_a,
                                    const std::vector<std::string>& transform_b, bool orthonormalize)
{
    Query_poses q;
    if (!cases_path.empty())
        q.cases = read_cases(cases_path);
    else {
        q.pose_a = option_transform(transform_a, "--transform-a", orthonormalize);
        q.pose_b = option_transform(transform_b, "--transform-b", orthonormalize);
    }
    return q;
}

} // namespace pccd_tool
