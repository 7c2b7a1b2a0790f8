/// @file version.hpp
/// kin5's version, as numbers and as text.
#pragma once

#define KIN5_VERSION_MAJOR 0
#define KIN5_VERSION_MINOR 1
#define KIN5_VERSION_PATCH 0

namespace kin5 {
inline constexpr int version_major = KIN5_VERSION_MAJOR;
inline constexpr int version_minor = KIN5_VERSION_MINOR;
inline constexpr int version_patch = KIN5_VERSION_PATCH;
inline constexpr const char* version_string = "0.1.0";
}  // namespace kin5
