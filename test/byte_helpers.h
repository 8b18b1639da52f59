// Shared helper of the serialization tests: the bytes of a buffer as unsigned values, so that
// Catch2 prints them as numbers and comparisons with expected byte lists read naturally.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pccd_test {

inline std::vector<unsigned> bytes_of(const std::string& text)
{
    std::vector<unsigned> out;
    for (const char c : text) out.push_back(static_cast<unsigned char>(c));
    return out;
}

inline std::vector<unsigned> bytes_of(const std::string& text, std::size_t offset, std::size_t count)
{
    return bytes_of(text.substr(offset, count));
}

} // namespace pccd_test
