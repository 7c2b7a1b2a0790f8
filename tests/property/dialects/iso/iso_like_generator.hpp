/// @file iso/iso_like_generator.hpp
/// Generated programs of ISO / Fanuc G code and of the dialects that spell a few codes otherwise
/// (Haas: `G234`, `G154 P n`, `G4 P` seconds), for the dialect laws (laws.cpp): `draw_program`.
/// Each generated line is drawn together with the block it must read as (the independent
/// expectation), then spelled with random case, blanks, signs, dots, leading zeros and line
/// endings.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/block.hpp>
#include <kin5/program/number.hpp>
#include <kin5/program/work_offsets.hpp>

#include "../contract.hpp"
#include "../text_gen.hpp"

namespace kin5::test::iso_like {

using namespace kin5::program;
using kin5::test::draw_blanks;
using kin5::test::draw_case;
using kin5::test::draw_decimal;
using kin5::test::draw_direction;
using kin5::test::draw_spelling;
using kin5::test::spell_word;
using kin5::test::draw_words;

/// The codes a dialect built on ISO spells its own way (program/iso/writer.hpp, `spelling`).
struct flavour {
  std::string_view tcp_on = "G43.4";    ///< tracking on with rotary positions
  bool vector_tcp = true;               ///< G43.5 with I J K is drawn
  std::string_view extended = "G54.1";  ///< extended work offsets, P n after
  int extended_count = 300;
  bool g110 = false;                    ///< G110 … G129 select extended offsets 1 … 20 (Haas)
  char dwell_seconds = 'X';             ///< the dwell word in seconds with a decimal point
};

struct item {
  block expected;
  std::vector<std::string> words;  // spelled words, joined with random blanks
  std::optional<bool> g91;         // G91 (true) or G90 (false) said in the block
};

/// What the generator knows of the program so far (the reader's record, drawn independently).
struct state {
  std::optional<motion_kind> motion;
  arc_plane plane = arc_plane::xy;
  bool vector_tcp = false;
  bool g91 = false;          // G91 in effect: axis words are distances
  bool written_g91 = false;  // the model's G91 in effect: a machine-coordinate block said it
  bool inverse_time = false;  // G93: every feed move gives its F
  std::optional<long long> last[6];  // X Y Z A B C in thousandths: each incremental sum exact
};

/// A position in thousandths as the double the reader gives (program/incremental.hpp).
inline double thousandths(long long n) { return static_cast<double>(n) / 1000.0; }

/// The state words G17/G18/G19 and G40 read into (`block::state`); false for another word.
inline bool read_as_state(const std::string& g, block& b, state& st) {
  if (g == "G17" || g == "G18" || g == "G19") {
    st.plane = g == "G17" ? arc_plane::xy : g == "G18" ? arc_plane::zx : arc_plane::yz;
    b.state.working_plane = st.plane;
  } else if (g == "G40") {
    b.state.radius_compensation = cutter_side::off;
  } else {
    return false;
  }
  return true;
}

/// A whole code (`G1`, `M03`): random case and leading zero.
inline std::string spell_code(char letter, int v) {
  const std::string digits = std::to_string(v);
  return draw_case(std::string(1, letter)) + (v < 10 && *rc::gen::arbitrary<bool>() ? "0" : "") + digits;
}

inline void draw_motion(item& it, state& st, const flavour& f) {
  block& b = it.expected;
  const int kind = *rc::gen::inRange(0, 4);  // 0 rapid, 1 linear, 2 cw, 3 ccw
  const bool arc = kind >= 2;
  const bool known = st.last[0] && st.last[1] && st.last[2];
  if (arc && !known) return draw_motion(it, st, f);
  if (st.g91 && !(known && st.last[3] && st.last[4] && st.last[5])) {  // a distance from an unknown position
    it.g91 = false;
    st.g91 = false;
  }
  // Each axis word: a position, or under G91 a distance from the last one (the model holds the
  // position it reaches).
  const auto axis = [&](int k, char letter, long long at) {
    (k == 0 ? b.axes.x_mm : k == 1 ? b.axes.y_mm : k == 2 ? b.axes.z_mm : k == 3 ? b.axes.a_deg
     : k == 4 ? b.axes.b_deg : b.axes.c_deg) = thousandths(at);
    it.words.push_back(spell_word(letter, thousandths(st.g91 ? at - *st.last[k] : at), 3, true));
  };
  const auto draw_at = [&](int k, long long range) {  // a position, or a distance of at most `range`
    const long long d = std::llround(draw_decimal(-static_cast<double>(range), static_cast<double>(range), 3) * 1000);
    return st.g91 ? *st.last[k] + d : d;
  };
  const bool write_g = arc || !st.motion || *rc::gen::arbitrary<bool>();
  const motion_kind m = kind == 0 ? motion_kind::rapid : kind == 1 ? motion_kind::linear : kind == 2 ? motion_kind::arc_cw : motion_kind::arc_ccw;
  const motion_kind effective = write_g ? m : *st.motion;
  if (write_g) {
    b.motion = m;
    it.words.push_back(spell_code('G', kind));
  }
  st.motion = effective;
  const bool arc_effective = effective == motion_kind::arc_cw || effective == motion_kind::arc_ccw;
  long long pos[6];
  bool have[6] = {false, false, false, false, false, false};
  const char* names = "XYZABC";
  for (int k = 0; k < 3; ++k) {
    if (*rc::gen::inRange(0, 3) != 0) {
      pos[k] = draw_at(k, 1000);
      have[k] = true;
    }
  }
  if (!have[0] && !have[1] && !have[2] && (arc_effective || *rc::gen::arbitrary<bool>())) {
    pos[0] = draw_at(0, 1000);
    have[0] = true;
  }
  for (int k = 3; k < 6; ++k)
    if (*rc::gen::inRange(0, 3) == 0) pos[k] = draw_at(k, 360), have[k] = true;
  if (!have[0] && !have[1] && !have[2] && !have[3] && !have[4] && !have[5])  // at least one axis word
    pos[5] = draw_at(5, 360), have[5] = true;
  for (int k = 0; k < 6; ++k)
    if (have[k]) axis(k, names[k], pos[k]);
  if (arc_effective) {
    arc_words a;
    a.plane = st.plane;
    if (*rc::gen::arbitrary<bool>() || !known) {
      const double r = draw_decimal(-500, 500, 3);
      a.radius_mm = r;
      it.words.push_back(spell_word('R', r, 3, true));
    } else {
      const int first = st.plane == arc_plane::xy ? 0 : st.plane == arc_plane::zx ? 0 : 1;
      const int second = st.plane == arc_plane::xy ? 1 : 2;
      double c[3] = {thousandths(*st.last[0]), thousandths(*st.last[1]), thousandths(*st.last[2])};
      const bool skip_first = *rc::gen::inRange(0, 4) == 0, skip_second = !skip_first && *rc::gen::inRange(0, 4) == 0;
      for (int k : {first, second})
        if (k == first ? !skip_first : !skip_second) {
          const double off = draw_decimal(-300, 300, 3);
          c[k] = c[k] + off;
          it.words.push_back(spell_word(static_cast<char>('I' + k), off, 3, true));
        }
      a.centre_mm = kin5::vec3{c[0], c[1], c[2]};
    }
    b.arc = a;
  } else if (st.vector_tcp && *rc::gen::arbitrary<bool>()) {
    const auto [i, j, k] = draw_direction();
    b.axes.tool_axis = kin5::vec3{i, j, k};
    it.words.push_back(spell_word('I', i, 7, true));
    it.words.push_back(spell_word('J', j, 7, true));
    it.words.push_back(spell_word('K', k, 7, true));
  }
  for (int k = 0; k < 6; ++k)
    if (have[k]) st.last[k] = pos[k];
  if (*rc::gen::inRange(0, 3) == 0 || (st.inverse_time && effective != motion_kind::rapid)) {
    const double rate = draw_decimal(0.1, 20000, 1);
    b.feed = rate;
    it.words.push_back(spell_word('F', rate, 1));
  }
}

/// A dwell, alone in its block: `G4 X1.5` (seconds, always with a decimal point; Haas: `G4 P1.5`)
/// or `G04 P1500` (whole milliseconds).
inline void draw_dwell(item& it, const flavour& f) {
  const int ms = *rc::gen::inRange(0, 100000);
  it.expected.state.dwell_s = ms / 1000.0;
  it.words.push_back(draw_case(*rc::gen::element<std::string>("G4", "G04")));
  if (*rc::gen::arbitrary<bool>()) return it.words.push_back(spell_code('P', ms));
  std::string x = format_number(ms / 1000.0, 3);
  if (x.find('.') == std::string::npos) x += '.';
  it.words.push_back(draw_case(std::string(1, f.dwell_seconds)) + x);
}

inline item draw_item(state& st, const flavour& f) {
  item it;
  block& b = it.expected;
  const bool g91_before = st.g91;
  if (*rc::gen::inRange(0, 6) == 0) {  // G90 or G91 in this block
    it.g91 = *rc::gen::arbitrary<bool>();
    st.g91 = *it.g91;
  }
  if (*rc::gen::inRange(0, 5) == 0) {
    const auto n = *rc::gen::inRange<long long>(0, 100000);
    b.number = n;
    it.words.push_back(spell_code('N', static_cast<int>(n)));
  }
  switch (*rc::gen::inRange(0, 17)) {
    case 0: case 1: case 2: case 3: case 4: case 5:
      draw_motion(it, st, f);
      break;
    case 6: {  // harmless modal words, plane selection
      for (const char* g : {"G17", "G18", "G19", "G40", "G54", "G64", "G80", "G54.1", "G98"}) {
        if (*rc::gen::inRange(0, 4) != 0) continue;
        if (std::string(g).rfind("G54", 0) == 0) {  // a work offset, one per block: G54 … G59, extended n
          if (b.state.work_offset) continue;
          const bool extended = std::string(g) == "G54.1";
          const int n = extended ? *rc::gen::inRange(1, f.extended_count + 1) : *rc::gen::inRange(1, 7);
          b.state.work_offset = work_offset{extended ? work_offset_family::extended : work_offset_family::g54, n};
          if (extended && f.g110 && n <= 20 && *rc::gen::arbitrary<bool>()) {  // Haas G110 … G129: P1 … P20
            it.words.push_back(draw_case("G" + std::to_string(109 + n)));
            continue;
          }
          it.words.push_back(draw_case(extended ? std::string(f.extended) : "G" + std::to_string(53 + n)));
          if (extended) it.words.push_back(spell_code('P', n));
          continue;
        }
        std::string w = draw_case(g);
        if (!read_as_state(g, b, st)) b.kept_words.push_back(w);
        it.words.push_back(w);
      }
      if (it.words.empty() && !it.g91) it.g91 = st.g91 = false;
      if (*rc::gen::arbitrary<bool>()) draw_motion(it, st, f);
      break;
    }
    case 7: {  // tool-tip tracking
      const int kind = *rc::gen::inRange(0, 3);
      if (kind == 2) {
        b.tcp = false;
        b.state.length_compensation = false;
        st.vector_tcp = false;
        it.words.push_back(draw_case("G49"));
        break;
      }
      b.tcp = true;
      st.vector_tcp = kind == 1 && f.vector_tcp;
      it.words.push_back(draw_case(st.vector_tcp ? "G43.5" : std::string(f.tcp_on)));
      const int h = *rc::gen::inRange(0, 100);
      if (st.vector_tcp && *rc::gen::arbitrary<bool>()) {
        b.axes.tool_axis = kin5::vec3{0, 0, 1};
        it.words.push_back("I0 J0 K1.");
        if (st.inverse_time && st.motion && *st.motion != motion_kind::rapid) {  // a feed move: its F
          b.feed = 100;
          it.words.push_back("F100.");
        }
      }
      it.words.push_back(spell_code('H', h));
      b.state.length_compensation = true;  // G43.4 H n: the length of offset n, with tracking
      b.state.length_register = h;
      break;
    }
    case 8: {
      const bool inverse = *rc::gen::arbitrary<bool>();
      b.feed_mode = inverse ? feed_unit::inverse_time : feed_unit::per_minute;
      st.inverse_time = inverse;
      it.words.push_back(draw_case(inverse ? "G93" : "G94"));
      break;
    }
    case 9:
      b.metric = true;
      it.words.push_back(spell_code('G', 21));
      break;
    case 10: {  // spindle, tool, M codes
      if (*rc::gen::arbitrary<bool>()) {
        const int s = *rc::gen::inRange(1, 40001);  // S is a whole number on a Fanuc control
        b.spindle_rpm = s;
        it.words.push_back(spell_code('S', s));
      }
      if (*rc::gen::arbitrary<bool>()) {
        const int t = *rc::gen::inRange(0, 100);
        b.tool = t;
        it.words.push_back(spell_code('T', t));
      }
      const int count = *rc::gen::inRange(b.spindle_rpm || b.tool ? 0 : 1, 3);
      for (int k = 0; k < count; ++k) {
        const int m = *rc::gen::element(0, 1, 3, 4, 5, 6, 8, 9, 428);
        read_machine_function(b, m);
        it.words.push_back(spell_code('M', m));
      }
      break;
    }
    case 11: {  // a program number starts its block (after N): no G90 or G91 before it
      st.g91 = g91_before;
      it.g91.reset();
      const std::string name = std::to_string(*rc::gen::inRange(1, 9999));
      b.program_begin = name;
      it.words.push_back(draw_case("O") + name);
      break;
    }
    case 12: {
      const bool m2 = *rc::gen::arbitrary<bool>();
      b.program_end = m2 ? "M2" : "M30";
      it.words.push_back(spell_code('M', m2 ? 2 : 30));
      break;
    }
    case 13: {  // machine coordinates
      const int kind = *rc::gen::inRange(0, 4);
      const char* g = kind == 0 ? "G53" : kind == 2 ? "G30" : "G28";
      b.machine_coordinates = true;
      if (kind == 3) it.g91 = st.g91 = true;  // the homing idiom `G91 G28 Z0`
      if (kind != 0) b.machine_reference = kind == 2 ? machine_position::second_reference : machine_position::reference_point;
      it.words.push_back(draw_case(g));  // the word is `machine_reference`, not a kept word
      const double z = draw_decimal(-500, 500, 3);
      b.axes.z_mm = z;
      it.words.push_back(spell_word('Z', z, 3, true));
      st.last[2].reset();  // the machine's position
      break;
    }
    case 14: {  // controller modes
      const bool on = *rc::gen::arbitrary<bool>();
      b.kept_words = {draw_case("G05.1"), on ? "Q1" : "Q0"};
      it.words = {b.kept_words[0], b.kept_words[1]};
      b.number.reset();
      break;
    }
    case 15:  // a dwell, a block of its own
      if (!it.g91) draw_dwell(it, f);
      break;
    default: {  // not understood, no axis words
      st.g91 = g91_before;
      b = block{};
      b.passthrough = true;
      b.text = *rc::gen::element<std::string>("%", "%_N_X");  // words not understood are refused
      it.words = {b.text};
      return it;
    }
  }
  if (it.g91) it.words.insert(it.words.begin() + (b.number ? 1 : 0), draw_case(*it.g91 ? "G91" : "G90"));
  if (*rc::gen::inRange(0, 4) == 0) {
    const std::string c = draw_words();
    b.comment = c;
    it.words.push_back(*rc::gen::arbitrary<bool>() ? "(" + draw_blanks() + c + draw_blanks() + ")" : ";" + c);
  }
  if (it.words.empty()) it.words.push_back("G90"), it.g91 = st.g91 = false;
  // The distance mode the model says (iso/reader.hpp, `absolute_positions`): a machine-coordinate
  // block the control's own, a move G90 where the model's G91 is in effect, another block what
  // it writes.
  if (b.machine_coordinates) {
    if (it.g91 || st.written_g91 != st.g91) b.state.distance = st.g91 ? distance_mode::incremental : distance_mode::absolute;
    st.written_g91 = st.g91;
  } else if (b.moves() || (b.motion && (*b.motion == motion_kind::arc_cw || *b.motion == motion_kind::arc_ccw))) {
    if (it.g91 || st.written_g91) b.state.distance = distance_mode::absolute;
    st.written_g91 = false;
  } else if (it.g91) {
    b.state.distance = st.g91 ? distance_mode::incremental : distance_mode::absolute;
    st.written_g91 = st.g91;
  }
  return it;
}

inline std::string spell(const std::vector<item>& items) {
  const std::string eol = *rc::gen::element<std::string>("\n", "\r\n", "\r");
  std::string text;
  for (const item& it : items) {
    if (*rc::gen::inRange(0, 10) == 0) text += draw_blanks() + eol;
    text += kin5::test::draw_line(it.words) + eol;
  }
  return text;
}


/// Text drawn with the block each line must read as, in dialect D spelled as `f` says.
template <class D>
drawn_program draw_program(const flavour& f) {
  state st;
  const auto items = draw_items(39, [&] { return draw_item(st, f); });
  // After an end (M2, M30) the control stops, and an `O` line starts a program of the file that
  // runs only where it is called (docs/dialects/iso.md): none is, so no line from there is read.
  std::size_t read = items.size();
  bool ended = false;
  for (std::size_t i = 0; i < items.size() && read == items.size(); ++i) {
    if (ended && items[i].expected.program_begin) read = i;
    ended = ended || items[i].expected.program_end.has_value();
  }
  return drawn_from<D>(spell(items), std::vector<item>(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(read)));
}

}  // namespace kin5::test::iso_like
