/// @file translate/carry_over.hpp
/// Dialect text a translation carries over without interpreting it. A block the reader did not
/// understand (`passthrough`) and the words it kept without interpreting them (`kept_words`:
/// G40, G54, H1, …) mean something only in the source dialect, so in a program of another
/// dialect they travel as a comment, never as code (`carry_over`). The working plane
/// (`state.working_plane`, and kept G17/G18/G19) is rewritten through the setup rotation, as arc
/// planes are (`map_plane_words`), or refused when the plane has no principal image on the target.
/// @code
///   program::block o = b;
///   if (auto error = map_plane_words(o, target_R_source)) fail(*error);
///   carry_over(o, source_language, output_language);
///   // o.kept_words is empty; o.comment ends with "siemens: G40 G54"
/// @endcode
#pragma once

#include <optional>
#include <string>

#include "../core/vec.hpp"
#include "../program/block.hpp"
#include "../program/dialect.hpp"
#include "../program/text.hpp"
#include "arc_plane.hpp"

namespace kin5::translate_detail {

/// Maps the plane-selection words G17/G18/G19 kept in a block through the setup rotation
/// `target_R_source`; the reason, when a plane has no principal image on the target.
inline std::optional<std::string> map_plane_words(program::block& b, const mat3& target_R_source) {
  if (auto& p = b.state.working_plane) {  // G17/G18/G19 read as the working plane
    const auto mapped = principal_plane(target_R_source * plane_normal(*p));
    if (!mapped) return "working plane " + std::string(plane_name(*p)) + " has no principal image on the target";
    p = mapped->first;
  }
  for (auto& w : b.kept_words) {
    std::string upper;
    for (char c : w) upper.push_back(program::to_upper(c));
    if (upper != "G17" && upper != "G18" && upper != "G19") continue;
    const program::arc_plane p = upper == "G17"   ? program::arc_plane::xy
                                 : upper == "G18" ? program::arc_plane::zx
                                                  : program::arc_plane::yz;
    const auto mapped = principal_plane(target_R_source * plane_normal(p));
    if (!mapped) return "plane selection " + w + " cannot be mapped: plane " + std::string(plane_name(p)) +
                        " has no principal image on the target";
    w = mapped->first == program::arc_plane::xy ? "G17" : (mapped->first == program::arc_plane::zx ? "G18" : "G19");
  }
  return std::nullopt;
}

/// Makes `b` a block of dialect `to`: text kin5 did not interpret (`passthrough`) and words it
/// kept without interpreting (`kept_words`) mean something only in the source dialect `from`, so
/// they travel as a comment instead of being written as code, as does an alarm stop's number (the
/// target writes its own). A CL data statement that is not
/// passed through is read whole into the model (the APT reader refuses the rest), and the
/// statements it keeps (`MULTAX`) say how CL records are laid out, nothing an NC program has:
/// neither its text nor its kept words travel.
inline void carry_over(program::block& b, program::dialect from, program::dialect to) {
  if (from == to) return;
  if (!b.passthrough && program::capabilities_of(from).cl_data) {
    b.text.clear();
    b.kept_words.clear();
    return;
  }
  std::string note;
  if (b.passthrough) {
    note = b.text;  // the whole line, its own comment included
    b.passthrough = false;
    b.comment.reset();
  } else if (!b.kept_words.empty()) {
    note = std::string(program::name(from)) + ":";
    for (const auto& w : b.kept_words) note += " " + w;
  }
  // An alarm number names a text of the source's control only: the target's writer writes its
  // own (alarm_stop.hpp), and the source's travels as a comment.
  if (b.alarm && b.alarm->number) {
    note += (note.empty() ? "" : " ") + std::string(program::name(from)) + ": alarm " + std::to_string(*b.alarm->number);
    b.alarm->number.reset();
  }
  b.kept_words.clear();
  if (!note.empty()) b.comment = b.comment ? *b.comment + " | " + note : note;
}

/// `b` as it goes into a program of another dialect (see `carry_over`).
inline program::block carried_over(program::block b, program::dialect from, program::dialect to) {
  carry_over(b, from, to);
  return b;
}

}  // namespace kin5::translate_detail
