/// @file program/canonical/text.hpp
/// Canonical operations of a block's text: where a block begins (its number and text as
/// written), the program's name, comments, an alarm stop, and the text a block keeps without
/// meaning to motion (framing, text passed through, a parameter assignment, kept words).
#pragma once

#include <optional>
#include <string>

#include "../alarm_stop.hpp"
#include "origin.hpp"

namespace kin5::program::canonical {

/// A block begins: every block's operations start with this one. Its text is the whole
/// statement as written (without the line ending), which `framing`, `pass_through` and
/// `parameter_assignment` keep.
struct block_start {
  static constexpr std::string_view kind_name = "block_start";
  origin from;
  std::optional<long long> number;  ///< N number, Heidenhain block number
  std::string text;
  friend bool operator==(const block_start&, const block_start&) = default;
};

/// The program begins, with its name (BEGIN PGM, `%` O…, PARTNO).
struct begin_program {
  static constexpr std::string_view kind_name = "begin_program";
  origin from;
  std::string name;
  friend bool operator==(const begin_program&, const begin_program&) = default;
};

/// A comment, without its delimiters.
struct comment {
  static constexpr std::string_view kind_name = "comment";
  origin from;
  std::string text;
  friend bool operator==(const comment&, const comment&) = default;
};

/// The program stops here with an alarm (alarm_stop.hpp).
struct raise_alarm {
  static constexpr std::string_view kind_name = "raise_alarm";
  origin from;
  alarm_stop alarm;
  friend bool operator==(const raise_alarm&, const raise_alarm&) = default;
};

/// The block's text only frames the program for transfer or storage (`%`, `;$PATH=…`).
struct framing {
  static constexpr std::string_view kind_name = "framing";
  origin from;
  friend bool operator==(const framing&, const framing&) = default;
};

/// The block's text is not understood and has no axis words: kept as text, never interpreted.
struct pass_through {
  static constexpr std::string_view kind_name = "pass_through";
  origin from;
  friend bool operator==(const pass_through&, const pass_through&) = default;
};

/// The block's text assigns a parameter (`#1=500.`, `R1=5000`), whose value its readers put in
/// every word that uses it: kept as text, understood.
struct parameter_assignment {
  static constexpr std::string_view kind_name = "parameter_assignment";
  origin from;
  friend bool operator==(const parameter_assignment&, const parameter_assignment&) = default;
};

/// A word that does not change geometry and has no meaning of its own in the model (G64, H1,
/// …), as written: a writer of the same dialect writes it back, another one into a comment.
struct kept_word {
  static constexpr std::string_view kind_name = "kept_word";
  origin from;
  std::string word;
  friend bool operator==(const kept_word&, const kept_word&) = default;
};

}  // namespace kin5::program::canonical
