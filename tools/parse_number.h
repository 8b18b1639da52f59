// tools/parse_number.h -- the pccd tool's reading of one number from command-line text: the whole
// text must spell a finite number. Shared by the commands' option parsers.
#pragma once

#include <PCCD/Error.h>

#include <cmath>
#include <exception>
#include <string>

namespace pccd_tool {

/// The finite number spelled by all of `text`. \throws PCCD::Invalid_input naming `what` otherwise.
inline double parse_finite_number(const std::string& text, const std::string& what)
{
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(value))
        throw PCCD::Invalid_input(what + ": \"" + text + "\" is not a finite number");
    return value;
}

} // namespace pccd_tool
