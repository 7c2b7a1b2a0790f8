// Generated LinuxCNC programs for the dialect laws (laws.cpp). Each line is drawn together with
// the block it must read as (the independent expectation), then spelled with random case,
// blanks, signs, dots and line endings. Tracking (M428, G12.1 P1) is switched on only where G43
// holds the loaded tool's length, as the reader requires.
#include <optional>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/linuxcnc/dialect.hpp>

#include "../text_gen.hpp"
#include "contract.hpp"

namespace {

using namespace kin5::program;
using kin5::test::draw_blanks;
using kin5::test::draw_case;
using kin5::test::draw_decimal;
using kin5::test::draw_spelling;
using kin5::test::spell_word;
using kin5::test::draw_words;

struct item {
  block expected;
  std::vector<std::string> words;
};

/// What the generator knows of the program so far, drawn independently of the reader.
struct state {
  std::optional<motion_kind> motion;
  arc_plane plane = arc_plane::xy;
  std::optional<double> last[3];
  bool tracking = false, length = false;  // M428 on; G43 holds the loaded tool's length
  std::optional<long long> loaded;        // the tool of the last M6: G43 without H is its length
  bool inverse_time = false;              // G93: every feed move gives its F
};

std::string spell_code(char letter, int v) {
  return draw_case(std::string(1, letter)) + (v < 10 && *rc::gen::arbitrary<bool>() ? "0" : "") + std::to_string(v);
}

/// X Y Z (at least one when nothing else moves), A B C, each drawn on its own.
void draw_axes(item& it, state& st, bool arc) {
  block& b = it.expected;
  const char* names = "XYZ";
  for (int k = 0; k < 3; ++k)
    if (*rc::gen::inRange(0, 3) != 0 || (k == 0 && arc)) {
      const double v = draw_decimal(-1000, 1000, 3);
      (k == 0 ? b.axes.x_mm : k == 1 ? b.axes.y_mm : b.axes.z_mm) = v;
      it.words.push_back(spell_word(names[k], v, 3));
    }
  const char* rot = "ABC";
  for (int k = 0; k < 3; ++k)
    if (*rc::gen::inRange(0, 3) == 0 || (k == 2 && !b.moves())) {
      const double v = draw_decimal(-360, 360, 3);
      (k == 0 ? b.axes.a_deg : k == 1 ? b.axes.b_deg : b.axes.c_deg) = v;
      it.words.push_back(spell_word(rot[k], v, 3));
    }
  static_cast<void>(st);
}

/// The arc data of an arc block: R, or I J (K) as the offset of the centre from the last point.
void draw_arc(item& it, state& st) {
  arc_words a;
  a.plane = st.plane;
  const bool known = st.last[0] && st.last[1] && st.last[2];
  if (!known || *rc::gen::arbitrary<bool>()) {
    a.radius_mm = draw_decimal(-500, 500, 3);
    it.words.push_back(spell_word('R', *a.radius_mm, 3));
  } else {
    const int first = st.plane == arc_plane::yz ? 1 : 0;
    const int second = st.plane == arc_plane::xy ? 1 : 2;
    double c[3] = {*st.last[0], *st.last[1], *st.last[2]};
    for (int k : {first, second}) {
      const double off = draw_decimal(-300, 300, 3);
      c[k] += off;
      it.words.push_back(spell_word(static_cast<char>('I' + k), off, 3));
    }
    a.centre_mm = kin5::vec3{c[0], c[1], c[2]};
  }
  it.expected.arc = a;
}

void draw_motion(item& it, state& st) {
  block& b = it.expected;
  const int kind = *rc::gen::inRange(0, 4);
  const motion_kind m = kind == 0 ? motion_kind::rapid : kind == 1 ? motion_kind::linear
                      : kind == 2 ? motion_kind::arc_cw : motion_kind::arc_ccw;
  if (kind >= 2 || !st.motion || *rc::gen::arbitrary<bool>()) {
    b.motion = m;
    st.motion = m;
    it.words.push_back(spell_code('G', kind));
  }
  const bool arc = *st.motion == motion_kind::arc_cw || *st.motion == motion_kind::arc_ccw;
  draw_axes(it, st, arc);
  if (arc) draw_arc(it, st);
  const std::optional<double>* xyz[3] = {&b.axes.x_mm, &b.axes.y_mm, &b.axes.z_mm};
  for (int k = 0; k < 3; ++k)
    if (*xyz[k]) st.last[k] = **xyz[k];
  if (*rc::gen::inRange(0, 3) == 0 || (st.inverse_time && *st.motion != motion_kind::rapid)) {
    b.feed = draw_decimal(0.1, 20000, 1);
    it.words.push_back(spell_word('F', *b.feed, 1));
  }
}

/// Harmless modal words and work offsets G54 … G59.3.
void draw_modes(item& it, state& st) {
  block& b = it.expected;
  for (const char* g : {"G17", "G18", "G19", "G40", "G90", "G80", "G61", "G98"}) {
    if (*rc::gen::inRange(0, 4) != 0) continue;
    const std::string name = g;
    it.words.push_back(draw_case(g));
    if (name == "G17" || name == "G18" || name == "G19") {  // read into the block's state
      st.plane = name == "G17" ? arc_plane::xy : name == "G18" ? arc_plane::zx : arc_plane::yz;
      b.state.working_plane = st.plane;
    } else if (name == "G40") {
      b.state.radius_compensation = cutter_side::off;
    } else if (name == "G90") {
      b.state.distance = distance_mode::absolute;
    } else {
      b.kept_words.push_back(it.words.back());
    }
  }
  if (*rc::gen::arbitrary<bool>()) {
    const int n = *rc::gen::inRange(1, 10);
    b.state.work_offset = work_offset{work_offset_family::g54, n};
    it.words.push_back(draw_case(spelling(*b.state.work_offset)));
  }
  if (it.words.empty()) it.words.push_back("G90"), b.state.distance = distance_mode::absolute;
}

/// Tracking on (only with the loaded tool's length in effect: G43 in the line if need be) or off.
void draw_tracking(item& it, state& st) {
  block& b = it.expected;
  const bool on = *rc::gen::arbitrary<bool>();
  if (on && !st.length) {
    b.state.length_compensation = true;
    b.state.length_register = st.loaded;
    it.words.push_back(draw_case("G43"));
    st.length = true;
  }
  b.tcp = on;
  st.tracking = on;
  const bool g_form = *rc::gen::arbitrary<bool>();
  it.words.push_back(draw_case(on ? (g_form ? "G12.1" : "M428") : (g_form ? "G13.1" : "M429")));
  if (on && g_form) it.words.push_back(spell_code('P', 1));
}

/// Tools and length: T, M6, G43 [H], G49 (changes only while tracking is off).
void draw_tool(item& it, state& st) {
  block& b = it.expected;
  if (st.tracking) {
    b.state.length_compensation = true;
    b.state.length_register = st.loaded;
    it.words.push_back(draw_case("G43"));
    st.length = true;
    return;
  }
  const int t = *rc::gen::inRange(0, 100);
  b.tool = t;
  it.words.push_back(spell_code('T', t));
  if (*rc::gen::arbitrary<bool>()) {
    b.m_codes.push_back(6);
    it.words.push_back(spell_code('M', 6));
    st.length = false;
    st.loaded = t;
  }
  const int length = *rc::gen::inRange(0, 3);
  if (length == 0) return;
  b.state.length_compensation = length == 1;
  if (length == 1) b.state.length_register = st.loaded;  // G43 alone: the loaded tool's
  it.words.push_back(draw_case(length == 1 ? "G43" : "G49"));
  st.length = false;  // G43 H n may name another tool than the loaded one
  if (length == 1 && *rc::gen::arbitrary<bool>()) {
    b.state.length_register = *rc::gen::inRange(0, 100);
    it.words.push_back(spell_code('H', static_cast<int>(*b.state.length_register)));
  }
}

void draw_codes(item& it) {
  block& b = it.expected;
  if (*rc::gen::arbitrary<bool>()) {
    b.spindle_rpm = draw_decimal(1, 40000, 1);
    it.words.push_back(spell_word('S', *b.spindle_rpm, 1));
  }
  const int count = *rc::gen::inRange(b.spindle_rpm ? 0 : 1, 3);
  for (int k = 0; k < count; ++k) {
    const int m = *rc::gen::element(0, 1, 3, 4, 5, 7, 8, 9);
    b.m_codes.push_back(m);
    it.words.push_back(spell_code('M', m));
  }
}

item draw_item(state& st) {
  item it;
  block& b = it.expected;
  if (*rc::gen::inRange(0, 5) == 0) {
    b.number = *rc::gen::inRange<long long>(0, 100000);
    it.words.push_back(spell_code('N', static_cast<int>(*b.number)));
  }
  switch (*rc::gen::inRange(0, 15)) {
    case 0: case 1: case 2: case 3: case 4:
      draw_motion(it, st);
      break;
    case 5: draw_modes(it, st); break;
    case 6: draw_tracking(it, st); break;
    case 7: draw_tool(it, st); break;
    case 8:
      b.feed_mode = *rc::gen::arbitrary<bool>() ? feed_unit::inverse_time : feed_unit::per_minute;
      st.inverse_time = b.feed_mode == feed_unit::inverse_time;
      it.words.push_back(draw_case(b.feed_mode == feed_unit::inverse_time ? "G93" : "G94"));
      break;
    case 9:
      b.metric = true;
      it.words.push_back(spell_code('G', 21));
      break;
    case 10: draw_codes(it); break;
    case 11:
      b.program_end = *rc::gen::arbitrary<bool>() ? "M2" : "M30";
      it.words.push_back(draw_case(*b.program_end));
      break;
    case 12: {  // dwell, seconds, in a block of its own
      const double s = draw_decimal(0, 100, 2);
      b.state.dwell_s = s;  // the block holds only its number so far
      it.words.push_back(draw_case("G4"));
      it.words.push_back(spell_word('P', s, 2));
      break;
    }
    case 13: {  // an abort: the line's last comment, so no comment after it
      const std::string m = draw_words();
      b.alarm = alarm_stop{m, std::nullopt};
      it.words.push_back("(" + draw_blanks() + draw_case("ABORT") + draw_blanks() + "," + draw_blanks() + m +
                         draw_blanks() + ")");
      return it;
    }
    default:
      b = block{};
      b.passthrough = true;
      b.text = "%";
      it.words = {b.text};
      return it;
  }
  if (*rc::gen::inRange(0, 4) == 0) {
    const std::string c = draw_words();
    b.comment = c;
    it.words.push_back(*rc::gen::arbitrary<bool>() ? "(" + draw_blanks() + c + draw_blanks() + ")" : ";" + c);
  }
  return it;
}

std::string spell(const std::vector<item>& items) {
  const std::string eol = *rc::gen::element<std::string>("\n", "\r\n");
  std::string text;
  for (const item& it : items) {
    text += kin5::test::draw_line(it.words) + eol;
  }
  return text;
}

}  // namespace

/// Text drawn with the block each line must read as (see the top of this file).
kin5::test::drawn_program kin5::test::contract<kin5::program::linuxcnc::dialect>::draw_program() {
  const auto n = *rc::gen::inRange<std::size_t>(0, 40);
  std::vector<item> items;
  state st;
  for (std::size_t i = 0; i < n; ++i) items.push_back(draw_item(st));
  kin5::program::program p;
  p.language = kin5::program::id_of<kin5::program::linuxcnc::dialect>();
  p.file = "gen.ngc";
  for (const item& it : items) p.blocks.push_back(it.expected);
  return {spell(items), p};
}
