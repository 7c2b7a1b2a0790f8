/// @file program/dialect_id.hpp
/// What names a dialect at run time and what every dialect declares of itself, as data:
/// `dialect` (its place in `program::dialects`, so a new entry needs no enum), what its writer can
/// express (`capabilities`), what its controller reads (`controller`), the words its reader keeps
/// whose effect a comment would lose (`kept_word_effect`), and the text that gives a file away as
/// written in it (`marker`).
///
/// Each entry of `program::dialects` (program/dialect.hpp) carries one `capabilities`, one
/// `controller` and an array of `marker`s; the translation asks them (can the target write G93?
/// how many decimals does its controller read?), and `guess_dialect` looks for the markers.
/// `dialect_order` names the entries in the list's order, so a dialect's folder knows its own id
/// and another's (`id_named("iso")`, `id_of<D>()`) without including the list and so every other
/// dialect; program/dialect.hpp checks that the two orders agree.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "dwell.hpp"
#include "resolution.hpp"
#include "work_offsets.hpp"

namespace kin5::program {

/// A dialect at run time: its index in `program::dialects` (or in the list a fold is given).
/// The default is the first entry of the list.
class dialect {
 public:
  constexpr dialect() = default;
  constexpr explicit dialect(std::size_t index) : index_(static_cast<std::uint8_t>(index)) {}
  /// Its place in the list.
  constexpr std::size_t index() const { return index_; }
  friend constexpr bool operator==(dialect, dialect) = default;

 private:
  std::uint8_t index_ = 0;
};

/// The name the dialect folders use for `program::dialect` (each folder has a `dialect` of its own).
using dialect_id = dialect;

/// The names of the entries of `program::dialects`, in its order: a dialect's id is its name's
/// place here. program/dialect.hpp asserts that the list and this table agree, so a new entry
/// there needs its name here, in the same place.
inline constexpr std::array<std::string_view, 6> dialect_order{"siemens", "heidenhain", "iso",
                                                               "linuxcnc", "haas", "apt"};

/// The dialect named `name` in `dialect_order`; a name that is not there does not compile.
consteval dialect id_named(std::string_view name) {
  for (std::size_t i = 0; i < dialect_order.size(); ++i)
    if (dialect_order[i] == name) return dialect(i);
  throw "id_named: no entry of dialect_order has this name";
}

/// Entry D of `program::dialects` as a run-time value (its `name`'s place in `dialect_order`).
template <class D>
constexpr dialect id_of() {
  return id_named(D::name);
}

/// What a dialect's writer can express. Each flag is checked against the writer by the dialect
/// law suite: a capability that is false makes the writer refuse (or, for TCP switches, note) the
/// construct; one that is true writes it so that the dialect's reader reads it back.
struct capabilities {
  bool cl_data = false;            ///< cutter-location data: tool tip and tool axis, no machine axes (APT)
  bool inverse_time_feed = false;  ///< feed as 1 / block time (G93, FEDRAT/INVERS)
  bool tcp_switch = false;         ///< words that switch tool-tip tracking on and off (TRAORI, M128, G43.4)
  bool rotary_axis_words = false;  ///< A B C axis words
  bool tool_axis_vectors = false;  ///< a tool-axis vector in a motion block (A3=, TX, G43.5 I J K, GOTO/…,i,j,k)
  bool arcs = false;               ///< circular moves
  bool arc_centre_block = false;   ///< an arc's centre is a modal block of its own (Heidenhain CC)
  bool tool_names = false;         ///< a tool called by name (T="MILL_D10", TOOL CALL "MILL_D10")
  /// The work offsets its writer selects, each range in the dialect's own form (G54, G54.1 P n,
  /// G505, CYCL DEF 247 Q339=n); a selection in none of them is refused (docs/dialects/*.md).
  std::array<work_offset_names, 3> work_offsets{};

  /// Whether the writer selects work offset `w`.
  constexpr bool writes(const work_offset& w) const {
    for (const work_offset_names& r : work_offsets)
      if (r.holds(w)) return true;
    return false;
  }

  /// Work offset `w` as this dialect spells it ("G154 P7" for Haas), else as `spelling` does.
  std::string spelled(const work_offset& w) const {
    for (const work_offset_names& r : work_offsets)
      if (r.holds(w) && !r.code.empty()) return std::string(r.code) + std::to_string(w.number);
    return spelling(w);
  }
};

/// What a dialect's controller reads, beyond its words: how finely it takes numbers, which
/// comments its text has, the M functions whose meaning is not the common one, its dwells. Each
/// dialect's folder cites the manual for its values (docs/dialects/<name>.md).
struct controller {
  word_decimals usual;   ///< decimals written when the source is no finer
  word_decimals finest;  ///< the controller's input resolution
  bool paren_comments = false;  ///< `( … )` is a comment (ISO), not text to read
  bool m7_mist_coolant = true;  ///< M7 is mist coolant (false: no standard M7, as on a TNC)
  bool m91_m92_machine_coordinates = false;  ///< M91/M92 in a block: it moves in machine coordinates
  /// S takes a whole number of revolutions per minute (Fanuc: a decimal point in S is an alarm,
  /// another control drops the fraction): a spindle speed with a fraction cannot be written.
  bool whole_spindle_speed = false;
  dwell_input dwell{};  ///< the dwells it takes (dwell.hpp): a dwell outside them is refused
  /// The working plane turns the tool length: under G18/G19 a milling tool's length acts along Y/X
  /// (and turns a TRAORI tool orientation), not along the tool axis (SINUMERIK 840D).
  bool plane_turns_tool_length = false;
  /// M5, M9 and M6 in a block that moves act before its move (LinuxCNC's order of execution);
  /// false: M5 and M9 act at the block's end, after the move (TNC, 840D, Fanuc), and when M6
  /// acts is the machine maker's choice. M3, M4, M7, M8 act at the start and M0, M1, M2, M30 at
  /// the end in every kin5 dialect. docs/dialects/apt.md, "M functions on a moving block".
  bool spindle_off_before_motion = false;
  /// The cutter radius compensation's entry move ends tangent to the entry line, not at the
  /// contour's start (LinuxCNC; docs/dialects/compensation.md): between two controls that differ
  /// here the approach cuts differently, so compensation is not translated.
  bool tangent_compensation_entry = false;
};

/// What the controller of dialect `d` reads, asked from the folder of entry `Self`, which cannot
/// name the list (`controller_of`; defined in program/dialect.hpp, after the list).
template <class Self>
constexpr controller controller_from(dialect d);

/// What kept word `word` (upper case, no spaces) of dialect `d` does that a comment would lose
/// (`lost_as_comment`), asked from the folder of entry `Self`; empty when nothing. Defined in
/// program/dialect.hpp, as `controller_from` is.
template <class Self>
constexpr std::string_view lost_from(dialect d, std::string_view word);

/// A word that a dialect's reader keeps without interpreting it (`block::kept_words`) and whose
/// effect a program of another dialect would lose as a comment: a translation into another
/// dialect refuses it (translate/source_checks.hpp). Words are compared upper case, spaces removed.
struct kept_word_effect {
  enum class match {
    whole,   ///< the word itself ("D0")
    prefix,  ///< any word that starts with it ("T=")
    code,    ///< its letter with the same number, however written ("G4": G4, G04, G4.0)
    other_code,  ///< its letter with another number above 0 ("D1": D2, D17; not D1, not D0)
  };
  std::string_view word;
  match how = match::whole;
  std::string_view effect;  ///< what the word does, for the message ("a dwell")

  /// Whether word `w` (upper case, no spaces) is this one.
  constexpr bool matches(std::string_view w) const {
    if (how == match::whole) return w == word;
    if (how == match::prefix) return w.substr(0, word.size()) == word;
    if (w.empty() || word.empty() || w[0] != word[0]) return false;
    const double n = number_of(w.substr(1));
    if (how == match::code) return n == number_of(word.substr(1));
    return n > 0 && n != number_of(word.substr(1));
  }

 private:
  /// The value of an unsigned decimal number ("04", "4.0"); -1 for any other text.
  static constexpr double number_of(std::string_view s) {
    double value = 0, scale = 1;
    bool point = false, digits = false;
    for (char c : s) {
      if (c == '.' && !point) {
        point = true;
      } else if (c >= '0' && c <= '9') {
        digits = true;
        if (point) scale /= 10;
        value = value * (point ? 1 : 10) + (c - '0') * (point ? scale : 1);
      } else {
        return -1;
      }
    }
    return digits ? value : -1;
  }
};

static_assert(kept_word_effect{"G4", kept_word_effect::match::code, ""}.matches("G04"));
static_assert(!kept_word_effect{"G4", kept_word_effect::match::code, ""}.matches("G40"));
static_assert(kept_word_effect{"D1", kept_word_effect::match::other_code, ""}.matches("D2"));
static_assert(kept_word_effect{"D1", kept_word_effect::match::other_code, ""}.matches("D12"));
static_assert(!kept_word_effect{"D1", kept_word_effect::match::other_code, ""}.matches("D01"));
static_assert(!kept_word_effect{"D1", kept_word_effect::match::other_code, ""}.matches("D0"));
static_assert(!kept_word_effect{"D1", kept_word_effect::match::other_code, ""}.matches("DX"));

/// Text only one dialect writes, as `guess_dialect` looks for it: an upper-case keyword matched
/// case-insensitively, either at the start of a block (after an optional block number) or as a
/// word anywhere in a line (not glued to a letter or digit before it, nor to a digit after it).
struct marker {
  enum class place { block_start, anywhere };
  std::string_view keyword;
  place where = place::anywhere;
};

}  // namespace kin5::program
