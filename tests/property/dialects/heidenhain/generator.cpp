// Generated Heidenhain programs for the dialect laws (laws.cpp). Each generated line is
// drawn together with the block it must read as (the independent expectation), then spelled with
// random case, blanks, signs, trailing and leading dots, block numbers (missing, repeated) and
// line endings.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/heidenhain/dialect.hpp>

#include "../text_gen.hpp"
#include "contract.hpp"


namespace {

using namespace kin5::program;
using kin5::vec3;

/// k / 10^decimals for k uniform in [lo·10^d, hi·10^d]: a value the writer reproduces exactly.
double draw_decimal(double lo, double hi, int decimals) {
  double scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10;
  const auto k = *rc::gen::inRange<std::int64_t>(static_cast<std::int64_t>(lo * scale),
                                                 static_cast<std::int64_t>(hi * scale) + 1);
  return static_cast<double>(k) / scale;
}

/// `value` as programs spell it: `+5`, `5`, `5.`, `+.5`, `-.5`, `5.500`.
std::string spell(double value, int decimals) {
  std::string s = format_number(value, decimals);
  const bool negative = s.front() == '-';
  std::string digits = negative ? s.substr(1) : s;
  if (digits.find('.') == std::string::npos && *rc::gen::arbitrary<bool>()) digits += '.';
  if (digits.rfind("0.", 0) == 0 && *rc::gen::arbitrary<bool>()) digits.erase(0, 1);
  if (digits.find('.') != std::string::npos && *rc::gen::arbitrary<bool>()) digits += "00";
  return (negative ? "-" : (*rc::gen::inRange(0, 4) != 0 ? "+" : "")) + digits;
}

/// An upper-case word in random letter case.
std::string draw_case(std::string word) {
  const int mode = *rc::gen::inRange(0, 3);
  for (char& c : word)
    if ((mode == 1 || (mode == 2 && *rc::gen::arbitrary<bool>())) && c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return word;
}

/// The blanks between two words: at least one.
std::string gap() { return *rc::gen::element<std::string>(" ", " ", "  ", "\t", " \t "); }

/// Comment text, possibly with bytes of another encoding and a second `;`.
std::string draw_comment() {
  std::string s = *rc::gen::element<std::string>("", " ", " OPERATION 1", "T1 - L0 R5", "\xC1\xA2\xCF\xB3", "a;b", "  == ");
  if (*rc::gen::arbitrary<bool>()) s += *rc::gen::element<std::string>("X+5", " done", "\xB5\xB6");
  return s;
}

struct modal {
  std::optional<double> last[3];
  std::optional<long long> position[3];  ///< X Y Z in thousandths, unknown after M91/M92: IX's base
  arc_plane plane = arc_plane::xy;
  std::optional<vec3> centre;
  long long number = 0;
};

struct item {
  block expected;
  std::string text;
};

/// A word with a value: letter(s) in random case, now and then a blank, then the spelled number.
std::string value_word(const std::string& key, double v, int decimals) {
  return draw_case(key) + (*rc::gen::inRange(0, 8) == 0 ? " " : "") + spell(v, decimals);
}

void add_m_codes(std::string& text, block& b) {
  const auto codes = *rc::gen::container<std::vector<int>>(
      *rc::gen::inRange<std::size_t>(0, 3), rc::gen::element(3, 5, 8, 9, 91, 92, 117, 126, 128, 129, 140));
  bool tcp_seen = false;
  for (int m : codes) {
    if (m == 128 || m == 129) {
      if (tcp_seen) continue;
      tcp_seen = true;
      b.tcp = m == 128;
    } else {
      read_machine_function(b, m, {.m7_mist = false, .m13_m14 = true});
      if (m == 91 || m == 92) b.machine_coordinates = true;
      if (m == 92) b.machine_reference = machine_position::builder_position;
    }
    text += gap() + draw_case("M") + std::to_string(m);
  }
}

void add_comment(std::string& text, block& b) {
  if (*rc::gen::inRange(0, 4) != 0) return;
  const std::string c = draw_comment();
  text += *rc::gen::element<std::string>("", " ", "  ") + ";" + c;
  b.comment = c;
}

/// The in-plane axes of `plane`, as indices into x, y, z.
std::pair<int, int> plane_axes(arc_plane p) {
  return p == arc_plane::xy ? std::pair{0, 1} : p == arc_plane::zx ? std::pair{0, 2} : std::pair{1, 2};
}

std::optional<double>& linear(block& b, int a) { return a == 0 ? b.axes.x_mm : a == 1 ? b.axes.y_mm : b.axes.z_mm; }

item draw_item(modal& m) {
  item it;
  block& b = it.expected;
  std::string& t = it.text;
  const std::string letters[6] = {"X", "Y", "Z", "A", "B", "C"};
  int kind = *rc::gen::inRange(0, 16);
  if (kind == 5 && !m.centre) kind = 0;
  switch (kind) {
    case 0:
    case 1:
    case 2:
    case 3: {  // L
      t = draw_case("L");
      std::string m_words;
      add_m_codes(m_words, b);  // first: an M91/M92 block takes no incremental words
      const int required = *rc::gen::inRange(0, 6);  // an L has an end point: one axis at least
      for (int a = 0; a < 6; ++a) {
        if (a != required && !*rc::gen::arbitrary<bool>()) continue;
        double v = a < 3 ? draw_decimal(-2000, 2000, 3) : draw_decimal(-360, 360, 3);
        if (a < 3 && m.position[a] && !b.machine_coordinates && *rc::gen::inRange(0, 3) == 0) {
          // IX: v on from the last position; the model holds the position reached
          t += gap() + value_word("I" + letters[a], v, 3);
          v = static_cast<double>(*m.position[a] + std::llround(v * 1000)) / 1000.0;
        } else {
          t += gap() + value_word(letters[a], v, 3);
        }
        if (a < 3) linear(b, a) = v;
        if (a == 3) b.axes.a_deg = v;
        if (a == 4) b.axes.b_deg = v;
        if (a == 5) b.axes.c_deg = v;
      }
      // R0 with compensation off is kept as written; RL/RR are read in cutter_compensation_laws.cpp.
      const std::string comp = *rc::gen::element<std::string>("", "", "R0");
      if (!comp.empty()) t += gap() + draw_case(comp), b.kept_words.push_back(comp);
      b.motion = motion_kind::linear;
      switch (*rc::gen::inRange(0, 3)) {
        case 0: break;
        case 1:
          t += gap() + draw_case("FMAX");
          b.feed_rapid = true;
          b.motion = motion_kind::rapid;
          break;
        default: {
          const double f = draw_decimal(0, 20000, 1);
          t += gap() + draw_case("F") + spell(f, 1);
          b.feed = f;
        }
      }
      t += m_words;
      break;
    }
    case 4: {  // LN with a tool-axis vector
      t = draw_case("LN");
      for (int a = 0; a < 3; ++a) {
        if (!*rc::gen::arbitrary<bool>()) continue;
        const double v = draw_decimal(-2000, 2000, 3);
        t += gap() + value_word(letters[a], v, 3);
        linear(b, a) = v;
      }
      if (*rc::gen::arbitrary<bool>()) {
        for (const char* n : {"NX", "NY", "NZ"}) {
          const std::string v = spell(draw_decimal(-1, 1, 7), 7);
          t += gap() + draw_case(n) + v;
          b.kept_words.push_back(n + v);
        }
      }
      const vec3 v = kin5::test::draw_direction();
      t += gap() + value_word("TX", v.x, 7) + gap() + value_word("TY", v.y, 7) + gap() + value_word("TZ", v.z, 7);
      b.axes.tool_axis = v;
      if (*rc::gen::arbitrary<bool>()) t += gap() + draw_case("R0"), b.kept_words.push_back("R0");
      b.motion = motion_kind::linear;
      if (*rc::gen::arbitrary<bool>()) {
        const double f = draw_decimal(0, 20000, 1);
        t += gap() + draw_case("F") + spell(f, 1);
        b.feed = f;
      }
      add_m_codes(t, b);
      break;
    }
    case 5:    // C around the last CC
    case 6: {  // CR
      const bool radius = kind == 6;
      t = draw_case(radius ? "CR" : "C");
      const auto [p, q] = plane_axes(m.plane);
      for (int a : {p, q}) {
        const double v = draw_decimal(-2000, 2000, 3);
        t += gap() + value_word(letters[a], v, 3);
        linear(b, a) = v;
      }
      b.arc = arc_words{m.plane, std::nullopt, std::nullopt};
      if (radius) {
        double r = draw_decimal(0.001, 500, 3);
        if (*rc::gen::arbitrary<bool>()) r = -r;
        t += gap() + draw_case("R") + (r > 0 ? "+" : "") + format_number(r, 3);
        b.arc->radius_mm = r;
      } else {
        b.arc->centre_mm = m.centre;
      }
      const bool cw = *rc::gen::arbitrary<bool>();
      t += gap() + draw_case("DR") + (cw ? "-" : "+");
      b.motion = cw ? motion_kind::arc_cw : motion_kind::arc_ccw;
      if (*rc::gen::arbitrary<bool>()) t += gap() + draw_case("R0"), b.kept_words.push_back("R0");
      if (*rc::gen::arbitrary<bool>()) {
        const double f = draw_decimal(0, 20000, 1);
        t += gap() + draw_case("F") + spell(f, 1);
        b.feed = f;
      }
      add_m_codes(t, b);
      break;
    }
    case 7: {  // CC: two coordinates give the plane; the third comes from the last position
      const arc_plane plane = *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz);
      const auto [p, q] = plane_axes(plane);
      double c[3] = {m.last[0].value_or(0), m.last[1].value_or(0), m.last[2].value_or(0)};
      t = draw_case("CC");
      for (int a : {p, q}) {
        c[a] = draw_decimal(-2000, 2000, 3);
        t += gap() + value_word(letters[a], c[a], 3);
      }
      b.arc = arc_words{plane, vec3{c[0], c[1], c[2]}, std::nullopt};
      m.plane = plane;
      m.centre = b.arc->centre_mm;
      break;
    }
    case 8: {  // TOOL CALL
      t = draw_case("TOOL") + gap() + draw_case("CALL");
      const int tool_kind = *rc::gen::inRange(0, 8);  // 0: no tool (S alone), 1: by name, else by number
      const bool tool = tool_kind != 0;
      if (tool_kind == 1) {  // a name of the characters a TNC takes (TNC 640 User's Manual §5.2)
        b.tool_name = *rc::gen::element<std::string>("MILL_D10", "BALL-R3.5", "T#1", "DRILL$6&,%");
        t += gap() + "\"" + *b.tool_name + "\"", b.state.tool_change = true;
      } else if (tool) {
        b.tool = *rc::gen::inRange(0, 1000), t += gap() + std::to_string(*b.tool), b.state.tool_change = true;
      }
      const std::string axis = *rc::gen::element<std::string>("", "X", "Y", "Z", "Z");
      if (!axis.empty()) {
        t += gap() + draw_case(axis);
        b.kept_words.push_back(axis);
        m.plane = axis == "Z" ? arc_plane::xy : axis == "Y" ? arc_plane::zx : arc_plane::yz;
      }
      if (*rc::gen::arbitrary<bool>()) {
        // An oversize other than 0 is refused (reader.hpp); `+.` is no number, so 0 is spelled out.
        const std::string dl = *rc::gen::element<std::string>("DL+0", "DL0", "DL-0.000", "DL+0.0");
        t += gap() + draw_case(dl);
        b.kept_words.push_back(dl);
      }
      if (!tool || *rc::gen::arbitrary<bool>()) {
        const double s = draw_decimal(0, 30000, 0);
        t += gap() + draw_case("S") + spell(s, 0);
        b.spindle_rpm = s;
      }
      if (*rc::gen::arbitrary<bool>()) {
        const double f = draw_decimal(0, 20000, 1);
        t += gap() + draw_case("F") + spell(f, 1);
        b.feed = f;
      }
      break;
    }
    case 9: {  // M functions alone; M140 MB MAX, the retract along the tool axis
      b.m_codes.clear();
      if (*rc::gen::inRange(0, 6) == 0) {
        t = draw_case("M") + "140" + gap() + draw_case("MB") + gap() + draw_case("MAX");
        b.machine_coordinates = true;
        b.machine_reference = machine_position::tool_axis_limit;
        // M functions beside it: state words (M5, M9, M13) and the machine maker's numbers alike;
        // no M91/M92 (another machine position) nor M128/M129 (no TCP switch in an M140 block).
        const auto codes = *rc::gen::container<std::vector<int>>(*rc::gen::inRange<std::size_t>(0, 3),
                                                                 rc::gen::element(0, 3, 5, 9, 13, 117));
        for (int code : codes) {
          t += gap() + draw_case("M") + std::to_string(code);
          read_machine_function(b, code, {.m7_mist = false, .m13_m14 = true});
        }
        break;
      }
      t = draw_case("M") + std::to_string(*rc::gen::element(3, 5, 9, 30, 91, 128, 129));
      const int first = std::stoi(t.substr(1));
      const auto take = [&b](int code) {
        read_machine_function(b, code, {.m7_mist = false, .m13_m14 = true});
      };
      if (first == 128 || first == 129) b.tcp = first == 128;
      else take(first), b.machine_coordinates = first == 91;
      if (*rc::gen::arbitrary<bool>()) t += gap() + draw_case("M") + "8", take(8);
      break;
    }
    case 10: {  // comment lines
      const std::string c = draw_comment();
      t = std::string(*rc::gen::arbitrary<bool>() ? ";" : "*") + c;
      b.comment = c;
      return it;
    }
    case 11:  // BEGIN / END PGM: only first and last (draw_frame)
    case 12: {  // FUNCTION TCPM
      if (*rc::gen::arbitrary<bool>()) {
        t = draw_case("FUNCTION") + gap() + draw_case("RESET") + gap() + draw_case("TCPM");
        b.tcp = false;
      } else {
        t = draw_case("FUNCTION") + gap() + draw_case("TCPM");
        b.tcp = true;
        for (const char* o : {"F TCP", "AXIS POS", "PATHCTRL AXIS"}) {
          if (!*rc::gen::arbitrary<bool>()) continue;
          const std::string s(o);
          const auto sp = s.find(' ');
          t += gap() + draw_case(s.substr(0, sp)) + gap() + draw_case(s.substr(sp + 1));
          b.kept_words.push_back(s);
        }
      }
      break;
    }
    case 13: {  // passed through unchanged
      // Only blocks that change nothing pass through; cycles, labels, calls are refused (reader.hpp).
      t = *rc::gen::element<std::string>("BLK FORM 0.1 Z X-32.746 Y-32.697 Z-74.399", "PLANE RESET STAY",
                                         "CYCL DEF 19.0 WORKING PLANE", "CYCL DEF 19.1 A+0 B+0 C+0",
                                         "CYCL DEF 7.0 DATUM SHIFT", "Q1 = 5 ; depth", "TOOL DEF 5");
      b.passthrough = true;
      break;
    }
    default: {  // a block number alone
      it.text = std::to_string(m.number++);
      b.number = m.number - 1;
      b.passthrough = false;
      b.text = it.text;
      return it;
    }
  }
  if (kind != 13 && kind != 10) add_comment(t, b);
  if (!b.passthrough)
    for (int a = 0; a < 3; ++a)
      if (const auto v = linear(b, a)) {
        m.last[a] = v;
        m.position[a] = b.machine_coordinates ? std::nullopt : std::optional<long long>(std::llround(*v * 1000));
      }
  return it;
}

/// A program's `BEGIN PGM name MM` (`begin`) or `END PGM name MM` line.
item draw_frame(bool begin, const std::string& name) {
  item it;
  block& b = it.expected;
  it.text = draw_case(begin ? "BEGIN" : "END") + gap() + draw_case("PGM") + gap() + name + gap() + draw_case("MM");
  (begin ? b.program_begin : b.program_end) = name;
  b.metric = true;
  add_comment(it.text, b);
  return it;
}

/// Generated text and the program it must read as.
struct generated {
  std::string text;
  program expected;
};

generated draw_program() {
  generated g;
  g.expected.language = id_of<heidenhain::dialect>();
  g.expected.file = "g.h";
  modal m;
  const std::string eol = *rc::gen::element<std::string>("\n", "\r\n", "\r");
  const auto n = *rc::gen::inRange(0, 30);
  // A program opens with BEGIN PGM and closes with END PGM of the same name, or lacks either.
  const std::string name = *rc::gen::element<std::string>("P1", "YL-05", "part_7", "Bracket");
  const bool begins = *rc::gen::arbitrary<bool>(), ends = *rc::gen::arbitrary<bool>();
  for (int k = begins ? -1 : 0; k < n + (ends ? 1 : 0); ++k) {
    if (*rc::gen::inRange(0, 8) == 0) g.text += *rc::gen::element<std::string>("", "  ", "\t") + eol;  // blank lines are skipped
    item it = k < 0 ? draw_frame(true, name) : k == n ? draw_frame(false, name) : draw_item(m);
    if (!it.expected.number) {
      switch (*rc::gen::inRange(0, 4)) {
        case 0: break;  // unnumbered, as NX writes its header
        case 1:         // repeated, as hand edits leave them
          if (m.number > 0) it.expected.number = m.number - 1;
          break;
        default: it.expected.number = m.number++;
      }
      if (it.expected.number) it.text = std::to_string(*it.expected.number) + gap() + it.text;
    }
    if (it.expected.passthrough) it.expected.text = it.text;
    g.text += it.text + eol;
    g.expected.blocks.push_back(std::move(it.expected));
  }
  if (*rc::gen::arbitrary<bool>() && !g.text.empty()) g.text.resize(g.text.size() - eol.size());  // no final line ending
  return g;
}

}  // namespace

/// Text drawn with the block each line must read as (see the top of this file).
kin5::test::drawn_program kin5::test::contract<kin5::program::heidenhain::dialect>::draw_program() {
  auto g = ::draw_program();
  return {std::move(g.text), std::move(g.expected)};
}
