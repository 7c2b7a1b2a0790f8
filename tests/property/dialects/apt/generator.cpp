// Generated APT CL data for the dialect laws (laws.cpp). Each generated statement is
// drawn together with the block it must read as (the independent expectation), then spelled
// with random case, blanks, signs, dots, `$` continuations and line endings.
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/apt/dialect.hpp>

#include "../text_gen.hpp"
#include "contract.hpp"

namespace {

using namespace kin5::program;
using kin5::test::draw_blanks;
using kin5::test::draw_case;
using kin5::test::draw_decimal;
using kin5::test::draw_direction;
using kin5::test::draw_spelling;
using kin5::test::draw_words;

struct item {
  block expected;
  std::string text;  // the statement, without its line ending
};

/// `MAJOR/arg,arg` with random blanks and case.
std::string statement(const std::string& major, const std::vector<std::string>& args) {
  std::string s = draw_case(major) + draw_blanks() + "/" + draw_blanks();
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i) s += draw_blanks() + "," + draw_blanks();
    s += args[i];
  }
  return s;
}

/// One statement and the block it reads as. `rapid_pending`: a RAPID came since the last GOTO.
item draw_item(bool& rapid_pending) {
  item it;
  block& b = it.expected;
  switch (*rc::gen::inRange(0, 15)) {
    case 0:
    case 1:
    case 2: {  // GOTO, 3 or 6 values
      const double x = draw_decimal(-5000, 5000, 3), y = draw_decimal(-5000, 5000, 3), z = draw_decimal(-2000, 2000, 3);
      b.axes.x_mm = x, b.axes.y_mm = y, b.axes.z_mm = z;
      std::vector<std::string> args{draw_spelling(x, 3), draw_spelling(y, 3), draw_spelling(z, 3)};
      if (*rc::gen::arbitrary<bool>()) {
        const auto [i, j, k] = draw_direction();
        b.axes.tool_axis = kin5::vec3{i, j, k};
        for (double v : {i, j, k}) args.push_back(draw_spelling(v, 7));
      }
      b.motion = rapid_pending ? motion_kind::rapid : motion_kind::linear;
      rapid_pending = false;
      it.text = statement("GOTO", args);
      break;
    }
    case 3:
      b.motion = motion_kind::rapid;
      b.feed_rapid = true;
      rapid_pending = true;
      it.text = draw_case("RAPID");
      break;
    case 4: {
      const double f = draw_decimal(0.1, 20000, 1);
      b.feed = f;
      const int form = *rc::gen::inRange(0, 4);
      b.feed_mode = form == 3 ? feed_unit::inverse_time : feed_unit::per_minute;
      const std::string v = draw_spelling(f, 1);
      it.text = form == 0 ? statement("FEDRAT", {v})
                : form == 1 ? statement("FEDRAT", {draw_case("MMPM"), v})
                : form == 2 ? statement("FEDRAT", {v, draw_case("MMPM")})
                            : statement("FEDRAT", {draw_case("INVERS"), v});
      break;
    }
    case 5: {
      const int form = *rc::gen::inRange(0, 6);
      const double s = draw_decimal(1, 40000, 1);
      if (form == 0) b.state.spindle = spindle_rotation::stopped, it.text = statement("SPINDL", {draw_case("OFF")});
      else if (form == 1) b.spindle_rpm = s, it.text = statement("SPINDL", {draw_spelling(s, 1)});
      else if (form == 2) b.spindle_rpm = s, b.state.spindle = spindle_rotation::clockwise, it.text = statement("SPINDL", {draw_spelling(s, 1), draw_case("CLW")});
      else if (form == 3) b.spindle_rpm = s, b.state.spindle = spindle_rotation::counter_clockwise, it.text = statement("SPINDL", {draw_case("RPM"), draw_spelling(s, 1), draw_case("CCLW")});
      else if (form == 4) b.state.spindle = spindle_rotation::clockwise, it.text = statement("SPINDL", {draw_case("ON")});
      else b.state.spindle = spindle_rotation::counter_clockwise, it.text = statement("SPINDL", {draw_case("CCLW")});
      break;
    }
    case 6: {
      const auto t = *rc::gen::inRange<long long>(0, 1000);
      b.tool = t;
      b.state.tool_change = true;  // as ISO's T n M6
      it.text = *rc::gen::arbitrary<bool>() ? statement("LOADTL", {draw_spelling(static_cast<double>(t), 0)})
                                            : statement("LOAD", {draw_case("TOOL"), draw_spelling(static_cast<double>(t), 0)});
      break;
    }
    case 7: {
      const int form = *rc::gen::inRange(0, 4);
      if (form == 3) b.state.coolant_mist = true;
      else if (form == 2) b.state.coolant_flood = b.state.coolant_mist = false;
      else b.state.coolant_flood = true;
      it.text = statement("COOLNT", {draw_case(form == 0 ? "ON" : form == 1 ? "FLOOD" : form == 2 ? "OFF" : "MIST")});
      break;
    }
    case 8: {
      const bool stop = *rc::gen::arbitrary<bool>();
      b.state.stop = stop ? program_stop::stop : program_stop::optional_stop;
      it.text = draw_case(stop ? "STOP" : "OPSTOP");
      break;
    }
    case 9:
      b.metric = true;
      it.text = statement("UNITS", {draw_case("MM")});
      break;
    case 10: {
      const std::string name = draw_words();
      b.program_begin = name;
      it.text = draw_case("PARTNO") + " " + draw_blanks() + name;
      break;
    }
    case 11:
      b.program_end = std::string();
      it.text = draw_case("FINI");
      break;
    case 12: {
      const std::string c = draw_words();
      b.comment = c;
      it.text = *rc::gen::arbitrary<bool>() ? "$$" + draw_blanks() + c : statement("PPRINT", {c});
      return it;  // already a comment
    }
    case 13: {
      if (*rc::gen::arbitrary<bool>()) {  // MULTAX, kept as the APT statement it is
        const std::string form = *rc::gen::element<std::string>("", "ON", "OFF");
        b.kept_words = {form.empty() ? "MULTAX" : "MULTAX/" + form};
        it.text = form.empty() ? draw_case("MULTAX") : statement("MULTAX", {draw_case(form)});
      } else {  // a tool made ready, not changed: a T without M6
        const auto t = *rc::gen::inRange<long long>(0, 1000);
        b.tool = t;
        it.text = statement("SELECT", {draw_case("TOOL"), draw_spelling(static_cast<double>(t), 0)});
      }
      break;
    }
    default: {
      b.passthrough = true;
      // Only statements that change no motion pass through (vocabulary.hpp); the rest are refused.
      it.text = *rc::gen::element<std::string>("CUTTER/10,0.5",
                                               "TOOL PATH/ROUGH,TOOL,EM10", "MSYS/0,0,0,1,0,0,0,1,0",
                                               "CSYS/1,0,0,0,0,1,0,0,0,0,1,0", "TLDATA/MILL,10,0.5,75,0");
      b.text = it.text;
      return it;
    }
  }
  if (*rc::gen::inRange(0, 4) == 0) {  // an inline comment
    const std::string c = draw_words();
    b.comment = c;
    it.text += draw_blanks() + " $$" + draw_blanks() + c;
  }
  return it;
}

/// Spells `items` as a file: optional blank lines, `$` continuations after a comma or slash,
/// LF / CRLF / CR line endings, leading blanks.
std::string spell(const std::vector<item>& items) {
  const std::string eol = *rc::gen::element<std::string>("\n", "\r\n", "\r");
  std::string text;
  for (const item& it : items) {
    if (*rc::gen::inRange(0, 8) == 0) text += draw_blanks() + eol;
    std::string s = it.text;
    const bool is_code = !it.expected.passthrough && s.rfind("$$", 0) != 0 &&
                         !it.expected.comment.has_value() && s.find('/') != std::string::npos;
    if (is_code && *rc::gen::inRange(0, 3) == 0) {  // break after a comma or the slash
      std::vector<std::size_t> cuts;
      for (std::size_t k = 0; k < s.size(); ++k)
        if (s[k] == ',' || s[k] == '/') cuts.push_back(k + 1);
      const std::size_t cut = cuts[*rc::gen::inRange<std::size_t>(0, cuts.size())];
      s = s.substr(0, cut) + draw_blanks() + "$" + eol + draw_blanks() + s.substr(cut);
    }
    text += draw_blanks() + s + draw_blanks() + eol;
  }
  return text;
}

}  // namespace

/// Text drawn with the block each line must read as (see the top of this file).
kin5::test::drawn_program kin5::test::contract<kin5::program::apt::dialect>::draw_program() {
  bool rapid_pending = false;
  const auto items = kin5::test::draw_items(39, [&] { return ::draw_item(rapid_pending); });
  return kin5::test::drawn_from<kin5::program::apt::dialect>(::spell(items), items);
}
