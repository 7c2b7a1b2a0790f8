/// @file program/siemens/reader.hpp
/// The second stage of the Siemens reader: the words of a line (lexer.hpp) become a `block`, with
/// the modal state (motion word, plane, last point) applied across lines.
///
/// Reading rules (docs/dialects/siemens.md lists every word): `TRAORI` / `TRAFOOF` switch
/// tool-tip tracking, `A3= B3= C3=` give a tool-axis vector, `I J K` (incremental from the last
/// programmed point) or `CR=` give arcs, `SUPA` / `G53` / `G153` mean machine coordinates.
/// `G70`/`G700` inch blocks are read in millimetres (`units`). `G41`/`G42`/`G40` are cutter
/// radius compensation with the first edge `D1` only (`compensation`). The program runs under the
/// interpreter (../interp/executor.hpp) with the Siemens syntax (statements.hpp): labels, jumps,
/// IF, loops and section repeats are executed, and each line executed is read here, with its R
/// parameters and variables evaluated (parameters.hpp), so the blocks are the executed program.
/// `G91`, `X=IC(…)` and `X=AC(…)` are resolved to the positions they reach
/// (`incremental_words`). Active frame changes (`TRANS`, `ROT`, `CYCLE800`,
/// …) are errors. A line without geometry that is not understood is kept verbatim (`passthrough`).
/// Most lines of a long program (`N… G1 X… Y… Z… A… B… F…`) are read in one scan
/// (`read_plain_motion`), which a law holds equal to the word-by-word reading.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../called_files.hpp"
#include "../interp/executor.hpp"
#include "../read_limits.hpp"
#include "../lexing.hpp"
#include "../modal.hpp"
#include "../number.hpp"
#include "../text.hpp"
#include "../transmission.hpp"
#include "../units.hpp"
#include "lexer.hpp"
#include "modal.hpp"
#include "parameter_rules.hpp"
#include "parameters.hpp"
#include "statements.hpp"
#include "vocabulary.hpp"
#include "words.hpp"

namespace kin5::program::siemens::detail {

/// Puts frame words into the block (alone) or the errors (with geometry or frame arguments).
inline void frame_words(line_parse& p) {
  for (const auto& [word, column] : p.frame_words) {
    if (p.has_geometry || p.frame_arguments)
      keep_or_count(p.errors, p.errors_not_kept, {{p.b.where.file, p.b.where.line, column + 1}, frame_message(word)});
    else
      p.b.kept_words.push_back(word);
  }
}

/// Whether the line is kept verbatim: not understood, no geometry, and known to change nothing
/// (`changes_nothing`), or a lone MSG. A line not understood that may change something is refused.
inline bool is_passthrough(const line_parse& p) {
  const bool only_msg = p.has_msg && !p.has_content && !p.has_geometry && p.unknown.empty() && !p.b.moves();
  return (!p.unknown.empty() && !p.has_geometry && (p.only_assignments || changes_nothing(p.b.text))) || only_msg;
}

/// The tool-axis vector from A3= B3= C3=.
inline void tool_axis_vector(line_parse& p, std::vector<diagnostic>& errors) {
  const auto& v = p.vector;
  if (!v[0] && !v[1] && !v[2]) return;
  const source_location at{p.b.where.file, p.b.where.line, p.vector_column + 1};
  if (!v[0] || !v[1] || !v[2]) errors.push_back({at, "tool-axis vector needs A3, B3 and C3"});
  else if (p.b.axes.has_rotary()) errors.push_back({at, "rotary axes and a tool-axis vector in one block"});
  else if (!is_direction(*v[0], *v[1], *v[2])) errors.push_back({at, "tool-axis vector shorter than 0.001 is not a direction"});
  else p.b.axes.tool_axis = vec3{*v[0], *v[1], *v[2]};
}

/// The arc: its centre (I J K from the last programmed point) or its radius (CR=).
inline void arc(line_parse& p, const modal_state& state, std::vector<diagnostic>& errors) {
  block& b = p.b;
  const auto error = [&](std::size_t column, std::string m) {
    errors.push_back({{b.where.file, b.where.line, column + 1}, std::move(m)});
  };
  const auto& o = p.centre_offset_mm;
  const bool has_centre = o[0] || o[1] || o[2];
  if (has_centre || p.radius_mm) {
    if (!is_arc(state.motion)) {
      error(p.arc_column, "word '" + p.arc_word + "' needs G2 or G3");
    } else if (has_centre && p.radius_mm) {
      error(p.arc_column, "arc has both a centre and a radius");
    } else if (p.radius_mm) {
      b.arc = arc_words{state.plane, std::nullopt, p.radius_mm};
    } else if (const auto start = state.position()) {
      // I J K from the start point, or the centre's coordinate itself (`I=AC(…)`)
      const auto at = [&](std::size_t i, double from) { return p.centre_absolute[i] ? *o[i] : from + o[i].value_or(0.0); };
      b.arc = arc_words{state.plane, vec3{at(0, start->x), at(1, start->y), at(2, start->z)}, std::nullopt};
    } else {
      error(p.arc_column, "arc start point is not known");
    }
  } else if (is_arc(state.motion) && b.axes.has_linear()) {
    error(p.geometry_column, "arc needs a centre (I J K) or a radius (CR=)");
  }
}

/// The cutting edge a tool change activates when its block says no D: machine data 20270
/// `$MC_CUTTING_EDGE_DEFAULT`, whose default is 1 (SINUMERIK Function Manual W1, "Tool offset":
/// after a tool change edge D1 is active unless the machine data say otherwise). kin5 reads a
/// program for a control with the default, as it reads unit-less programs as metric.
inline constexpr long long default_cutting_edge = 1;

/// G41 / G42 compensate with the active cutting edge's radius, which kin5 translates only for
/// the tool's first edge: `D1`, said or the default after the last tool change
/// (`default_cutting_edge`; SINUMERIK 840D sl Fundamentals 05/2017 ch. 11 "Tool radius
/// compensation"; ch. 6: D selects the edge). Start-up and cancel (G40) are refused in a
/// circular move, a D other than D1 while compensation is on too.
inline void compensation(line_parse& p, modal_state& state, std::optional<motion_kind> before,
                         std::vector<diagnostic>& errors) {
  block& b = p.b;
  const auto error = [&](std::size_t column, std::string m) {
    errors.push_back({{b.where.file, b.where.line, column + 1}, std::move(m)});
  };
  // A D other than D1 before the change may be the one the change activates (a D written with
  // T, before M6): it stays, and G41/G42 under it are refused as for any other edge.
  if (changes_tool(b) && (!state.edge || *state.edge == 1)) state.edge = default_cutting_edge;
  if (changes_tool(b)) state.tool_loaded = true;
  if (p.edge) state.edge = *p.edge;
  // D0 switches the tool length off; D n on, with edge n of the tool loaded (before any tool
  // change there is none: the D is a kept word only). The D stays a kept word, for the Siemens
  // writer; `lost_as_comment` refuses another edge than D1 in other dialects.
  if (p.edge && (*p.edge == 0 || state.tool_loaded)) b.state.length_compensation = *p.edge != 0;
  const auto kind = b.motion ? b.motion : before;
  const bool arc = is_arc(kind) && (b.motion || b.moves());
  if (!p.radius_word) {
    if (state.startup_pending && arc)
      error(0, "a circular move starts cutter radius compensation up (G41/G42 before it): start-up is allowed only "
               "in G0/G1");
    if (b.moves()) state.startup_pending = false;
    if (p.edge && state.radius_on && *p.edge != 1)
      error(0, "D" + std::to_string(*p.edge) + " while cutter radius compensation is on: kin5 translates only the "
               "first cutting edge's radius (D1)");
    return;
  }
  const auto& [word, column] = *p.radius_word;
  const bool on = b.state.radius_compensation != cutter_side::off;
  if (arc && (on || state.radius_on))  // G40 with compensation off cancels nothing
    return error(column, word + ": cutter radius compensation " + (on ? "start-up" : "cancel") +
                             " in a circular move (allowed only in G0/G1)");
  if (on && state.edge != 1)
    return error(column, word + ": cutter radius compensation with " +
                             (state.edge ? "D" + std::to_string(*state.edge) : std::string("no D and no tool change before it")) +
                             ": kin5 translates only the first cutting edge's radius (D1 after the tool change)");
  state.radius_on = on;
  state.startup_pending = on && !b.moves();
}

/// G70 / G700 (inch) and G71 / G710 (mm) apply from their own block on. In an inch block the
/// lengths (X Y Z, I J K, CR=) become millimetres (×25.4, units.hpp) and so does F under G700
/// (in/min → mm/min; never an inverse-time F). Under G70 F stays in the control's basic unit
/// system (SINUMERIK 802D sl manual §8.2.3: G70/G71 leave the feed alone, G700/G710 convert it
/// too), which the program does not say: an F there is refused. kin5 reads G71 and unit-less
/// programs as written for a control whose basic system is metric (docs/dialects/siemens.md).
inline void units(line_parse& p, modal_state& state, std::vector<diagnostic>& errors) {
  block& b = p.b;
  if (b.feed_mode) state.inverse_time = *b.feed_mode == feed_unit::inverse_time;
  if (p.unit_g) {
    state.inch = *p.unit_g == 70 || *p.unit_g == 700;
    state.g70 = *p.unit_g == 70;
  }
  if (!state.inch) return;
  for (std::optional<double>* v : {&b.axes.x_mm, &b.axes.y_mm, &b.axes.z_mm, &p.centre_offset_mm[0],
                                   &p.centre_offset_mm[1], &p.centre_offset_mm[2], &p.radius_mm})
    if (*v) **v *= mm_per_inch;
  if (!b.feed || state.inverse_time) return;
  if (!state.g70) {
    *b.feed *= mm_per_inch;
    return;
  }
  errors.push_back({{b.where.file, b.where.line, p.feed_column + 1},
                    "F under G70 is in the control's basic unit system, which the program does not say "
                    "(G700 gives F in inch/min)"});
  b.feed.reset();
}

/// G90 / G91 and `=AC(…)` / `=IC(…)` (SINUMERIK 840D sl Programming Manual Fundamentals,
/// "Absolute dimensions (G90, AC)", "Incremental dimensions (G91, IC)"): an incremental axis word
/// is a distance from the last programmed position of its axis, linear or rotary. The block gets
/// the position the control reaches (millimetres: after `units`), so the model holds absolute
/// positions; an incremental word whose base is not known (no absolute position yet, or a
/// machine-coordinate move since: SUPA, G53, G153) is refused at the word, and so is IC or AC in
/// a machine-coordinate block, whose words are kept as written. A distance of 0 from an unknown
/// position moves nothing: the word is left out.
inline void incremental_words(line_parse& p, modal_state& state, std::vector<diagnostic>& errors) {
  block& b = p.b;
  if (p.g91) {
    if (p.g91->first && !state.incremental) state.incremental_line = b.where.line;
    state.incremental = p.g91->first;
  }
  std::optional<double>* slots[6] = {&b.axes.x_mm, &b.axes.y_mm, &b.axes.z_mm, &b.axes.a_deg, &b.axes.b_deg, &b.axes.c_deg};
  static constexpr char letters[] = "XYZABC";
  for (std::size_t i = 0; i < 6; ++i) {
    if (!*slots[i]) continue;
    if (i < 3 && state.inch) ++p.axis_decimals[i];  // ×25.4: one decimal more
    const std::size_t column = p.axis_column[i] + 1;
    const std::string letter(1, letters[i]);
    if (b.machine_coordinates) {
      if (p.axis_incremental[i])
        errors.push_back({{b.where.file, b.where.line, column},
                          letter + "=" + (*p.axis_incremental[i] ? "IC" : "AC") +
                              "(…) in a machine-coordinate block is not supported (its words are kept as written)"});
      continue;
    }
    if (!p.axis_incremental[i].value_or(state.incremental)) continue;
    if (state.last[i]) {
      const axis_position to = reached(*state.last[i], **slots[i], p.axis_decimals[i]);
      *slots[i] = to.value, p.axis_decimals[i] = to.decimals;
      continue;
    }
    if (**slots[i] == 0) {  // no distance: the axis stays wherever it is, which a block without the word says
      slots[i]->reset();
      continue;
    }
    const std::string by = p.axis_incremental[i] ? letter + "=IC(…)" : "G91 of line " + std::to_string(state.incremental_line);
    const std::string since = state.lost_line[i] ? "since the machine-coordinate move of line " + std::to_string(state.lost_line[i])
                                                 : "since the start of the program";
    errors.push_back({{b.where.file, b.where.line, column},
                      "incremental " + letter + " (" + by + ") from a position the program does not say: no absolute " +
                          letter + " " + since + ", so the move would start from wherever the machine stands; program an "
                          "absolute " + letter + " (G90) before it"});
  }
}

/// The distance mode the block says in the model (`state.distance`): a machine-coordinate block
/// the control's own (its words are kept as written), a block that moves G90 where the model's
/// G91 is in effect (its positions are absolute), another block the G90 or G91 it writes.
inline void distance_written(line_parse& p, modal_state& state) {
  block& b = p.b;
  if (b.machine_coordinates) {
    if (p.g91 || state.written_incremental != state.incremental)
      b.state.distance = state.incremental ? distance_mode::incremental : distance_mode::absolute;
    state.written_incremental = state.incremental;
  } else if (b.moves() || (b.motion && is_arc(b.motion))) {
    if (p.g91 || state.written_incremental) b.state.distance = distance_mode::absolute;
    state.written_incremental = false;
  } else if (p.g91) {
    b.state.distance = state.incremental ? distance_mode::incremental : distance_mode::absolute;
    state.written_incremental = state.incremental;
  }
}

/// `G4 F2`: a dwell of F seconds, which the 840D takes only in a block of its own (SINUMERIK
/// 840D sl Fundamentals 05/2017, "Dwell time (G4)"); no F, or other words with it, refused.
inline void dwell(line_parse& p, std::vector<diagnostic>& errors) {
  block& b = p.b;
  const auto at = [&](std::size_t column) { return source_location{b.where.file, b.where.line, column + 1}; };
  if (!p.dwell_f) return errors.push_back({at(*p.dwell_column), "G4 needs F, the dwell in seconds (G4 F2)"});
  b.state.dwell_s = p.dwell_f->first;
  if (!b.only_dwell())
    errors.push_back({at(*p.dwell_column), "G4: the 840D takes a dwell in a block of its own (N, G4 F and a comment)"});
}

/// In inverse time (G93) F stays in effect until another is given, and a switch between G93 and
/// G94 needs a new one (S1 §2.7 "Feed control": F "remains active until a new feedrate is
/// programmed"; after switching between G93, G94 and G95 it "has to be reprogrammed"). Every
/// other dialect's G93 takes an F in each feed block, so a G1, G2, G3 block without F gets the
/// one in effect written into it (`b.feed`): its time. Without one since the switch, refused at
/// the block.
inline void inverse_time_feed(block& b, modal_state& state, std::optional<motion_kind> before,
                              std::vector<diagnostic>& errors) {
  if (b.feed_mode) state.inverse_feed.reset();
  if (!state.inverse_time) return;
  if (b.feed) state.inverse_feed = *b.feed;
  const auto kind = b.motion ? b.motion : before;
  if (b.feed || !b.moves() || b.machine_coordinates || !kind || *kind == motion_kind::rapid) return;
  if (state.inverse_feed) b.feed = *state.inverse_feed;
  else errors.push_back({b.where, "feed move in inverse time (G93) without F since G93: the block's time is not "
                                  "known (write F in this block)"});
}

/// M2 / M30 end the program: carried by `program_end` only, not also in `m_codes`.
inline void program_end(block& b, const modal_state& state) {
  const bool m30 = std::find(b.m_codes.begin(), b.m_codes.end(), 30) != b.m_codes.end();
  const bool m2 = std::find(b.m_codes.begin(), b.m_codes.end(), 2) != b.m_codes.end();
  if (!m30 && !m2) return;
  b.program_end = m30 ? state.program_name.value_or("") : std::string("M2");
  b.m_codes.erase(std::remove_if(b.m_codes.begin(), b.m_codes.end(), [](int m) { return m == 2 || m == 30; }),
                  b.m_codes.end());
}

/// Applies the modal state to a read line, decides passthrough, and hands the line's
/// diagnostics to `result` in column order.
inline void finish(line_parse& p, modal_state& state, read_result& result) {
  block& b = p.b;
  if (p.control) p.unknown.clear(), p.unknown_not_kept = 0;  // the arguments of a refused jump or call
  frame_words(p);
  if (is_passthrough(p)) {
    block kept;
    kept.where = b.where;
    kept.text = b.text;
    kept.number = b.number;
    kept.passthrough = true;
    kept.assignment = b.assignment;  // `R1=500`: understood, its number put into the words using it
    b = std::move(kept);
  } else {
    for (auto& d : p.unknown) keep_or_count(p.errors, p.errors_not_kept, std::move(d));
    p.errors_not_kept += p.unknown_not_kept;
    std::stable_partition(b.kept_words.begin(), b.kept_words.end(), [](const std::string& w) { return !is_late_kept(w); });
    const std::optional<motion_kind> motion_before = state.motion;
    if (b.motion) state.motion = b.motion;
    if (p.plane) state.plane = *p.plane;
    {
      std::vector<diagnostic> found;
      units(p, state, found);
      incremental_words(p, state, found);
      for (auto& d : found) keep_or_count(p.errors, p.errors_not_kept, std::move(d));
    }
    // Checks across words only on a line whose words read cleanly: one diagnostic per problem
    // (an arc word may be the one in error: the arc is then left out).
    if (p.errors.empty()) {
      std::vector<diagnostic> found;
      if (p.dwell_column) dwell(p, found);
      tool_axis_vector(p, found);
      arc(p, state, found);
      compensation(p, state, motion_before, found);
      inverse_time_feed(b, state, motion_before, found);
      for (auto& d : found) keep_or_count(p.errors, p.errors_not_kept, std::move(d));
    }
    distance_written(p, state);
    state.move(b);
    state.reach(b, p.axis_decimals);
    program_end(b, state);
  }
  std::stable_sort(p.errors.begin(), p.errors.end(),
                   [](const diagnostic& a, const diagnostic& c) { return a.where.column < c.where.column; });
  for (auto& d : p.errors) result.add_error(std::move(d));
  for (auto& d : p.warnings) result.add_warning(std::move(d));
  result.errors_not_kept += p.errors_not_kept;
  result.warnings_not_kept += p.warnings_not_kept;
}

/// `%_N_NAME_MPF`, `%_N_NAME_SPF`, `%NAME`: the program name, or nothing if `line` is not a header.
inline std::optional<std::string> program_header(std::string_view line) {
  line = lexing::trim(line);
  if (line.empty() || line.front() != '%') return std::nullopt;
  line.remove_prefix(1);
  if (starts_with_keyword(line, "_N_")) line.remove_prefix(3);
  std::size_t n = 0;
  while (n < line.size() && is_ident_char(line[n])) ++n;
  if (n == 0 || n != line.size()) return std::nullopt;
  std::string name(line);
  if (name.size() > 4 && lexing::upper(name.substr(name.size() - 4)) == "_MPF") name.resize(name.size() - 4);
  return name;
}

/// Whether `line` is the `;$PATH=…` comment that says which directory a program is loaded
/// into: framing, like the `%_N_…` header before it.
inline bool path_line(std::string_view line) {
  line = lexing::trim(line);
  return line.size() > 7 && line.front() == ';' && lexing::upper(line.substr(1, 6)) == "$PATH=";
}

/// `PROC NAME`, a subprogram's declaration at the head of its file (SINUMERIK 840D sl
/// Programming Manual Job Planning, "Subprograms with parameter transfer"): an empty text when it
/// names the subprogram alone (a call of it needs nothing more), the refusal when it declares
/// parameters or attributes (`PROC SUB(REAL X)`, `PROC SUB SAVE`: what the call passes or restores);
/// none when `line` is no PROC line.
inline std::optional<std::string> procedure_line(std::string_view line) {
  std::size_t i = lexing::skip_blanks(line, 0);
  if (i + 1 < line.size() && to_upper(line[i]) == 'N' && is_digit(line[i + 1])) {
    while (++i < line.size() && is_digit(line[i])) {}
    i = lexing::skip_blanks(line, i);
  }
  if (!starts_with_keyword(line.substr(i), "PROC") || (i + 4 < line.size() && !is_space(line[i + 4]))) return std::nullopt;
  std::size_t k = lexing::skip_blanks(line, i + 4);
  const std::size_t name = k;
  while (k < line.size() && is_ident_char(line[k])) ++k;
  const std::size_t rest = lexing::skip_blanks(line, k);
  if (k > name && (rest == line.size() || line[rest] == ';')) return std::string();
  return "PROC " + std::string(lexing::trim(line.substr(i + 4))) +
         ": a subprogram with parameters or attributes (SAVE, DISPLOF, …) is not supported; kin5 runs a "
         "subprogram declared with its name alone";
}

/// The words of a plain motion line, as `read_plain_motion` collects them.
struct plain_motion {
  std::optional<long long> number;
  std::optional<motion_kind> motion;
  axis_words axes;
  std::optional<double> feed;

  std::array<int, 6> decimals{};  ///< X Y Z A B C: the decimals written

  /// Takes word `letter` `v`, written `text`; false if the full reader must judge it (twice, not
  /// whole, …).
  bool take(char letter, double v, std::string_view text) {
    if (is_axis_letter(letter)) decimals[axis_index(letter)] = decimals_written(text);
    auto set = [v](std::optional<double>& field) {
      if (field) return false;
      field = v;
      return true;
    };
    switch (letter) {
      case 'N':
        if (number || !lexing::is_whole(v)) return false;
        number = static_cast<long long>(v);
        return true;
      case 'G':
        if (motion || !(v == 0.0 || v == 1.0)) return false;
        motion = v == 0.0 ? motion_kind::rapid : motion_kind::linear;
        return true;
      case 'X': return set(axes.x_mm);
      case 'Y': return set(axes.y_mm);
      case 'Z': return set(axes.z_mm);
      case 'A': return set(axes.a_deg);
      case 'B': return set(axes.b_deg);
      case 'C': return set(axes.c_deg);
      case 'F': return v >= 0 && !unwritable_rate(v, finest_rate_decimals) && set(feed);  // else reported by the full reader
      default: return false;
    }
  }
};

/// The line most of a long program is made of: `N… G0|G1 X… Y… Z… A… B… C… F…`, any of those
/// words at most once each, in any order, upper case, blanks between them and nothing else. Such
/// a line is read into `b` in one scan, with the modal state moved on as `finish` would, and the
/// result is true; for any other line (or an arc in effect) nothing changes and the result is
/// false: the full reader then reads it. A law checks that both readers agree on such lines.
inline bool read_plain_motion(std::string_view line, block& b, modal_state& state) {
  if (state.inch) return false;  // the full reader converts
  if (state.incremental || state.written_incremental) return false;  // the full reader resolves, says G90
  plain_motion words;
  std::size_t i = 0;
  for (;;) {
    i = lexing::skip_blanks(line, i);
    if (i == line.size()) break;
    const char letter = line[i++];
    const parsed_number n = read_number(line.substr(i));
    if (n.error != number_error::none) return false;
    const std::string_view text = line.substr(i, n.length);
    i += n.length;
    if (i < line.size() && !is_space(line[i])) return false;
    if (!words.take(letter, n.value, text)) return false;
  }
  if (is_arc(words.motion ? words.motion : state.motion) && words.axes.has_linear()) return false;  // needs its centre
  if (state.inverse_time) return false;  // the full reader carries the F of inverse time (`inverse_time_feed`)
  b.number = words.number;
  b.motion = words.motion;
  b.axes = words.axes;
  b.feed = words.feed;
  if (words.motion) state.motion = words.motion;
  state.move(b);
  state.reach(b, words.decimals);
  if (b.moves()) state.startup_pending = false;
  return true;
}

/// Reads the lines of one program: the header, the one-scan path for plain motion lines, and the
/// word-by-word path (lexer, then `word_reader` and `finish`) for every other line.
class line_reader {
 public:
  line_reader(const std::string& file_path, interp::parameter_store& store) : file_(file_path), parameters_(store) {}

  /// Reads `line` into a block for `on_block` (nothing for an empty line, nor for a label alone,
  /// `MARK:` or `N40 MARK:`: it only marks the line, for the jumps and repeats that name it).
  void read(const text_line& line, read_result& diagnostics, const block_sink& on_block) {
    if (line.text.empty()) return;
    if (const auto label = line_label(line.text); label && lexing::skip_blanks(line.text, label->end) == line.text.size())
      return;
    block b;
    const std::size_t first = lexing::skip_blanks(line.text, 0);
    b.where = {file_, line.number, (first < line.text.size() ? first : 0) + 1};
    b.call_chain = diagnostics.reading_call;
    b.text = std::string(line.text);
    if (first == line.text.size()) {  // blanks only
      b.passthrough = true;
    } else if (auto name = program_header(line.text)) {
      b.program_begin = *name;
      state_ = modal_state{};
      state_.program_name = *name;
    } else if (!read_plain_motion(line.text, b, state_)) {
      b = read_words(line, std::move(b), diagnostics);
      b.framing = path_line(line.text);
    }
    on_block(std::move(b));
  }

  /// Reads `line` word by word into `b` (whose `where` and `text` are set), without the
  /// one-scan path: the reader `read_plain_motion` is held equal to.
  block read_words(const text_line& line, block b, read_result& diagnostics) {
    line_parse p;
    p.b = std::move(b);
    std::string_view text = line.text;
    if (const auto label = line_label(text)) {
      unlabelled_.assign(text);  // `MARK: G1 X10`, `MARK: ;…`: the words after the label (statements.hpp took it)
      unlabelled_.replace(label->begin, label->end - label->begin, label->end - label->begin, ' ');
      text = unlabelled_;
    }
    lexer_.run(text, words_);
    parameters_.read(line.number, text, words_, p);
    word_reader(line.number, file_, p).read(words_);
    finish(p, state_, diagnostics);
    return std::move(p.b);
  }

  modal_state& state() { return state_; }

  /// The file the lines read next are in (a subprogram's file a call runs, or the main text's).
  void in_file(const file_name& file) { file_ = file; }

 private:
  file_name file_;  // one string for every location in the file
  modal_state state_;
  line_lexer lexer_;
  std::vector<word> words_;  // reused from line to line
  std::string unlabelled_;   // a labelled line with its label blanked
  variables parameters_;
};

}  // namespace kin5::program::siemens::detail

namespace kin5::program::siemens {

/// Reads a Siemens 840D program block by block, as the control runs it: `on_block` receives
/// each block executed, in the order executed (a loop's lines once per run; statements.hpp lists
/// the control statements, which give no block); errors and warnings go to `diagnostics` (its
/// `parsed` is not touched). An error in a control statement, or past `limits.max_executed_lines`,
/// stops the run there. The lines after the program's end (M30, M2, M17) never run: they are read
/// in file order as written, up to the first label or control statement, and the rest (sections
/// only a REPEAT runs) kept as text. Memory grows with the labels and the open loops, not with
/// the program's length.
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& diagnostics,
                        const block_sink& on_block, const read_limits& limits) {
  read_transmitted(text, file_path, diagnostics, on_block, [&](std::string_view body, const block_sink& sink) {
    interp::executor run{body, parameter_rules(), {limits.max_executed_lines}};
    run.record_calls_in(diagnostics.calls, file_path);
    run.open_files_with([&](const std::string&, const std::vector<std::string>& names) -> std::optional<interp::called_file> {
      // The calling program's directory first, then the include directories (the control
      // searches the caller's directory, then its subprogram directories).
      const beside_caller_result found =
          find_beside_caller(run.file().empty() ? file_path : run.file(), names, limits.include_dirs);
      if (found.path) return load_called_file(*found.path, limits);
      return interp::called_file{names.front() + " or " + names.back(), {},
                                 found.not_found + " (a name alone in a block calls a subprogram; --include-dir DIR "
                                                   "names the directory that holds it)"};
    });
    const file_name main_file(file_path);
    detail::line_reader reader(file_path, run.parameters());
    statements syntax;
    const text_line* last = nullptr;
    text_line end_line;
    // A subprogram's file: its header (`%_N_SUB_SPF`, `PROC SUB`) and `;$PATH=` lines make no
    // block, nor does its end (M17); M2 and M30 are refused there.
    bool in_called_file = false;  // the reader's file is a called one: set back before a line of this file
    const auto read_called = [&](const std::string& path, const text_line& line) {
      reader.in_file(file_name(path));
      in_called_file = true;
      const std::size_t first = lexing::skip_blanks(line.text, 0);
      if (detail::program_header(line.text) || detail::path_line(line.text)) return;
      if (const auto proc = detail::procedure_line(line.text)) {
        if (!proc->empty())
          diagnostics.add_error({{file_name(path), line.number, first + 1}, *proc});
        return;
      }
      reader.read(line, diagnostics, [&](block b) {
        if (b.program_end)
          diagnostics.add_error({b.where, "the end of the program (M2, M30) in a subprogram's file: end it with M17 or "
                                          "RET, which return to the caller"});
        const auto m17 = std::find(b.m_codes.begin(), b.m_codes.end(), 17);
        if (m17 != b.m_codes.end()) {
          b.m_codes.erase(m17);  // the return: the executor has taken it
          if (b.m_codes.empty() && !b.moves() && !b.motion && !b.feed && !b.tool && !b.spindle_rpm &&
              b.kept_words.empty() && !b.comment)
            return;
        }
        sink(std::move(b));
      });
    };
    const bool ended = run.execute(
        syntax,
        [&](const text_line& line, const interp::statement& s) {
          diagnostics.reading_call = run.call_chain();
          if (!run.file().empty()) return read_called(run.file(), line);
          if (in_called_file) reader.in_file(main_file), in_called_file = false;
          reader.read(line, diagnostics, sink);
          if (s.ends_program) end_line = line, last = &end_line;
        },
        [&](const interp::flow_error& e) {
          diagnostics.reading_call = run.call_chain();
          diagnostics.add_error({{e.file.empty() ? main_file : file_name(e.file), e.line, e.column}, e.message});
        });
    diagnostics.reading_call = 0;
    reader.in_file(main_file);
    if (!ended || !last) return;
    // After the end: the lines never run (see above).
    const std::size_t from = static_cast<std::size_t>(last->text.data() - body.data()) + last->text.size();
    std::size_t next = from;
    if (next < body.size() && body[next] == '\r') ++next;
    if (next < body.size() && body[next] == '\n') ++next;
    bool section = false;
    for_each_line(body.substr(next), [&](text_line line) {
      line.number += last->number;
      if (!section) {
        const interp::statement s = syntax.statement_of(line);
        section = s.kind != interp::statement_kind::ordinary || s.error || detail::line_label(line.text).has_value();
      }
      if (!section) return reader.read(line, diagnostics, sink);
      if (line.text.empty()) return;
      block b;
      const std::size_t first = lexing::skip_blanks(line.text, 0);
      b.where = {file_name(file_path), line.number, (first < line.text.size() ? first : 0) + 1};
      b.text = std::string(line.text);
      b.passthrough = true;
      sink(std::move(b));
    });
  });
}

/// The same, with the limits of the reading under way (`current_read_limits`), as the other
/// dialects' readers take them.
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& diagnostics,
                        const block_sink& on_block) {
  read_blocks(text, file_path, diagnostics, on_block, current_read_limits());
}

}  // namespace kin5::program::siemens
