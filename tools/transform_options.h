// tools/transform_options.h -- reading rigid transforms from the command line (--transform-a,
// --transform-b of `pccd collide` and `pccd render`) and from CSV rows: 12 numbers, the 3x4 matrix
// [R | t] row by row, separated by commas and/or white space.
#pragma once

#include <PCCD/Error.h>
#include <PCCD/Rigid_transform_3.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace pccd_tool {

/// The number spelled by the whole of `token`, if it is one.
inline std::optional<double> parse_number(const std::string& token)
{
    if (token.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || errno == ERANGE) return std::nullopt;
    return value;
}

/// The fields of `text` separated by commas and/or white space.
inline std::vector<std::string> split_fields(const std::string& text)
{
    std::string spaced = text;
    for (char& c : spaced)
        if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream in(spaced);
    std::vector<std::string> fields;
    for (std::string field; in >> field;) fields.push_back(field);
    return fields;
}

/// The rigid transform given by 12 numbers (3x4 row-major, rotation | translation); `what` names
/// the source in error messages. Rigid_transform_3 rejects non-rigid matrices (its one tolerance
/// rule, shared with the library and the Python module); with `orthonormalize` the rotation is
/// replaced by its nearest rotation instead (PCCD::orthonormalize), and how far that moved it is
/// printed to stderr.
inline PCCD::Rigid_transform_3<double> make_transform(const std::vector<std::string>& fields, std::size_t first,
                                               const std::string& what, bool orthonormalize = false)
{
    std::array<double, 12> m{};
    for (std::size_t i = 0; i < 12; ++i) {
        const std::optional<double> value = parse_number(fields[first + i]);
        if (!value)
            throw PCCD::Invalid_input(what + ": \"" + fields[first + i] + "\" (number " + std::to_string(i + 1) +
                                      ") is not a number");
        m[i] = *value;
    }
    try {
        if (orthonormalize) {
            const PCCD::Orthonormalized_transform<double> fixed = PCCD::orthonormalize(m);
            std::cerr << "pccd: " << what << ": orthonormalized, the rotation moved by "
                      << PCCD::Rigid_transform_3<double>::full_digits(fixed.moved) << " (largest entry change)\n";
            return fixed.transform;
        }
        return PCCD::Rigid_transform_3<double>(m);
    } catch (const PCCD::Invalid_input& e) {
        throw PCCD::Invalid_input(what + ": " + e.what());
    }
}

/// The transform of --transform-a / --transform-b: identity when absent, else 12 numbers given as
/// separate arguments or in one quoted string.
inline PCCD::Rigid_transform_3<double> option_transform(const std::vector<std::string>& arguments, const std::string& option,
                                                        bool orthonormalize = false)
{
    if (arguments.empty()) return {};
    std::string joined;
    for (const std::string& a : arguments) joined += a + ' ';
    const std::vector<std::string> fields = split_fields(joined);
    if (fields.size() != 12)
        throw PCCD::Invalid_input(option + " expects 12 numbers (3x4 row-major: r00 r01 r02 t0 r10 ... t2), got " +
                                  std::to_string(fields.size()));
    try {
        return make_transform(fields, 0, option, orthonormalize);
    } catch (const PCCD::Invalid_input& e) {
        if (orthonormalize || std::string(e.what()).find("is not a number") != std::string::npos) throw;
        throw PCCD::Invalid_input(std::string(e.what()) + " (--orthonormalize uses the nearest rotation instead)");
    }
}

} // namespace pccd_tool
