/// @file translate/source_checks.hpp
/// Checks of an NC block against its own machine, before any kinematics: a program that does
/// not fit the machine it names cannot mean anything on another one.
///
///  - a rotary axis word the machine does not have (`A+30` for `dmu-80p`, whose rotary axes are
///    B and C) is an error at the word: the reader has no machine and keeps it, and the
///    kinematics would drop it — silently, were it not checked;
///  - a word the reader kept without interpreting it whose effect another dialect would lose as
///    a comment (`check_kept_words`: an ISO `G43` without tracking, Siemens `D0`, …) is an error;
///  - a tool called by name where the output dialect takes only numbers and the user maps none
///    (`check_tool_name`, tool_map.hpp) is an error at the block;
///  - a spindle speed with a fraction where the output controller reads S as a whole number
///    (`check_spindle_speed`) is an error at the word;
///  - a dwell the output controller cannot take (`check_dwell`: too long, or finer than its
///    step) is an error at the block;
///  - a rotary value outside its axis' travel by more than the angle tolerance
///    (`angle_tolerance.hpp`) is an error naming the travel (A−150 on `sajo-12000p`, whose A
///    travels over [−120°, 30°]).
///
/// Both are checked in every block with axis words, machine-coordinate moves included. The
/// reader keeps no column per word, so the word is found again in the block's first line
/// (`program::for_each_address_word`); where it is not found there, the block's start is named.
/// @code
///   kin5::translate_detail::source_context ctx{source_language, 0.0005_deg, &result};
///   if (!kin5::translate_detail::check_source_axes(kin5::machines::sajo_12000p::model, block, ctx)) fail();
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../core/units.hpp"
#include "../kinematics/machine.hpp"
#include "../program/address_words.hpp"
#include "../program/block.hpp"
#include "../program/dialect.hpp"
#include "../program/machine_functions.hpp"
#include "angle_tolerance.hpp"
#include "m_codes.hpp"
#include "options.hpp"
#include "tool_map.hpp"
#include "work_offset_map.hpp"

namespace kin5::translate_detail {

/// What the source checks of one program need: its dialect, the angle tolerance, and where
/// diagnostics go (nowhere in the second pass, which sees the same blocks again).
struct source_context {
  program::dialect language{};
  degrees tolerance = widest_default_angle_tolerance;
  translation* out = nullptr;
  std::string_view machine_option = "--from";  ///< the option that names the source machine
  program::dialect output{};  ///< the dialect written
  const m_map* m_codes = nullptr;                        ///< the user's M mapping (`--m-map`), if any
  const work_offset_map* work_offsets = nullptr;         ///< the user's work-offset mapping, if any
  /// Decimals of the program's X Y Z (program/resolution.hpp): how finely its points are known.
  std::optional<int> linear_decimals{};
};

/// An address word of block `b` found again in its first line: where it starts and how it is
/// written; empty when it is not found there.
struct located_word {
  program::source_location where;
  std::string text;
};

/// The first word with letter `letter` (and value `value`, when given) in the first line of `b`
/// (see the file comment).
inline std::optional<located_word> locate_word(const program::block& b, char letter, program::dialect language,
                                               std::optional<double> value = std::nullopt) {
  const std::string_view text = b.text;
  const std::string_view line(text.data(), std::min(text.find('\n'), text.size()));  // the first line
  std::size_t first = 0;  // b.where names the first non-blank byte of the line
  while (first < line.size() && program::is_space(line[first])) ++first;
  std::optional<located_word> found;
  program::for_each_address_word(line, language, [&](const program::address_word& w) {
    if (found || w.letter != letter || w.offset < first) return;
    if (value && !(std::abs(std::strtod(std::string(w.text.substr(w.text[1] == '=' ? 2 : 1)).c_str(), nullptr) -
                            *value) < 1e-9))
      return;
    program::source_location where = b.where;
    where.column = b.where.column + (w.offset - first);
    found = located_word{where, std::string(w.text)};
  });
  return found;
}

/// `v` with as few decimals as it needs, at most 6: "-120", "30", "0.0005".
inline std::string short_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  std::string s(buf);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

/// `v` degrees as `short_number` writes it, with the degree sign.
inline std::string degrees_text(double v) { return short_number(v) + "°"; }

/// The rotary words of `b` that machine From checks: letter and value, in A B C order.
struct rotary_value {
  char letter;
  std::optional<double> value_deg;
};
inline std::array<rotary_value, 3> rotary_values(const program::block& b) {
  return {{{'A', b.axes.a_deg}, {'B', b.axes.b_deg}, {'C', b.axes.c_deg}}};
}

/// "B and C", "A": the rotary letters of machine `m`, in alphabetical order.
inline std::string rotary_letters(const machine_model& m) {
  std::string s;
  for (char letter : {'A', 'B', 'C'})
    if (m.rotary_index(static_cast<axis_letter>(letter)) < m.rotary_count)
      s += std::string(s.empty() ? "" : " and ") + letter;
  return s;
}

/// Checks block `b` of a program for machine `from` (see the file comment); false when it has
/// an error, reported to `ctx.out` when given. The same answer in every pass.
inline bool check_source_axes(const machine_model& from, const program::block& b, const source_context& ctx) {
  bool ok = true;
  for (const rotary_value& w : rotary_values(b)) {
    if (!w.value_deg) continue;
    const auto word_at = [&] {  // where the word stands and how it is written: for a message only
      const auto located = locate_word(b, w.letter, ctx.language);
      return located ? *located : located_word{b.where, std::string(1, w.letter) + short_number(*w.value_deg)};
    };
    const std::size_t i = from.rotary_index(static_cast<axis_letter>(w.letter));
    if (i == from.rotary_count) {
      ok = false;
      if (!ctx.out) continue;
      const auto [where, word] = word_at();
      ctx.out->errors.push_back({where,
                                 word + ": " + std::string(from.geometry.id) + " has no " + w.letter +
                                     " axis (its rotary axes are " + rotary_letters(from) +
                                     "): the program is not for this machine",
                                 word, std::string(ctx.machine_option)});
      continue;
    }
    const rotary_travel& travel = from.rotary(i).travel;
    if (travel.continuous) continue;
    const double v = *w.value_deg;
    const double excess = v < travel.lower.value ? travel.lower.value - v : v - travel.upper.value;
    if (!(excess > ctx.tolerance.value) && std::isfinite(v)) continue;
    ok = false;
    if (!ctx.out) continue;
    const auto [where, word] = word_at();
    ctx.out->errors.push_back(
        {where,
         word + ": outside the travel of " + w.letter + " on " + std::string(from.geometry.id) + ", [" +
             degrees_text(travel.lower.value) + ", " + degrees_text(travel.upper.value) + "], by " +
             degrees_text(excess) + " (angle tolerance " + degrees_text(ctx.tolerance.value) + ")",
         word, excess <= 10.0 * ctx.tolerance.value ? "--angle-tolerance" : ""});
  }
  return ok;
}

/// `check_source_axes` for machine type From.
template <machine From>
bool check_source_axes(const program::block& b, const source_context& ctx) {
  return check_source_axes(From::model, b, ctx);
}

/// Checks the M functions of block `b`, its state words' and its numbers, against the output
/// dialect (m_codes.hpp): each is
/// carried when its meaning is shared or the user maps it, else refused at its word. False on
/// an error, reported to `ctx.out` when given.
inline bool check_m_codes(const program::block& b, const source_context& ctx) {
  bool ok = true;
  std::vector<int> ms;  // the state words as their M functions (machine_functions.hpp), then the numbers
  (void)program::m_words_of(b, {}, true, ms);  // what no M function says is the writer's to refuse
  for (int m : ms) {
    if (shared_m_code(m, ctx.language, ctx.output, b.machine_coordinates)) continue;
    if (ctx.m_codes && ctx.m_codes->target_of(m)) continue;
    ok = false;
    if (!ctx.out) continue;
    const auto located = locate_word(b, 'M', ctx.language, static_cast<double>(m));
    const std::string word = "M" + std::to_string(m);
    ctx.out->errors.push_back(
        {located ? located->where : b.where,
         word + ": an M function of " + std::string(program::name(ctx.language)) +
             " whose meaning is the machine maker's; it is not written into " +
             std::string(program::name(ctx.output)) + " (--m-map " + std::to_string(m) + "=N renames it, --m-map " +
             std::to_string(m) + "= drops it)",
         word, "--m-map " + std::to_string(m) + "="});
  }
  return ok;
}

/// Checks the spindle speed of block `b` against the output dialect: where the controller reads S
/// as a whole number (`controller::whole_spindle_speed`: ISO/Fanuc), a speed with a fraction
/// (`TOOL CALL 1 Z S8000.5`, `SPINDL/RPM,8000.5`) has no spelling there and is refused at its
/// word. False on an error, reported to `ctx.out` when given.
inline bool check_spindle_speed(const program::block& b, const source_context& ctx) {
  const double s = *b.spindle_rpm;
  if (!program::controller_of(ctx.output).whole_spindle_speed || std::floor(s) == s) return true;
  if (ctx.out) {
    const auto located = locate_word(b, 'S', ctx.language, s);
    const std::string word = located ? located->text : "S" + short_number(s);
    ctx.out->errors.push_back({located ? located->where : b.where,
                               word + ": " + std::string(program::name(ctx.output)) +
                                   " reads a spindle speed as a whole number of revolutions per minute (S takes no "
                                   "decimal point): " + short_number(s) + " cannot be written there",
                               word});
  }
  return false;
}

/// Checks the dwell of block `b` against the output dialect's controller (`controller::dwell`,
/// program/dwell.hpp): refused at the block when it cannot dwell that long or that finely (a
/// Heidenhain Cycle 9 is 0 to 3600 s in steps of 0.001 s). False on an error, reported to
/// `ctx.out` when given.
inline bool check_dwell(const program::block& b, const source_context& ctx) {
  const std::string why = program::dwell_refusal(program::controller_of(ctx.output).dwell, *b.state.dwell_s,
                                                 "the " + std::string(program::name(ctx.output)) + " controller");
  if (why.empty()) return true;
  if (ctx.out) ctx.out->errors.push_back({b.where, why, "dwell"});
  return false;
}

/// Checks the work offset block `b` selects against the output dialect (work_offset_map.hpp):
/// refused at its word when the target has no certain equivalent and the user maps none. False
/// on an error, reported to `ctx.out` when given.
inline bool check_work_offset(const program::block& b, const source_context& ctx) {
  const program::work_offset& w = *b.state.work_offset;
  static const work_offset_map none;
  const work_offset_translation t = work_offset_into(w, ctx.language, ctx.output, ctx.work_offsets ? *ctx.work_offsets : none);
  if (t.refusal.empty()) return true;
  if (ctx.out) {
    const std::string source_name = program::capabilities_of(ctx.language).spelled(w);  // "G154 P7", "G55"
    const double g = w.family == program::work_offset_family::g54        ? 53.0 + w.number
                     : w.family == program::work_offset_family::extended ? std::strtod(source_name.c_str() + 1, nullptr)
                                                                         : (w.number == 0 ? 500.0 : w.number);
    const auto located = w.family == program::work_offset_family::preset ? std::nullopt : locate_word(b, 'G', ctx.language, g);
    ctx.out->errors.push_back({located ? located->where : b.where, t.refusal, source_name,
                               "--work-offset-map " + map_key(w, ctx.language) + "="});
  }
  return false;
}

/// Checks the tool block `b` calls by name against the output dialect (tool_map.hpp): refused
/// at the block when the target takes only numbers (a name the user maps is a number by now).
/// False on an error, reported to `ctx.out` when given.
inline bool check_tool_name(const program::block& b, const source_context& ctx) {
  const std::string why = tool_name_refusal(*b.tool_name, ctx.language, ctx.output);
  if (why.empty()) return true;
  if (ctx.out) ctx.out->errors.push_back({b.where, why, "tool name", "--tool-map " + *b.tool_name + "="});
  return false;
}

/// What a word that the reader kept without interpreting it (`block::kept_words`) does, when a
/// program of another dialect could only carry it as a comment and so lose it; empty when it is
/// harmless as a comment (plane, absolute mode, cancels, path-smoothing modes, …). Each dialect
/// lists its own (`lost_as_comment` of its entry, program/dialect.hpp). Work offsets (G54 …) are
/// not listed there: they are translated by their own table.
inline std::string lost_kept_word(std::string_view word, program::dialect from) {
  std::string w;
  for (char c : word)
    if (!program::is_space(c)) w.push_back(program::to_upper(c));
  return std::string(program::lost_as_comment(from, w));
}

/// Checks the kept words of block `b` against the output dialect: in a program of another
/// dialect a kept word becomes a comment (`carry_over`), so one whose effect would be lost
/// (`lost_kept_word`) is refused at the block. False on an error, reported to `ctx.out` when given.
inline bool check_kept_words(const program::block& b, const source_context& ctx) {
  if (ctx.language == ctx.output) return true;
  bool ok = true;
  for (const std::string& w : b.kept_words) {
    const std::string what = lost_kept_word(w, ctx.language);
    if (what.empty()) continue;
    ok = false;
    if (ctx.out)
      ctx.out->errors.push_back({b.where,
                                 w + ": " + what + " of " + std::string(program::name(ctx.language)) +
                                     " is not translated into " + std::string(program::name(ctx.output)) +
                                     " yet (it would become a comment)",
                                 w});
  }
  return ok;
}

}  // namespace kin5::translate_detail
