// PCCD/version.h -- library version macros and the on-disk format version.
// Provides PCCD_VERSION_{MAJOR,MINOR,PATCH} and PCCD_VERSION_STRING.
#pragma once

#define PCCD_VERSION_MAJOR 0
#define PCCD_VERSION_MINOR 1
#define PCCD_VERSION_PATCH 0
#define PCCD_VERSION_STRING "0.1.0"

namespace PCCD {
/// Library version as one integer: major * 10000 + minor * 100 + patch.
inline constexpr int version = PCCD_VERSION_MAJOR * 10000 + PCCD_VERSION_MINOR * 100 + PCCD_VERSION_PATCH;
} // namespace PCCD
