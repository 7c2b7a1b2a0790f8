/// @file program/heidenhain/tool_name.hpp
/// The tool names a TNC takes in `TOOL CALL "…"`: up to 32 of the characters A–Z 0–9
/// `# $ % & , - _ .` (TNC 640 User's Manual 1/2015 §5.2 "Tool number, tool name"; lower case is
/// not among them). The writer refuses another dialect's name that breaks the rule.
/// @code
///   kin5::program::heidenhain::is_tnc_tool_name("MILL_D10");   // true
///   kin5::program::heidenhain::is_tnc_tool_name("Mill 10");    // false: lower case, a blank
/// @endcode
#pragma once

#include <algorithm>
#include <string_view>

#include "../text.hpp"

namespace kin5::program::heidenhain {

/// Whether `name` is a tool name a TNC takes (see the file comment).
constexpr bool is_tnc_tool_name(std::string_view name) {
  return !name.empty() && name.size() <= 32 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || is_digit(c) || std::string_view("#$%&,-_.").find(c) != std::string_view::npos;
  });
}

static_assert(is_tnc_tool_name("MILL_D10") && is_tnc_tool_name("DRILL$6&,%") && !is_tnc_tool_name("Mill 10") &&
              !is_tnc_tool_name("") && !is_tnc_tool_name("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456"));

}  // namespace kin5::program::heidenhain
