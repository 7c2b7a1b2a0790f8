/// @file program/apt.hpp
/// APT cutter-location data (CL data): reader and writer. One block per statement
/// (`MAJOR/args`, with `$` at a line end continuing it on the next line).
///
/// Read: `GOTO/x,y,z[,i,j,k]` (tool tip in mm, tool-axis vector), `RAPID` (the next GOTO is
/// rapid), `FEDRAT/[MMPM,|INVERS,]f`, `SPINDL/[RPM,]n[,CLW|CCLW]`, `SPINDL/ON|OFF|CLW|CCLW`,
/// `LOADTL/n`, `COOLNT/ON|FLOOD|MIST|OFF`, `STOP`, `OPSTOP`, `UNITS/MM`, `PARTNO name`, `FINI`,
/// `PPRINT/text` and `$$ text` comments. `MULTAX`, `INSERT` and unknown statements are
/// passthrough. Rejected: `UNITS/INCHES`, inch and per-revolution feeds, `CIRCLE`, GOTO with
/// other than 3 or 6 values. Numbers are plain decimals (`program/number.hpp`).
///
/// ```cpp
/// auto r = kin5::program::apt::read("GOTO/10,0,5,0,0,1\n", "part.cls");
/// std::string text = kin5::program::apt::write(r.parsed);   // "GOTO/10,0,5,0,0,1\n"
/// ```
/// Written: one statement per line, no continuations. Axis-word rotary angles, arcs and inch
/// programs cannot be written (std::invalid_argument naming the block); anything else without
/// an APT form becomes a `$$` comment carrying the block's text.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "block.hpp"
#include "number.hpp"
#include "text.hpp"

namespace kin5::program::apt {

/// Decimals written for each kind of number.
struct write_options {
  int linear_decimals = 3;   ///< GOTO x, y, z (mm)
  int angle_decimals = 3;    ///< unused: APT has no angle words
  int feed_decimals = 1;     ///< FEDRAT and SPINDL values
  int vector_decimals = 7;   ///< GOTO i, j, k
};

namespace detail {

/// One statement: its physical lines joined by '\n', with a map from offsets to locations.
struct statement {
  std::string text;      ///< source text, lines joined by '\n', outer blanks trimmed
  std::string content;   ///< `text` with comments, continuation `$` and line ends blanked
  std::string comment;   ///< `$$` comment text of all its lines, trimmed, joined by ' '
  bool has_comment = false;
  struct segment { std::size_t offset, line, column; };
  std::vector<segment> segments;  ///< where each physical line starts in `text`

  source_location at(const file_name& file, std::size_t offset) const {
    std::size_t k = 0;
    while (k + 1 < segments.size() && segments[k + 1].offset <= offset) ++k;
    return {file, segments[k].line, segments[k].column + (offset - segments[k].offset)};
  }
};

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

inline std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = to_upper(c);
  return u;
}

/// Groups physical lines into statements and calls `f(statement&&)` for each, in order; blank
/// lines are skipped.
template <class F>
void for_each_statement(std::string_view text, F&& f) {
  const auto lines = split_lines(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string_view first = lines[i].text;
    std::size_t lead = 0;
    while (lead < first.size() && is_space(first[lead])) ++lead;
    if (lead == first.size()) continue;
    statement st;
    for (;;) {
      std::string_view raw = lines[i].text;
      std::size_t skip = st.segments.empty() ? lead : 0;
      raw.remove_prefix(skip);
      if (!st.text.empty()) st.text += '\n', st.content += ' ';
      st.segments.push_back({st.text.size(), lines[i].number, skip + 1});
      const std::size_t base = st.text.size();
      st.text += raw;
      st.content += raw;
      const std::size_t dollars = raw.find("$$");
      std::string_view code = raw.substr(0, dollars);
      if (dollars != std::string_view::npos) {
        const std::string_view c = trim(raw.substr(dollars + 2));
        if (st.has_comment && !c.empty() && !st.comment.empty()) st.comment += ' ';
        st.comment += c;
        st.has_comment = true;
        for (std::size_t k = base + dollars; k < st.content.size(); ++k) st.content[k] = ' ';
      }
      code = trim(code);
      const bool continues = !code.empty() && code.back() == '$' && i + 1 < lines.size();
      if (!code.empty() && code.back() == '$') {
        const std::size_t pos = static_cast<std::size_t>(code.data() - raw.data()) + code.size() - 1;
        st.content[base + pos] = ' ';
      }
      if (!continues) break;
      ++i;
    }
    while (!st.text.empty() && is_space(st.text.back())) st.text.pop_back();
    st.content.resize(st.text.size());
    f(std::move(st));
  }
}

/// The statements of `text`, in order; blank lines are skipped.
inline std::vector<statement> statements(std::string_view text) {
  std::vector<statement> out;
  for_each_statement(text, [&](statement&& st) { out.push_back(std::move(st)); });
  return out;
}

/// One comma-separated argument of a statement: its text (trimmed) and offset in the statement.
struct argument {
  std::string_view text;
  std::size_t offset = 0;
};

inline std::vector<argument> arguments(std::string_view content, std::size_t offset) {
  std::vector<argument> args;
  std::size_t start = offset;
  for (std::size_t k = offset; k <= content.size(); ++k) {
    if (k == content.size() || content[k] == ',') {
      std::string_view piece = content.substr(start, k - start);
      std::size_t lead = 0;
      while (lead < piece.size() && is_space(piece[lead])) ++lead;
      args.push_back({trim(piece), start + lead});
      start = k + 1;
    }
  }
  return args;
}

class reader {
 public:
  reader(std::string file) : file_(std::move(file)) {}

  void run(std::string_view text, read_result& diagnostics, const block_sink& on_block) {
    for_each_statement(text, [&](statement&& st) { on_block(read_statement(st, diagnostics.errors)); });
  }

 private:
  file_name file_;  // one string for every location in the file
  bool rapid_pending_ = false;

  block read_statement(const statement& st, std::vector<diagnostic>& errors) {
    block b;
    b.where = st.at(file_, 0);
    b.text = st.text;
    if (st.has_comment) b.comment = st.comment;
    const std::string_view content = st.content;
    auto error = [&](std::size_t offset, std::string message) {
      errors.push_back({st.at(file_, offset), std::move(message)});
    };

    std::size_t k = 0;
    while (k < content.size() && is_space(content[k])) ++k;
    const std::size_t major_at = k;
    while (k < content.size() && (is_letter(content[k]) || is_digit(content[k]) || content[k] == '_')) ++k;
    const std::string major = upper(content.substr(major_at, k - major_at));
    std::size_t rest = k;
    while (rest < content.size() && is_space(content[rest])) ++rest;
    const bool slash = rest < content.size() && content[rest] == '/';
    if (slash) ++rest;

    // Free text after PARTNO / PPRINT / INSERT may hold any byte; elsewhere control bytes are errors.
    const bool free_text = major == "PARTNO" || major == "PPRINT" || major == "INSERT";
    for (std::size_t c = 0; c < (free_text ? major_at : content.size()); ++c) {
      const auto u = static_cast<unsigned char>(content[c]);
      if ((u < 0x20 && content[c] != '\t') || u == 0x7f) {
        static constexpr char hex[] = "0123456789ABCDEF";
        error(c, std::string("unexpected byte 0x") + hex[u >> 4] + hex[u & 15]);
        return b;
      }
    }
    if (major.empty()) {
      b.passthrough = !st.has_comment;  // a `$$` comment line, or something else kept as written
      return b;
    }

    const std::string_view tail = trim(content.substr(rest));
    // In APT a trailing '$' continues the statement and '$$' starts a comment, so a '$' kept in
    // free text could not be written back with the same meaning: reject it rather than guess.
    if (free_text) {
      const std::size_t dollar = content.find('$', rest);
      if (dollar != std::string::npos) {
        error(dollar, "'$' in " + major + " text is ambiguous (continuation or comment in APT)");
        return b;
      }
    }
    const auto args = arguments(content, rest);
    auto no_values = [&] {
      if (!tail.empty()) {
        error(rest, "unexpected '" + std::string(tail) + "' after " + major);
        return false;
      }
      return true;
    };
    auto number = [&](const argument& a, double& v) {
      const parsed_number n = read_number(a.text);
      if (n.error == number_error::too_large) {
        error(a.offset, "value out of range");
        return false;
      }
      if (n.error != number_error::none || n.length != a.text.size()) {
        const bool malformed = n.length > 0 && a.text.substr(n.length).find_first_not_of("0123456789.eE+-") == std::string_view::npos;
        if (a.text.empty()) error(a.offset, major + " value is missing");
        else if (malformed) error(a.offset, "malformed number '" + std::string(a.text) + "'");  // `1.2.3`, `1E5`
        else error(a.offset, "'" + std::string(a.text) + "' is not a number");
        return false;
      }
      v = n.value;
      return true;
    };

    if (major == "GOTO") {
      b.motion = rapid_pending_ ? motion_kind::rapid : motion_kind::linear;
      rapid_pending_ = false;
      if (!slash || (args.size() != 3 && args.size() != 6)) {
        error(major_at, "GOTO needs 3 or 6 values");
        return b;
      }
      double v[6] = {};
      bool good = true;
      for (std::size_t a = 0; a < args.size(); ++a) good = number(args[a], v[a]) && good;
      if (!good) return b;
      b.axes.x_mm = v[0], b.axes.y_mm = v[1], b.axes.z_mm = v[2];
      if (args.size() == 6) b.axes.tool_axis = vec3{v[3], v[4], v[5]};
    } else if (major == "RAPID") {
      if (!no_values()) return b;
      b.motion = motion_kind::rapid;
      b.feed_rapid = true;
      rapid_pending_ = true;
    } else if (major == "FEDRAT") {
      if (!slash || tail.empty()) return error(major_at, "FEDRAT needs a feed value"), b;
      std::optional<feed_unit> mode = feed_unit::per_minute;
      const argument* value = nullptr;
      for (const argument& a : args) {
        const std::string word = upper(a.text);
        if (word == "MMPM") mode = feed_unit::per_minute;
        else if (word == "INVERS") mode = feed_unit::inverse_time;
        else if (word == "IPM") return error(a.offset, "inch programs are not supported"), b;
        else if (word == "MMPR" || word == "IPR") return error(a.offset, "feed per revolution is not supported"), b;
        else if (!value) value = &a;
        else return error(a.offset, "unexpected '" + std::string(a.text) + "' after FEDRAT"), b;
      }
      double f = 0;
      if (!slash || !value) return error(major_at, "FEDRAT needs a feed value"), b;
      if (!number(*value, f)) return b;
      b.feed = f;
      b.feed_mode = mode;
    } else if (major == "SPINDL") {
      if (!slash || tail.empty()) return error(major_at, "SPINDL needs a speed, ON, OFF, CLW or CCLW"), b;
      const argument* value = nullptr;
      int direction = 0;
      for (const argument& a : args) {
        const std::string word = upper(a.text);
        if (word == "OFF" && args.size() == 1) b.m_codes.push_back(5);
        else if (word == "ON" || word == "CLW") direction = 3;
        else if (word == "CCLW") direction = 4;
        else if (word == "RPM") continue;
        else if (word == "SFM" || word == "SMM") return error(a.offset, "constant surface speed is not supported"), b;
        else if (!value && !a.text.empty() && !is_letter(a.text.front())) value = &a;
        else return error(a.offset, "unexpected '" + std::string(a.text) + "' after SPINDL"), b;
      }
      if (!slash || (!value && !direction && b.m_codes.empty()))
        return error(major_at, "SPINDL needs a speed, ON, OFF, CLW or CCLW"), b;
      if (value) {
        double s = 0;
        if (!number(*value, s)) return b;
        b.spindle_rpm = s;
      }
      if (direction) b.m_codes.push_back(direction);
    } else if (major == "LOADTL") {
      double t = 0;
      if (!slash || args.size() != 1) return error(major_at, "LOADTL needs one tool number"), b;
      if (!number(args[0], t)) return b;
      if (t < 0 || t != static_cast<double>(static_cast<long long>(t)))
        return error(args[0].offset, "tool number must be a whole number"), b;
      b.tool = static_cast<long long>(t);
    } else if (major == "COOLNT") {
      const std::string word = upper(tail);
      if (word == "ON" || word == "FLOOD") b.m_codes.push_back(8);
      else if (word == "MIST") b.m_codes.push_back(7);
      else if (word == "OFF") b.m_codes.push_back(9);
      else b.passthrough = true;
    } else if (major == "STOP" || major == "OPSTOP") {
      if (!no_values()) return b;
      b.m_codes.push_back(major == "STOP" ? 0 : 1);
    } else if (major == "UNITS") {
      const std::string word = upper(tail);
      if (word == "MM") b.metric = true;
      else if (word == "INCHES" || word == "INCH") error(rest, "inch programs are not supported");
      else b.passthrough = true;
    } else if (major == "PARTNO") {
      b.program_begin = std::string(tail);
    } else if (major == "FINI") {
      if (!no_values()) return b;
      b.program_end = std::string();
    } else if (major == "PPRINT") {
      std::string text(tail);
      if (b.comment) text += (text.empty() ? "$$ " : " $$ ") + *b.comment;
      b.comment = std::string(trim(text));
    } else if (major == "CIRCLE") {
      error(major_at, "circular CL data (CIRCLE) is not supported");
    } else {
      b.passthrough = true;  // MULTAX, INSERT, TLAXIS, unknown: kept as written
    }
    return b;
  }
};

}  // namespace detail

/// Reads APT CL data statement by statement: `on_block` receives each block in file order as soon
/// as it is read; errors go to `diagnostics` (its `parsed` is not touched).
inline void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                        const block_sink& on_block) {
  detail::reader(file_name).run(text, diagnostics, on_block);
}

/// Reads APT CL data. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(dialect::apt, text, std::move(file_name), &read_blocks);
}

/// Writes blocks as APT CL data one at a time, remembering whether a RAPID is pending, so a
/// program of any length is written in constant memory. `write(program)` below is this writer
/// applied to every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's blocks keep their text in `$$`
  /// comments).
  explicit writer(dialect source, const write_options& chosen = {})
      : same(source == dialect::apt), options(chosen) {}

  /// Appends the statements of block `b` to `out`. Throws `std::invalid_argument` naming the
  /// block's `file:line` when it cannot be written in APT.
  void write(std::string& out, const block& b) {
    auto fail = [&](const std::string& why) {
      throw std::invalid_argument(b.where.file + ":" + std::to_string(b.where.line) +
                                  ": block cannot be written in APT: " + why);
    };
    auto one_line = [&](const std::string& s) {
      if (s.find_first_of("\r\n") != std::string::npos) fail("line break in text");
      return s;
    };
    if (b.passthrough) {
      if (same) out += b.text + '\n';
      else out += "$$ " + one_line(b.text) + '\n';
      if (b.comment && !same) out += "$$ " + one_line(*b.comment) + '\n';
      return;
    }
    std::vector<std::string> lines;
    bool foreign_note = false;  // something without an APT form: carry the block's text
    if (b.program_begin) {
      const std::string& name = one_line(*b.program_begin);
      lines.push_back(name.empty() ? "PARTNO" : name.front() == '/' ? "PARTNO/" + name : "PARTNO " + name);
    }
    if (b.metric) {
      if (!*b.metric) fail("inch units");
      lines.push_back("UNITS/MM");
    }
    if (b.tool) lines.push_back("LOADTL/" + std::to_string(*b.tool));
    const std::string rpm = b.spindle_rpm ? format_number(*b.spindle_rpm, options.feed_decimals) : "";
    bool rpm_written = !b.spindle_rpm;
    for (int m : b.m_codes) {
      if (m == 3 || m == 4) {
        lines.push_back("SPINDL/" + (rpm_written ? "" : rpm + ",") + (m == 3 ? "CLW" : "CCLW"));
        rpm_written = true;
      } else if (m == 5) lines.push_back("SPINDL/OFF");
      else if (m == 8) lines.push_back("COOLNT/ON");
      else if (m == 7) lines.push_back("COOLNT/MIST");
      else if (m == 9) lines.push_back("COOLNT/OFF");
      else if (m == 0) lines.push_back("STOP");
      else if (m == 1) lines.push_back("OPSTOP");
      else if (m == 6 && b.tool) continue;  // LOADTL is the tool change: no M6 beside it
      else foreign_note = true;
    }
    if (!rpm_written) lines.push_back("SPINDL/" + rpm);
    if (b.feed) {
      const bool inverse = b.feed_mode == feed_unit::inverse_time;
      lines.push_back(std::string("FEDRAT/") + (inverse ? "INVERS," : "MMPM,") + format_number(*b.feed, options.feed_decimals));
    } else if (b.feed_mode) {
      foreign_note = true;
    }
    if (b.tcp || !b.kept_words.empty()) foreign_note = true;
    const bool rapid = b.motion == motion_kind::rapid || b.feed_rapid;
    if (b.machine_coordinates && b.moves()) {
      foreign_note = true;
    } else if (b.moves()) {
      if (b.axes.has_rotary()) fail("rotary axis words (A, B, C) have no APT form");
      if (b.arc || b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw) fail("arcs have no APT form");
      if (!b.axes.x_mm || !b.axes.y_mm || !b.axes.z_mm) fail("GOTO needs x, y and z");
      if (rapid && !rapid_pending) lines.push_back("RAPID");
      if (!rapid && rapid_pending) fail("a linear move cannot follow RAPID");
      std::string go = "GOTO/" + format_number(*b.axes.x_mm, options.linear_decimals) + "," +
                       format_number(*b.axes.y_mm, options.linear_decimals) + "," +
                       format_number(*b.axes.z_mm, options.linear_decimals);
      if (b.axes.tool_axis) {
        const vec3& v = *b.axes.tool_axis;
        go += "," + format_number(v.x, options.vector_decimals) + "," + format_number(v.y, options.vector_decimals) +
              "," + format_number(v.z, options.vector_decimals);
      }
      lines.push_back(std::move(go));
      rapid_pending = false;
    } else if (rapid) {
      lines.push_back("RAPID");
      rapid_pending = true;
    } else if (b.motion || b.arc) {
      foreign_note = true;
    }
    if (b.program_end) lines.push_back("FINI");
    if (foreign_note) lines.insert(lines.begin(), "$$ " + one_line(b.text));
    if (b.comment) {
      if (lines.empty() || (foreign_note && lines.size() == 1)) lines.push_back("$$ " + one_line(*b.comment));
      else lines.back() += " $$ " + one_line(*b.comment);
    }
    if (lines.empty() && !b.text.empty() && !same) lines.push_back("$$ " + one_line(b.text));
    for (const std::string& l : lines) out += l + '\n';
  }

 private:
  bool same;  // the blocks were read as APT
  write_options options;
  bool rapid_pending = false;
};

/// Writes `p` as APT CL data, one statement per line. Throws std::invalid_argument naming the
/// block's `file:line` when a block has rotary axis words, an arc, inch units, a move missing
/// one of x, y, z, a linear move right after a rapid-only block, or a line break in a text field.
inline std::string write(const program& p, const write_options& options = {}) {
  writer w(p.language, options);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  return out;
}

}  // namespace kin5::program::apt
