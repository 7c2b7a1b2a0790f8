/// @file program/iso/reader_state.hpp
/// What the ISO reader (reader.hpp) keeps: `line_words`, what one line's words say before they
/// are taken (its G codes, I J K, R, the dwell), `reader_state`, the modal record carried from
/// line to line (plane, last position of each axis, G90/G91, inch, inverse time, the last H and
/// D), and `no_own_words`, ISO's answers to what a dialect built on its reader decides itself
/// (LinuxCNC's `own_words`): the words it owns, the parameters a program may set, the whole
/// and the decimal-point addresses.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../block.hpp"
#include "../interp/parameter_store.hpp"
#include "expression.hpp"
#include "../incremental.hpp"
#include "lexer.hpp"
#include "parameter_rules.hpp"
#include "statements.hpp"

namespace kin5::program::iso::detail {

/// What the words of one line say beyond the block's own fields.
struct line_words {
  bool homing = false, g43_5 = false, uses_pq = false, g52_reset = false;
  const word* dwell = nullptr;       ///< G4: its X (seconds) or P (milliseconds) is the time
  const word* dwell_time = nullptr;  ///< that X or P
  const word* extended = nullptr;  ///< G54.1: its P is the number of the extended work offset
  const word* offset = nullptr;    ///< the work-offset word of the block
  const word* g43 = nullptr;       ///< G43, G43.4 or G43.5: H is its length offset
  const word* h = nullptr;         ///< the H word
  const word* g41 = nullptr;       ///< G41 or G42: D is its radius offset
  const word* g40 = nullptr;       ///< G40
  const word* d = nullptr;         ///< the D word
  const word* motion = nullptr;
  std::optional<double> ijk[3];
  const word* ijk_word[3] = {};
  std::optional<double> radius;
  const word* distance = nullptr;  ///< G90 or G91
  const word* unknown = nullptr;  ///< the first word not understood
  bool suppress = false;          ///< a cycle's or frame's words: no further diagnostics

  const word* first_ijk() const { return ijk_word[0] ? ijk_word[0] : ijk_word[1] ? ijk_word[1] : ijk_word[2]; }
  bool any_ijk() const { return ijk[0] || ijk[1] || ijk[2]; }
};

/// The reader's record across lines, needed to read I J K: motion mode, plane, G43.5, last point.
struct reader_state {
  std::optional<motion_kind> motion;
  arc_plane plane = arc_plane::xy;
  bool tcp = false;           // G43.4 or G43.5 active (modal group 08): G43 or G49 ends it
  bool vector_tcp = false;    // G43.5 active
  bool incremental = false;          // G91 in effect, until G90
  std::size_t incremental_line = 0;  // the line of that G91
  bool written_incremental = false;  // the mode the written program is in: G91 said by a block kept as G91
  std::optional<axis_position> last[6];  // X Y Z A B C: the last programmed position, in the program's unit
  std::size_t lost_line[6] = {};     // the machine-coordinate or home move that made it unknown (0: none)
  bool lost_at_reference[6] = {};    // that move was G28: the source's home_deg would give a rotary axis
  bool inch = false;          // G20 active: lengths are inches
  bool inverse_time = false;  // G93 active: F is not a length
  bool moved = false;         // a block has moved: the unit is fixed
  std::optional<long long> length_register;  // the last H given: G43 without H takes it
  std::optional<long long> radius_register;  // the last D given: G41/G42 without D takes it
  bool radius_on = false;           // G41/G42 in effect
  bool startup_pending = false;     // G41/G42 said on a line without motion: the next move starts it up
};

/// The words a dialect built on this reader reads itself (LinuxCNC: program/linuxcnc/reader.hpp).
/// `line(s, first, end)` may refuse a line before it is lexed; `take(words, b, error)` reads and
/// removes the words it owns before the rest get their ISO meaning; `check(b, error)` sees each
/// block read without error. `error(column, message)` reports at a column of the line. `syntax`
/// says what a line is to the interpreter (statements.hpp), `parameter_rules()` which
/// parameters exist (parameter_rules.hpp: FANUC Custom Macro B's #1–#33, #100–#199, #500–#999;
/// #1000 and up are the control's system variables), `read_value` reads a computed word value
/// (expression.hpp). ISO owns no words.
struct no_own_words {
  using syntax = macro_statements;
  /// The system variable whose assignment stops the program with an alarm, `#3000 = n (MESSAGE)`
  /// (FANUC Custom Macro B; Haas), read as an alarm stop; 0 for none (LinuxCNC's #3000 is a
  /// parameter like the others).
  static constexpr long alarm_parameter = 3000;
  /// Whether G28 / G30 go to positions the control keeps in parameters (LinuxCNC #5161–#5166,
  /// #5181–#5186) rather than to the machine's reference points (Fanuc, Haas).
  static constexpr bool stored_homes = false;
  /// A `(` inside a comment opens a nested one (lexer.hpp, `comment_nesting`).
  static constexpr comment_nesting comments = comment_nesting::nested;
  static interp::parameter_rules parameter_rules() { return macro_parameter_rules(); }
  static parsed_expression read_value(std::string_view text, std::size_t line, std::size_t column) {
    return iso::read_value(text, line, column);
  }
  std::optional<lex_problem> line(std::string_view, std::size_t, std::size_t) { return std::nullopt; }
  /// Whether letter `l` takes a whole number, so that the control rounds a parameter used there to
  /// the nearest one (`S#1` with `#1 = 1000.5` is S1001, `H#1` with `#1 = 1.4` is H1: FANUC
  /// Custom Macro B, "real versus integer values") and refuses a fraction written there
  /// (`S8000.5`: S is no decimal-point address, Mitsubishi M700V §5.3). LinuxCNC's `own_words`
  /// answers for LinuxCNC, whose S is a real.
  static bool whole_address(char l) { return l == 'S' || l == 'T' || l == 'H' || l == 'D' || l == 'M' || l == 'P'; }
  /// Whether a number written at letter `l` without a decimal point counts least input
  /// increments or whole units as a parameter of the control sets (decimal point input I or II:
  /// `X10` is 0.010 mm or 10 mm; FANUC, Mitsubishi M700V §5.3), so that the reader refuses a
  /// non-zero one. A parameter's value (`X#1`) is always in units. LinuxCNC's integers are units.
  static bool point_decides_unit(char l) { return std::string_view("XYZABCIJKR").find(l) != std::string_view::npos; }
  template <class Error>
  void take(std::vector<word>&, block&, Error&&) {}
  template <class Error>
  void check(const block&, Error&&) {}
};

}  // namespace kin5::program::iso::detail
