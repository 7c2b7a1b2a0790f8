// Generated Siemens programs for the dialect laws (laws.cpp). Each generated line is
// drawn together with the block it must read as (the independent expectation): words in random
// case, with or without blanks, `X=` assignments, `+` signs, trailing and leading dots,
// comments of either kind, and LF / CRLF / CR line endings.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/siemens/dialect.hpp>

#include "../text_gen.hpp"
#include "contract.hpp"


namespace {

using namespace kin5::program;
using kin5::vec3;

/// A number with `decimals` decimals, exactly as the reader gets it from its shortest spelling.
double draw_decimal(std::int64_t lo, std::int64_t hi, int decimals) {
  double scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10;
  return static_cast<double>(*rc::gen::inRange<std::int64_t>(lo, hi + 1)) / scale;
}

bool coin() { return *rc::gen::inRange(0, 2) == 1; }

std::string draw_case(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (is_letter(c) && coin()) c = static_cast<char>(c ^ 0x20);
  return out;
}

std::string draw_blanks(int max) { return std::string(static_cast<std::size_t>(*rc::gen::inRange(0, max + 1)), ' '); }

/// `v` spelled with an optional `+`, a trailing dot on whole numbers, no leading zero below 1.
std::string spell_value(double v, int decimals) {
  std::string s = format_number(v, decimals);
  if (s.find('.') == std::string::npos) {
    if (coin()) s += '.';
  } else if (s.rfind("0.", 0) == 0 && coin()) {
    s.erase(0, 1);
  } else if (s.rfind("-0.", 0) == 0 && coin()) {
    s.erase(1, 1);
  }
  if (s.front() != '-' && coin()) s.insert(0, "+");
  return s;
}

/// An address word with a value: `X10`, `x 10.`, `X = +.5`.
std::string spell_address(std::string_view address, double v, int decimals) {
  const std::string value = spell_value(v, decimals);
  if (coin()) return draw_case(address) + draw_blanks(1) + "=" + draw_blanks(1) + value;
  return draw_case(address) + draw_blanks(1) + value;
}

/// A code word: `G1`, `g01`, `M 3`.
std::string spell_code(char letter, long long n, bool leading_zero_ok = true) {
  std::string digits = std::to_string(n);
  if (leading_zero_ok && coin()) digits.insert(0, "0");
  return draw_case(std::string(1, letter)) + draw_blanks(1) + digits;
}

/// What the reader remembers between blocks, mirrored by the generator.
struct state {
  std::optional<motion_kind> motion;
  arc_plane plane = arc_plane::xy;
  std::array<std::optional<double>, 3> position;
  std::optional<std::string> name;
  bool inverse_time = false;  // G93: every feed move is drawn with its F (the reader carries one into a move without)
  bool tool_loaded = false;    // an M6 drawn
};

struct line {
  block expected;
  std::vector<std::string> words;
  std::optional<std::string> verbatim;  ///< a passthrough line, written as is
};

const std::vector<std::string> kept_pool = {"G17", "G18", "G19", "G40", "G54", "G57", "G64", "G642", "G90", "G500", "G505", "G601",
                                            "SOFT", "BRISK", "FFWON", "FNORM", "CUT2DF", "ORIWKS", "ORIAXES", "D1", "H2"};

const std::vector<std::string> passthrough_pool = {
    // Only lines that change nothing pass through (vocabulary.hpp `changes_nothing`); cycles,
    // jumps and calls are refused.
    "R1=5", "MSG(\"roughing done\")", "DEF REAL DEPTH", "END:", "STOPRE", "%", "N5 R2=-3.5", "_Z_HOME=610.",
    "WORKPIECE(,\"\",,\"BOX\",0,0,-50,-80,0,0,100,100)"};

void add_kept(line& l, state& s, const std::string& word) {
  if (const auto w = parse_work_offset(word)) {  // G54 … G57, G500, G505 …: a work offset, one per block
    if (l.expected.state.work_offset) return;
    l.expected.state.work_offset = w;
    l.words.push_back(spell_code('G', std::stoll(word.substr(1))));
    return;
  }
  const bool numbered = word[0] == 'G' || word[0] == 'D' || word[0] == 'H';
  l.words.push_back(numbered ? spell_code(word[0], std::stoll(word.substr(1))) : draw_case(word));
  state_words& st = l.expected.state;  // G17 … G19, G40, G90 are read into the block's state
  if (word == "G17" || word == "G18" || word == "G19") {
    s.plane = word == "G17" ? arc_plane::xy : word == "G18" ? arc_plane::zx : arc_plane::yz;
    st.working_plane = s.plane;
  } else if (word == "G40") {
    st.radius_compensation = cutter_side::off;
  } else if (word == "G90") {
    st.distance = distance_mode::absolute;
  } else {
    l.expected.kept_words.push_back(word);
  }
}

void maybe_number(line& l) {
  if (*rc::gen::inRange(0, 3) == 0) return;
  const long long n = *rc::gen::inRange<long long>(0, 100000);
  l.expected.number = n;
  l.words.push_back(spell_code('N', n));
}

void move_block(line& l, state& s) {
  block& b = l.expected;
  maybe_number(l);
  if (coin()) {
    const int k = *rc::gen::inRange(0, 3);
    for (int i = 0; i < k; ++i) add_kept(l, s, *rc::gen::elementOf(kept_pool));
  }
  if (!s.motion || coin()) {
    const int g = *rc::gen::inRange(0, 4);
    b.motion = static_cast<motion_kind>(g);
    s.motion = b.motion;
    l.words.push_back(spell_code('G', g));
  }
  const bool arc = s.motion == motion_kind::arc_cw || s.motion == motion_kind::arc_ccw;
  const std::array<const char*, 3> linear = {"X", "Y", "Z"};
  std::array<std::optional<double>, 3> xyz;
  for (std::size_t i = 0; i < 3; ++i)
    if (coin()) xyz[i] = draw_decimal(-2'000'000, 2'000'000, 3), l.words.push_back(spell_address(linear[i], *xyz[i], 3));
  b.axes.x_mm = xyz[0], b.axes.y_mm = xyz[1], b.axes.z_mm = xyz[2];
  switch (*rc::gen::inRange(0, 3)) {
    case 0: {
      const std::array<const char*, 3> rotary = {"A", "B", "C"};
      std::array<std::optional<double>, 3> abc;
      for (std::size_t i = 0; i < 3; ++i)
        if (coin()) abc[i] = draw_decimal(-360'000, 360'000, 3), l.words.push_back(spell_address(rotary[i], *abc[i], 3));
      b.axes.a_deg = abc[0], b.axes.b_deg = abc[1], b.axes.c_deg = abc[2];
      break;
    }
    case 1: {
      const auto [i, j, k] = kin5::test::draw_direction();
      b.axes.tool_axis = vec3{i, j, k};
      for (auto [name, v] : {std::pair{"A3", i}, std::pair{"B3", j}, std::pair{"C3", k}})
        l.words.push_back(draw_case(name) + draw_blanks(1) + "=" + draw_blanks(1) + spell_value(v, 7));
      break;
    }
    default: break;
  }
  const auto start = s.position;
  const bool start_known = start[0] && start[1] && start[2];
  if (arc && (b.axes.has_linear() || coin())) {
    if (start_known && coin()) {
      std::array<double, 3> offset{};
      const std::array<bool, 3> in_plane = {s.plane != arc_plane::yz, s.plane != arc_plane::zx, s.plane != arc_plane::xy};
      const std::array<const char*, 3> names = {"I", "J", "K"};
      for (std::size_t i = 0; i < 3; ++i) {
        if (!in_plane[i] && coin()) continue;
        offset[i] = draw_decimal(-500'000, 500'000, 3);
        l.words.push_back(spell_address(names[i], offset[i], 3));
      }
      b.arc = arc_words{s.plane, vec3{*start[0] + offset[0], *start[1] + offset[1], *start[2] + offset[2]}, std::nullopt};
    } else {
      double r = draw_decimal(-500'000, 500'000, 3);
      if (r == 0) r = 1;
      b.arc = arc_words{s.plane, std::nullopt, r};
      l.words.push_back(draw_case("CR") + draw_blanks(1) + "=" + draw_blanks(1) + spell_value(r, 3));
    }
  }
  const bool needs_feed = s.inverse_time && s.motion != motion_kind::rapid && b.moves();
  if (coin() || needs_feed) b.feed = draw_decimal(0, 200'000, 1), l.words.push_back(spell_address("F", *b.feed, 1));
  if (*rc::gen::inRange(0, 4) == 0) b.spindle_rpm = draw_decimal(0, 240'000, 1), l.words.push_back(spell_address("S", *b.spindle_rpm, 1));
  if (*rc::gen::inRange(0, 6) == 0) {
    const int m = *rc::gen::element(3, 4, 5, 8, 9);
    b.m_codes.push_back(m);
    l.words.push_back(spell_code('M', m));
  }
  if (b.moves() && *rc::gen::inRange(0, 6) == 0) {
    b.kept_words.push_back("MSG(\"at work\")");
    l.words.push_back(draw_case("MSG") + "(\"at work\")");
  }
  for (std::size_t i = 0; i < 3; ++i)
    if (xyz[i]) s.position[i] = xyz[i];
}

line draw_line(state& s) {
  line l;
  block& b = l.expected;
  switch (*rc::gen::inRange(0, 15)) {
    case 0:
    case 1:
    case 2:
    case 3:
    case 4:
    case 5: move_block(l, s); break;
    case 6: {  // tool-tip tracking
      maybe_number(l);
      const int k = *rc::gen::inRange(0, 3);
      b.tcp = k != 2;
      l.words.push_back(draw_case(k == 0 ? "TRAORI" : k == 1 ? "TRAORI(1)" : "TRAFOOF"));
      break;
    }
    case 7: {  // settings
      maybe_number(l);
      if (coin()) b.metric = true, l.words.push_back(draw_case(*rc::gen::element<std::string>("G71", "G710")));
      if (coin()) {
        const bool inverse = coin();
        b.feed_mode = inverse ? feed_unit::inverse_time : feed_unit::per_minute;
        s.inverse_time = inverse;
        l.words.push_back(spell_code('G', inverse ? 93 : 94));
      }
      if (coin()) add_kept(l, s, *rc::gen::elementOf(kept_pool));
      if (coin()) b.tool = *rc::gen::inRange(0, 1000), l.words.push_back(spell_address("T", static_cast<double>(*b.tool), 0));
      else if (coin()) b.tool_name = "Mill 10", l.words.push_back(draw_case("T") + "=\"Mill 10\"");
      if (coin()) b.spindle_rpm = draw_decimal(0, 240'000, 1), l.words.push_back(spell_address("S", *b.spindle_rpm, 1));
      if (coin()) b.m_codes.push_back(6), l.words.push_back(spell_code('M', 6));
      if (l.words.empty()) b.m_codes.push_back(5), l.words.push_back(spell_code('M', 5));
      break;
    }
    case 8: {  // machine coordinates
      maybe_number(l);
      l.words.push_back(draw_case(*rc::gen::element<std::string>("SUPA", "G153", "G53")));
      b.machine_coordinates = true;
      b.motion = motion_kind::rapid;
      s.motion = b.motion;
      l.words.push_back(spell_code('G', 0));
      const double z = draw_decimal(-1'000'000, 0, 3);
      b.axes.z_mm = z;
      l.words.push_back(spell_address("Z", z, 3));
      s.position[2].reset();
      break;
    }
    case 9: {  // end of program
      maybe_number(l);
      const int m = coin() ? 30 : 2;
      b.program_end = m == 2 ? std::string("M2") : s.name.value_or("");
      l.words.push_back(spell_code('M', m));
      break;
    }
    case 10: {  // header: a new program
      const std::string name = *rc::gen::element<std::string>("PART1", "SAJO_TABLE1", "x5", "A_B_C");
      b.program_begin = name;
      l.verbatim = *rc::gen::element<std::string>("%_N_", "%_n_") + name + *rc::gen::element<std::string>("_MPF", "_mpf");
      s = state{};
      s.name = name;
      return l;
    }
    case 11: {  // passthrough
      const std::string text = *rc::gen::elementOf(passthrough_pool);
      b.passthrough = true;
      b.text = draw_blanks(2) + text;
      if (text.rfind("N5 ", 0) == 0) b.number = 5;
      l.verbatim = b.text;
      return l;
    }
    case 12: {  // an alarm stop: a cycle alarm number, and a text or none
      maybe_number(l);
      const long long n = *rc::gen::inRange<long long>(60000, 70000);
      std::string call = draw_case("SETAL") + "(" + std::to_string(n);
      std::string text;
      if (coin()) {
        const int k = *rc::gen::inRange(0, 10);
        for (int i = 0; i < k; ++i) text += *rc::gen::element<char>('A', 'b', ' ', '1', '.', '-');
        call += "," + draw_blanks(1) + "\"" + text + "\"";
      }
      b.alarm = alarm_stop{text, n};
      l.words.push_back(call + ")");
      break;
    }
    default: break;  // a comment line
  }
  const bool bare = l.words.empty();
  const bool semicolon = coin();
  const bool paren = bare ? (!semicolon || coin()) : *rc::gen::inRange(0, 4) == 0;
  const auto draw_comment = [] {
    std::string c;
    const int n = *rc::gen::inRange(0, 12);
    for (int i = 0; i < n; ++i) c += *rc::gen::element<char>('A', 'b', ' ', '1', ';', '(', '%', '=', '\xe9', '\xff', '\x01', '.');
    return c;
  };
  std::string paren_text, semicolon_text;
  if (paren) {
    paren_text = draw_comment();
    l.words.insert(l.words.begin() + *rc::gen::inRange<long>(0, static_cast<long>(l.words.size()) + 1), "(" + paren_text + ")");
  }
  if (semicolon) semicolon_text = draw_comment();
  if (paren || semicolon) {
    const auto trim = [](std::string t) {
      while (!t.empty() && t.front() == ' ') t.erase(0, 1);
      while (!t.empty() && t.back() == ' ') t.pop_back();
      return t;
    };
    std::string c = trim(paren_text);
    const std::string second = trim(semicolon_text);
    if (!c.empty() && !second.empty()) c += ' ';
    c += second;
    b.comment = c;
  }
  if (semicolon) l.words.push_back(";" + semicolon_text);
  return l;
}

/// A line's words joined by blanks, or by nothing where the next word starts a new address.
std::string join(const std::vector<std::string>& words) {
  std::string s = draw_blanks(2);
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i) {
      const char last = s.back(), next = words[i].front();
      const bool may_touch = (is_digit(last) || last == '.') && is_letter(next);
      s += may_touch && coin() ? "" : *rc::gen::element<std::string>(" ", "  ", "\t");
    }
    s += words[i];
  }
  return s;
}

struct drawn_program {
  program expected;
  std::string text;
};

drawn_program draw_program() {
  drawn_program d;
  d.expected.language = id_of<siemens::dialect>();
  d.expected.file = "gen.mpf";
  state s;
  const int n = *rc::gen::inRange(1, 30);
  std::size_t line_number = 0;
  std::string ending;
  for (int i = 0; i < n; ++i) {
    line l = draw_line(s);
    // D n is edge n's length switched on once a tool is loaded (an M6 here or before); D0 none.
    if (changes_tool(l.expected)) s.tool_loaded = true;
    for (const std::string& w : l.expected.kept_words)
      if (w.size() > 1 && w[0] == 'D' && w.find_first_not_of("0123456789", 1) == std::string::npos &&
          (w == "D0" || s.tool_loaded)) l.expected.state.length_compensation = w != "D0";
    // D and H are read after the other kept words (the order the writer uses).
    auto& kept = l.expected.kept_words;
    std::stable_partition(kept.begin(), kept.end(), [](const std::string& w) { return !(w[0] == 'D' || w[0] == 'H'); });
    const std::string text = l.verbatim ? *l.verbatim : join(l.words);
    if (ending != "\r" && *rc::gen::inRange(0, 8) == 0) d.text += "\n", ++line_number;  // an empty line, skipped
    ++line_number;
    std::size_t first = 0;
    while (first < text.size() && is_space(text[first])) ++first;
    l.expected.where = {"gen.mpf", line_number, first + 1};
    l.expected.text = text;
    d.text += text;
    ending = i + 1 < n || coin() ? *rc::gen::element<std::string>("\n", "\r\n", "\r") : "";
    d.text += ending;
    d.expected.blocks.push_back(std::move(l.expected));
  }
  return d;
}

}  // namespace

/// Text drawn with the block each line must read as (see the top of this file).
kin5::test::drawn_program kin5::test::contract<kin5::program::siemens::dialect>::draw_program() {
  auto d = ::draw_program();
  return {std::move(d.text), std::move(d.expected)};
}
