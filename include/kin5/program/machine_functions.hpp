/// @file program/machine_functions.hpp
/// The M functions whose meaning DIN 66025 / ISO 6983 fix and every kin5 dialect reads the same
/// way, as the state words they mean (state_words.hpp): M0/M1 stop, M3/M4/M5 spindle, M6 tool
/// change, M7/M8/M9 coolant, and Heidenhain's M13/M14 (spindle and coolant in one). Readers take
/// them into `block::state` (`read_machine_function`), so that a block built by meaning and one
/// read from text are the same block; writers spell the state words back (`m_words_of`). Any
/// other M function is the machine maker's and stays a number in `block::m_codes`.
/// @code
///   kin5::program::state_words s;
///   take_machine_function(s, 3);                 // true: s.spindle == clockwise
///   take_machine_function(s, 4);                 // false: the block's spindle is said; M4 stays a number
///   std::vector<int> m;
///   machine_functions_of(s, {}, m);              // {3}
/// @endcode
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "block.hpp"
#include "state_words.hpp"

namespace kin5::program {

/// Which of the shared M functions a dialect has beyond M0 M1 M3 M4 M5 M6 M8 M9.
struct machine_function_set {
  bool m7_mist = true;   ///< M7 is mist coolant (`controller::m7_mist_coolant`; a TNC has no standard M7)
  bool m13_m14 = false;  ///< M13 / M14 are M3 / M4 with coolant on (Heidenhain)
};

/// Takes M function `m` into `s` as its meaning and returns true; false when `m` has no shared
/// meaning in `set`, or when `s` already says what `m` would (a second spindle word in one
/// block, M9 beside M7 or M8): the reader keeps such an `m` as a number, as written.
inline bool take_machine_function(state_words& s, long long m, machine_function_set set = {}) {
  switch (m) {
    case 0:
    case 1:
      if (s.stop) return false;
      s.stop = m == 0 ? program_stop::stop : program_stop::optional_stop;
      return true;
    case 3:
    case 4:
    case 5:
      if (s.spindle) return false;
      s.spindle = m == 3 ? spindle_rotation::clockwise
                : m == 4 ? spindle_rotation::counter_clockwise : spindle_rotation::stopped;
      return true;
    case 6:
      if (s.tool_change) return false;
      s.tool_change = true;
      return true;
    case 7:
      if (!set.m7_mist || s.coolant_mist) return false;
      s.coolant_mist = true;
      return true;
    case 8:
      if (s.coolant_flood) return false;
      s.coolant_flood = true;
      return true;
    case 9:
      if (s.coolant_flood || s.coolant_mist) return false;
      s.coolant_flood = s.coolant_mist = false;
      return true;
    case 13:
    case 14:
      if (!set.m13_m14 || s.spindle || s.coolant_flood) return false;
      s.spindle = m == 13 ? spindle_rotation::clockwise : spindle_rotation::counter_clockwise;
      s.coolant_flood = true;
      return true;
    default:
      return false;
  }
}

/// Reads M function `m` of block `b`: into its state words where `take_machine_function` takes
/// it and no word of its group (stop; spindle; tool change; coolant) is among the block's numbers
/// already, else into `b.m_codes`, so that the words a block keeps as numbers all follow, in the
/// text, the state word of their group: a writer that writes the state words first keeps their
/// order (`M7 M9 M8`: mist on as a state word, then M9 and M8 as numbers). A word that says
/// again what the state words say (`M5 M5`) is read once.
inline void read_machine_function(block& b, long long m, machine_function_set set = {}) {
  const auto groups = [set](long long n) {  // one bit per group
    if (n == 0 || n == 1) return 1;
    if (n == 3 || n == 4 || n == 5) return 2;
    if (n == 6) return 4;
    if (n == 7 || n == 8 || n == 9) return 8;
    if (set.m13_m14 && (n == 13 || n == 14)) return 2 | 8;  // spindle and coolant
    return 0;
  };
  const int g = groups(m);
  const bool later =
      g != 0 && std::any_of(b.m_codes.begin(), b.m_codes.end(), [&](int n) { return (groups(n) & g) != 0; });
  if (!later && take_machine_function(b.state, m, set)) return;
  // What `m` says by itself: a word that says again what the state words say (`M5 M5`, the
  // last M3 of `M3 M4 M3`) is read once, as `m_words_of` writes it once.
  state_words alone;
  const bool again = take_machine_function(alone, m, set) &&
                     (!alone.spindle || alone.spindle == b.state.spindle) &&
                     (!alone.coolant_flood || alone.coolant_flood == b.state.coolant_flood) &&
                     (!alone.coolant_mist || alone.coolant_mist == b.state.coolant_mist) &&
                     (!alone.stop || alone.stop == b.state.stop) && (!alone.tool_change || b.state.tool_change);
  if (!again) b.m_codes.push_back(static_cast<int>(m));
}

/// Appends to `out` the M functions that say the spindle, coolant and stop of `s`, in this order
/// (the tool change is each writer's: it goes with the tool): M3/M4/M5; M7 and M8 for what is
/// switched on, M9 for both off; M0/M1. Returns why when `s` says what no M function of `set`
/// says (mist coolant without M7; one coolant off and the other on or unsaid: M9 switches both
/// off), else empty.
inline std::string machine_functions_of(const state_words& s, machine_function_set set, std::vector<int>& out) {
  if (s.spindle)
    out.push_back(*s.spindle == spindle_rotation::clockwise ? 3
                  : *s.spindle == spindle_rotation::counter_clockwise ? 4 : 5);
  const bool off = s.coolant_flood == false || s.coolant_mist == false;
  if (off && !(s.coolant_flood == false && s.coolant_mist == false))
    return "one coolant switched off without the other (M9 switches both off)";
  if (off) out.push_back(9);
  if (s.coolant_mist == true && !set.m7_mist) return "mist coolant (M7) has no M function here";
  if (s.coolant_mist == true) out.push_back(7);
  if (s.coolant_flood == true) out.push_back(8);
  if (s.stop) out.push_back(*s.stop == program_stop::stop ? 0 : 1);
  return {};
}

/// Whether block `b` changes the tool: `state.tool_change` (M6, `TOOL CALL n`, `LOADTL`), or an
/// M6 among its numbers.
inline bool changes_tool(const block& b) {
  return b.state.tool_change || std::find(b.m_codes.begin(), b.m_codes.end(), 6) != b.m_codes.end();
}

/// Whether block `b` says an M function: a tool change, spindle, coolant or stop word, or a number.
inline bool says_m_function(const block& b) {
  const state_words& s = b.state;
  return !b.m_codes.empty() || s.tool_change || s.spindle || s.coolant_flood || s.coolant_mist || s.stop;
}

/// Appends to `out` every M function block `b` says, each once: M6 first when the block changes
/// the tool and `tool_change_m6` (a dialect whose tool change is M6), then its state words'
/// (`machine_functions_of`), then its other numbers as written (an M6 among them too: a writer
/// whose tool change is not M6 leaves it out). Returns why when a state word has no M function,
/// else empty.
inline std::string m_words_of(const block& b, machine_function_set set, bool tool_change_m6, std::vector<int>& out) {
  if (tool_change_m6 && changes_tool(b)) out.push_back(6);
  std::string why = machine_functions_of(b.state, set, out);
  const auto said = static_cast<std::ptrdiff_t>(out.size());
  for (int m : b.m_codes)
    if (std::find(out.begin(), out.begin() + said, m) == out.begin() + said) out.push_back(m);
  return why;
}

}  // namespace kin5::program
