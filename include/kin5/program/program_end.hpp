/// @file program/program_end.hpp
/// Where a program stops running on its source control, block by block: at its first end (a
/// block with `program_end`: M2 / M30, END PGM, FINI) or at an M2 / M30 M function (a Heidenhain
/// `L … M30` stops the run there; its END PGM only closes the text). A block after that point
/// never runs on the source control. A writer of another dialect asks `after_end` of every block:
/// a block there that holds only a comment, blanks, framing or another end is written as its
/// comment at most (the target's own end is already written, never a second one); any other
/// block is refused, `FILE:LINE: block after the program end (line N): the source control never
/// runs it`, since written after the target's end it would not run either and before it, it
/// would run where the source never did.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "block.hpp"

namespace kin5::program {

/// Whether block `b` ends the program run: `program_end`, or an M2 / M30 M function.
inline bool ends_program(const block& b) {
  return b.program_end || std::any_of(b.m_codes.begin(), b.m_codes.end(), [](int m) { return m == 2 || m == 30; });
}

/// Whether block `b` says nothing a control acts on: a comment, blanks, a block number, a
/// program end (with the unit an `END PGM` repeats), framing (`%`, `;$PATH=`) or text carried
/// over unread (a comment in another dialect).
inline bool without_effect(const block& b) {
  block content = b;
  content.where = {};
  content.call_chain = 0;
  content.text.clear();
  content.number.reset();
  content.comment.reset();
  if (content.program_end) content.metric.reset();  // END PGM NAME MM: BEGIN PGM's unit again
  content.program_end.reset();
  content.passthrough = content.framing = false;
  return content == block{};
}

/// The end of the source program, as a writer of another dialect meets its blocks (see the
/// file comment).
class source_end {
 public:
  /// Whether `b` comes after the source's end (the writer then writes its comment at most);
  /// throws `std::invalid_argument` for such a block with an effect. Call once per block, in order.
  bool after_end(const block& b) {
    if (end_line_) {
      if (!without_effect(b))
        throw std::invalid_argument(b.where.file + ":" + std::to_string(b.where.line) +
                                    ": block after the program end (line " + std::to_string(*end_line_) +
                                    "): the source control never runs it");
      return true;
    }
    if (ends_program(b)) end_line_ = b.where.line;
    return false;
  }

  /// Whether a block seen so far ended the program.
  bool ended() const { return end_line_.has_value(); }

 private:
  std::optional<std::size_t> end_line_;  // the line of the block that ended the program
};

}  // namespace kin5::program
