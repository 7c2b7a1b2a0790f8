/// @file program/work_offsets.hpp
/// Work offsets by name: how a selection (`work_offset`, state_words.hpp) is spelled in messages
/// and in `--work-offset-map` (`spelling`, `parse_work_offset`), and which selections a dialect
/// writes (`work_offset_names`: one family and a range of numbers; each dialect entry lists its
/// own in `capabilities::work_offsets`).
/// @code
///   using namespace kin5::program;
///   spelling({work_offset_family::extended, 7});            // "G54.1 P7"
///   parse_work_offset("G505");                               // {siemens, 505}
///   parse_work_offset("3");                                  // {preset, 3}: a Heidenhain preset row
///   work_offset_names{work_offset_family::g54, 1, 6}.holds({work_offset_family::g54, 4});  // true
/// @endcode
#pragma once

#include <charconv>
#include <optional>
#include <string>
#include <string_view>

#include "state_words.hpp"

namespace kin5::program {

/// Work offsets a dialect selects by name: the numbers `first` … `last` of one family (an empty
/// range by default), and the dialect's own code for them when it is not the one `spelling`
/// gives (`code` "G154 P": Haas writes the extended offset 7 `G154 P7`, not `G54.1 P7`).
struct work_offset_names {
  work_offset_family family = work_offset_family::g54;
  int first = 1;
  int last = 0;
  std::string_view code{};  ///< written before the number; empty: `spelling`'s
  constexpr bool holds(const work_offset& w) const { return w.family == family && w.number >= first && w.number <= last; }
};

/// "G54" … "G59", "G59.1" … "G59.3", "G54.1 P7", "G500", "G505", "preset 7".
inline std::string spelling(const work_offset& w) {
  const std::string n = std::to_string(w.number);
  switch (w.family) {
    case work_offset_family::g54:
      if (w.number >= 1 && w.number <= 6) return "G" + std::to_string(53 + w.number);
      if (w.number >= 7 && w.number <= 9) return "G59." + std::to_string(w.number - 6);
      return "work offset " + n;
    case work_offset_family::extended: return "G54.1 P" + n;
    case work_offset_family::siemens: return w.number == 0 ? "G500" : "G" + n;
    case work_offset_family::preset: return "preset " + n;
  }
  return n;
}

/// The work offset `text` names, as `--work-offset-map` takes it (upper or lower case, no
/// blanks needed): `G54` … `G59`, `G59.1` … `G59.3`, `G54.1P7` (or `G54.1 P7`, or Haas's `G154P7`), `G500`,
/// `G505` … `G599`, or a bare number, a Heidenhain preset row. Empty when it names none.
inline std::optional<work_offset> parse_work_offset(std::string_view text) {
  std::string s;
  for (char c : text)
    if (c != ' ' && c != '\t') s.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
  const auto whole = [](std::string_view d) -> std::optional<int> {
    int v = 0;
    const auto [end, ec] = std::from_chars(d.data(), d.data() + d.size(), v);
    if (d.empty() || ec != std::errc{} || end != d.data() + d.size() || v < 0 || d[0] == '+' || d[0] == '-')
      return std::nullopt;
    return v;
  };
  if (const auto n = whole(s)) return work_offset{work_offset_family::preset, *n};
  if (s.rfind("G54.1P", 0) == 0 || s.rfind("G154P", 0) == 0) {  // Fanuc's spelling, Haas's
    const auto n = whole(std::string_view(s).substr(s[3] == '.' ? 6 : 5));
    if (n && *n >= 1) return work_offset{work_offset_family::extended, *n};
    return std::nullopt;
  }
  if (s.size() == 5 && s.rfind("G59.", 0) == 0 && s[4] >= '1' && s[4] <= '3')
    return work_offset{work_offset_family::g54, 6 + (s[4] - '0')};
  if (s.empty() || s[0] != 'G') return std::nullopt;
  const auto g = whole(std::string_view(s).substr(1));
  if (!g || s[1] == '0') return std::nullopt;
  if (*g >= 54 && *g <= 59) return work_offset{work_offset_family::g54, *g - 53};
  if (*g == 500 || (*g >= 505 && *g <= 599)) return work_offset{work_offset_family::siemens, *g == 500 ? 0 : *g};
  return std::nullopt;
}

}  // namespace kin5::program
