// Source checks and the angle tolerance (translate/source_checks.hpp, angle_tolerance.hpp):
// axis words the source machine lacks and values outside its travel are errors at the word;
// the tolerance lets a rounded value or tool axis count as on an edge, and no further; a rotary
// axis with no value is refused unless allowed; an empty program is an input error. Programs
// are written as text in each NC dialect and read by its reader, so the columns are the text's.
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>

#include "generators.hpp"
#include "program_builder.hpp"

namespace {

using namespace kin5;
using program::dialect;

/// "X+1.500" (Heidenhain) or "X1.500" (Siemens, ISO): a word with `decimals` decimals.
std::string word(dialect d, char letter, double v, int decimals = 3) {
  std::string number = translate_detail::fixed(v, decimals);
  if (d == program::id_of<program::heidenhain::dialect>() && number.front() != '-') number = "+" + number;
  return std::string(1, letter) + number;
}

/// A program text in dialect `d`: TCP on, then one motion line per entry of `motions` (each a
/// list of words), then the end. `first_motion_line`: the line of the first motion.
struct program_text {
  std::string text;
  std::size_t first_motion_line = 0;
};
program_text nc_text(dialect d, const std::vector<std::vector<std::string>>& motions) {
  program_text p;
  std::size_t line = 0;
  auto add = [&](const std::string& l) { p.text += l + "\n", ++line; };
  const std::string motion_word = d == program::id_of<program::heidenhain::dialect>() ? "L" : "G1";
  if (d == program::id_of<program::heidenhain::dialect>()) add("0 BEGIN PGM T MM"), add("1 M128");
  if (d == program::id_of<program::siemens::dialect>()) add("N10 TRAORI");
  if (d == program::id_of<program::iso::dialect>()) add("%"), add("O1000"), add("G43.4 H1");
  p.first_motion_line = line + 1;
  for (std::size_t k = 0; k < motions.size(); ++k) {
    std::string l = d == program::id_of<program::heidenhain::dialect>() ? std::to_string(line) + " " : (d == program::id_of<program::siemens::dialect>() ? "N" + std::to_string(10 * (line + 1)) + " " : "");
    l += motion_word;
    for (const auto& w : motions[k]) l += " " + w;
    if (k == 0) l += " F500";
    add(l);
  }
  if (d == program::id_of<program::heidenhain::dialect>()) add(std::to_string(line) + " END PGM T MM");
  if (d == program::id_of<program::siemens::dialect>()) add("N" + std::to_string(10 * (line + 1)) + " M30");
  if (d == program::id_of<program::iso::dialect>()) add("M30"), add("%");
  return p;
}

/// The column of `w` in line `line` (1-based) of `text`.
std::size_t column_of(const std::string& text, std::size_t line, const std::string& w) {
  std::size_t start = 0;
  for (std::size_t k = 1; k < line; ++k) start = text.find('\n', start) + 1;
  const std::string l = text.substr(start, text.find('\n', start) - start);
  return l.find(" " + w) + 2;
}

/// The words of M's commanded angles `a` (degrees), `decimals` decimals.
template <machine M>
std::vector<std::string> rotary_text(dialect d, const rotary_angles<M>& a, int decimals = 3) {
  std::vector<std::string> words;
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    words.push_back(word(d, to_char(M::rotary[i].letter), to_degrees(a[i]).value, decimals));
  return words;
}

constexpr dialect nc_dialects[] = {program::id_of<program::siemens::dialect>(), program::id_of<program::heidenhain::dialect>(), program::id_of<program::iso::dialect>()};

/// Translates `text` (dialect `d`) from M to itself.
template <machine From, machine To = From>
translation translate_text(dialect d, const std::string& text, translate_options options = test::options()) {
  const auto read = program::read(d, text, "t.nc");
  if (!read.ok()) throw std::runtime_error("test program not read: " + read.errors.front().to_string());
  return translate<From, To>(read.parsed, options);
}

}  // namespace

TEST_CASE("an axis word the source machine lacks is an error at that word, in every NC dialect") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string("a foreign rotary word on ") + std::string(M::id), [] {
      const dialect d = *rc::gen::elementOf(std::vector<dialect>(std::begin(nc_dialects), std::end(nc_dialects)));
      std::vector<char> foreign;
      for (char l : {'A', 'B', 'C'})
        if (rotary_index<M>(static_cast<axis_letter>(l)) == rotary_count<M>) foreign.push_back(l);
      const char letter = *rc::gen::elementOf(foreign);
      std::vector<std::vector<std::string>> motions;
      const auto n = *rc::gen::inRange<std::size_t>(1, 6);
      const auto bad = *rc::gen::inRange<std::size_t>(0, n);
      std::string bad_word;
      for (std::size_t k = 0; k < n + 1; ++k) {
        const vec3 tip = *test::tip();
        std::vector<std::string> w{word(d, 'X', tip.x), word(d, 'Y', tip.y), word(d, 'Z', tip.z)};
        for (const auto& r : rotary_text<M>(d, *test::angles_within<M>())) w.push_back(r);
        if (k == bad + 1) {  // never in the first motion, which sets every axis
          bad_word = word(d, letter, *test::uniform(-90.0, 90.0));
          w.insert(w.begin() + static_cast<long>(*rc::gen::inRange<std::size_t>(3, w.size() + 1)), bad_word);
        }
        motions.push_back(w);
      }
      const auto p = nc_text(d, motions);
      const auto t = translate_text<M>(d, p.text);
      const std::size_t line = p.first_motion_line + bad + 1;
      RC_ASSERT(t.errors.size() == 1u);
      const auto& e = t.errors.front();
      RC_ASSERT(e.where.line == line);
      RC_ASSERT(e.where.column == column_of(p.text, line, bad_word));
      RC_ASSERT(e.construct == bad_word);
      RC_ASSERT(e.message.find(std::string(M::id) + " has no " + letter + " axis") != std::string::npos);
    });
  });
}

TEST_CASE("a rotary value outside the source travel is an error unless within the angle tolerance") {
  // The bounded axes of the catalog: A on sajo-12000p [-120, 30], ac-trunnion [-120, 120],
  // ac-head [-110, 110]; B on dmu-80p and dmu-50v [0, 180]. A value off the edge by s with
  // tolerance t (given; t has a fifth decimal 5, s four decimals, so never s = t).
  machines::for_each_machine([]<class M>() {
    std::size_t bounded = rotary_count<M>;
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      if (!M::rotary[i].travel.continuous) bounded = i;
    if (bounded == rotary_count<M>) return;
    rc::prop(std::string("past an edge of ") + std::string(M::id), [bounded] {
      const dialect d = *rc::gen::elementOf(std::vector<dialect>(std::begin(nc_dialects), std::end(nc_dialects)));
      const rotary_travel travel = M::rotary[bounded].travel;
      const bool upper = *rc::gen::arbitrary<bool>();
      const double tolerance = (*rc::gen::inRange(0, 100) + 0.5) * 1e-4;
      const double past = *rc::gen::element(0.0001, 0.01, 1.0, 30.0) * *rc::gen::inRange(-3, 4);
      const double v = upper ? travel.upper.value + past : travel.lower.value - past;
      rotary_angles<M> angles = *test::angles_within<M>();
      angles[bounded] = to_radians(degrees{v});
      const auto first = rotary_text<M>(d, *test::angles_within<M>());
      auto second = rotary_text<M>(d, angles, 4);
      std::vector<std::string> a{word(d, 'X', 1), word(d, 'Y', 2), word(d, 'Z', 3)}, b = a;
      a.insert(a.end(), first.begin(), first.end());
      b.insert(b.end(), second.begin(), second.end());
      const auto p = nc_text(d, {a, b});
      auto options = test::options();
      options.common.angle_tolerance = degrees{tolerance};
      const auto t = translate_text<M, machines::sajo_12000p>(d, p.text, options);
      std::vector<program::diagnostic> travel_errors;
      for (const auto& e : t.errors)
        if (e.message.find("outside the travel") != std::string::npos) travel_errors.push_back(e);
      RC_ASSERT(travel_errors.size() == (past > tolerance ? 1u : 0u));
      if (past > tolerance) {
        const auto& e = travel_errors.front();
        const std::string written = second[bounded];
        RC_ASSERT(e.where.line == p.first_motion_line + 1);
        RC_ASSERT(e.where.column == column_of(p.text, e.where.line, written));
        const std::string range = "[" + translate_detail::degrees_text(travel.lower.value) + ", " +
                                  translate_detail::degrees_text(travel.upper.value) + "]";
        RC_ASSERT(e.message.find(range) != std::string::npos);
      }
    });
  });
}

TEST_CASE("the angle tolerance counts a tool axis as on the target's reach within n tolerances, and no further") {
  // sajo-12000p -> dmu-80p: A = d > 0 is outside the DMU's reach by exactly d (P14). Two source
  // angles are rounded, so the tool axis may be off by 2t: reachable iff d <= 2t.
  rc::prop("A = d on the SAJO, tolerance t", [] {
    const double t = *test::uniform(1e-5, 0.01);
    const double ratio = *rc::gen::suchThat(test::uniform(0.01, 4.0), [](double r) { return std::abs(r - 2.0) > 0.05; });
    auto p = test::tcp_program(program::id_of<program::siemens::dialect>(), "reach.mpf");
    test::add_motion(p, {0.0, 0.0, 50.0, -30.0, 10.0, std::nullopt, 500.0});
    // B within 179° of the first block's: a move of 180° or more is a sweep, which the DMU 80P
    // may be unable to follow (round_trip_laws.cpp).
    test::add_motion(p, {1.0, 0.0, 50.0, ratio * t, *test::uniform(-169.0, 189.0), std::nullopt, std::nullopt});
    auto options = test::options();
    options.common.angle_tolerance = degrees{t};
    const auto r = translate<machines::sajo_12000p, machines::dmu_80p>(p, options);
    RC_ASSERT(r.ok() == (ratio < 2.0));
    RC_ASSERT(r.per_class[static_cast<std::size_t>(matchability::unreachable)] == (ratio < 2.0 ? 0u : 1u));
  });
}

TEST_CASE("a value rounded past a travel limit within the tolerance is written on the limit") {
  // ac-trunnion to itself: A = 120 + e. Within the tolerance, the source accepts it and the
  // target clamps it to its travel limit 120 exactly; beyond, the source refuses it.
  rc::prop("A = 120 + e on the ac-trunnion", [] {
    const double t = *test::uniform(1e-4, 0.01);
    const double e = *rc::gen::suchThat(test::uniform(0.0, 2.0 * t), [t](double x) { return std::abs(x - t) > 1e-6; });
    auto p = test::tcp_program(program::id_of<program::siemens::dialect>(), "edge.mpf");
    const double c = *test::uniform(-180.0, 180.0);
    test::add_motion(p, {0.0, 0.0, 50.0, 120.0 + e, std::nullopt, c, 500.0});
    auto options = test::options(feed_policy::tcp, program::id_of<program::siemens::dialect>());
    options.common.angle_tolerance = degrees{t};
    const auto r = translate<machines::ac_trunnion, machines::ac_trunnion>(p, options);
    RC_ASSERT(r.ok() == (e <= t));
    if (e > t) return;
    const auto& out = r.output.blocks.back();
    RC_ASSERT(out.axes.a_deg.has_value());
    RC_ASSERT(std::abs(std::abs(*out.axes.a_deg) - 120.0) <= 1e-9);
  });
}

TEST_CASE("a 4-axis program through a 5-axis machine's 3-decimal text comes back within the default tolerance") {
  // a-rotary-4axis -> dmu-80p writes B and C with 3 decimals; read back, their tool axis is off
  // the 4-axis reach (u_x = 0) by rounding only, at most 2 x 0.0005 deg: not an error.
  rc::prop("A with 3 decimals, there and back", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 8);
    std::vector<std::vector<std::string>> motions;
    std::vector<double> a_deg;
    for (std::size_t k = 0; k < n; ++k) {
      const double a = std::round(*test::uniform(-85.0, 85.0) * 1000.0) / 1000.0;
      const vec3 tip = *test::tip();
      motions.push_back({word(program::id_of<program::iso::dialect>(), 'X', tip.x), word(program::id_of<program::iso::dialect>(), 'Y', tip.y), word(program::id_of<program::iso::dialect>(), 'Z', tip.z),
                         word(program::id_of<program::iso::dialect>(), 'A', a)});
      a_deg.push_back(a);
    }
    const auto there = translate_text<machines::a_rotary_4axis, machines::dmu_80p>(program::id_of<program::iso::dialect>(), nc_text(program::id_of<program::iso::dialect>(), motions).text);
    RC_ASSERT(there.ok());
    const std::string h = program::write(program::id_of<program::heidenhain::dialect>(), there.output);
    auto options = test::options(feed_policy::tcp, program::id_of<program::iso::dialect>());
    const auto back = translate_text<machines::dmu_80p, machines::a_rotary_4axis>(program::id_of<program::heidenhain::dialect>(), h, options);
    RC_ASSERT(back.ok());
    RC_ASSERT(back.angle_tolerance.value == 0.0005);
    std::size_t k = 0;
    for (const auto& b : back.output.blocks)
      if (b.axes.a_deg) RC_ASSERT(std::abs(std::remainder(*b.axes.a_deg - a_deg[k++], 360.0)) <= 0.002);
    RC_ASSERT(k == n);
  });
}

TEST_CASE("a rotary axis with no value yet is refused, or taken as 0 when allowed") {
  auto p = test::tcp_program(program::id_of<program::siemens::dialect>(), "unset.mpf");
  test::add_motion(p, {0.0, 0.0, 50.0, -30.0, std::nullopt, std::nullopt, 500.0});  // no B
  test::add_motion(p, {1.0, 0.0, 50.0, -30.0, 10.0, std::nullopt, std::nullopt});
  auto explicit_zero = p;
  explicit_zero.blocks[1].axes.b_deg = 0.0;
  using From = machines::sajo_12000p;
  using To = machines::dmu_80p;

  const auto refused = translate<From, To>(p, test::options());
  REQUIRE(refused.errors.size() == 1);
  CHECK(refused.errors[0].where.line == 2);
  CHECK(refused.errors[0].construct == "unset-rotary");
  CHECK(refused.errors[0].option == "--allow unset-rotary");
  CHECK(refused.allowed.empty());

  auto options = test::options();
  REQUIRE(options.common.allow.add("unset-rotary"));
  CHECK_FALSE(options.common.allow.add("no-such-refusal"));
  const auto allowed = translate<From, To>(p, options);
  CHECK(allowed.ok());
  REQUIRE(allowed.allowed.size() == 1);
  CHECK(allowed.allowed[0].where.line == 2);
  const auto zero = translate<From, To>(explicit_zero, test::options());
  REQUIRE(zero.ok());
  REQUIRE(zero.output.blocks.size() == allowed.output.blocks.size());
  for (std::size_t k = 0; k < zero.output.blocks.size(); ++k) CHECK(zero.output.blocks[k].axes == allowed.output.blocks[k].axes);
}

TEST_CASE("resolution: decimals per word class, scanned from the text of each dialect") {
  using program::scan_resolution;
  const auto s = scan_resolution("N10 G1 X10.1234 Y=2.5 A30.05 F1200.5 S8000 ; X1.1234567\nN20 A3=0.12345 R1=2.123456\n",
                                 program::id_of<program::siemens::dialect>());
  CHECK(s.linear_decimals == 4);
  CHECK(s.angle_decimals == 2);
  CHECK(s.feed_decimals == 1);
  CHECK(s.speed_decimals == 0);
  const auto h = scan_resolution("5 L X+1.5 Y-2 Z+3.25 B+12.3456 C-0.1 FMAX\n6 L IX+1.123456 R0 F MAX\n", program::id_of<program::heidenhain::dialect>());
  CHECK(h.linear_decimals == 2);
  CHECK(h.angle_decimals == 4);
  CHECK_FALSE(h.feed_decimals.has_value());
  const auto i = scan_resolution("G1X10.123Y20.A-5.1234(A1.1234567)F100.\n", program::id_of<program::iso::dialect>());
  CHECK(i.linear_decimals == 3);
  CHECK(i.angle_decimals == 4);
  CHECK(i.feed_decimals == 0);
  const auto a = scan_resolution("GOTO/1.5,2.25,3.125,0.1234567,0.0,0.9923\nFEDRAT/MMPM,1200.75\nSPINDL/RPM,6000\n",
                                 program::id_of<program::apt::dialect>());
  CHECK(a.linear_decimals == 3);
  CHECK(a.vector_decimals == 7);
  CHECK(a.feed_decimals == 2);
  CHECK(a.speed_decimals == 0);
  CHECK_FALSE(a.angle_decimals.has_value());

  CHECK(default_angle_tolerance(s).value == 0.0005);  // 2 decimals: 0.005, capped
  CHECK(default_angle_tolerance(h).value == Approx(0.00005).margin(1e-15));
  CHECK(default_angle_tolerance(program::number_resolution{}).value == 0.0005);
  CHECK(default_angle_tolerance(a).value == Approx(std::sqrt(3.0) * 0.5e-7 * 180.0 / pi).margin(1e-15));
}

/// The words of `text` as the word rule states them, line by line (`for_each_address_word`):
/// letter, offset in `text`, decimals.
std::vector<std::tuple<char, std::size_t, int>> words_line_by_line(std::string_view text, dialect d) {
  std::vector<std::tuple<char, std::size_t, int>> words;
  program::for_each_line(text, [&](const program::text_line& line) {
    program::for_each_address_word(line.text, d, [&](const program::address_word& w) {
      words.emplace_back(w.letter, static_cast<std::size_t>(line.text.data() - text.data()) + w.offset, w.decimals);
    });
  });
  return words;
}

TEST_CASE("resolution: the one-pass scan finds the words of the word rule, line by line") {
  // Texts of words of every class (and not) and of the bytes the rule turns on: letters,
  // boundaries, signs, points, `=`, comments, strings and every line ending.
  static const std::vector<std::string> pieces{
      "X1.5", "y=-2.25", "A3", "b+.125", "C7.", "F100.5", "S1.25", "I12.125", "r7.75", "G1", "N10", "A3=0.5", "LN",
      "X", "c", "_", "#", "$", "=", "+", "-", ".", "0", "7", "12.5", " ", "\t", "\n", "\r", "\r\n", ";", "(", ")",
      "\"", "\xc3\xa4"};
  for (std::size_t i = 0; i < program::dialect_count; ++i) {  // every letter-address (NC) dialect
    const dialect d{i};
    if (program::capabilities_of(d).cl_data) continue;
    rc::prop(std::string("dialect ") + std::string(program::name(d)), [d] {
      // Every piece as likely at any size (inRange alone favours the first ones on small sizes).
      const auto piece = rc::gen::resize(100, rc::gen::inRange<std::size_t>(0, pieces.size()));
      const auto picks = *rc::gen::container<std::vector<std::size_t>>(piece);
      std::string text;
      for (std::size_t k : picks) text += pieces[k];
      std::vector<std::tuple<char, std::size_t, int>> words;
      program::for_each_address_word_in_text(text, d, [&](char letter, std::size_t offset, int decimals) {
        words.emplace_back(letter, offset, decimals);
      });
      RC_ASSERT(words == words_line_by_line(text, d));
      program::number_resolution counted;
      for (const auto& [letter, offset, decimals] : words) program::detail::count_word(counted, letter, decimals);
      // and the parameters words use, as scan_resolution says (`A3=0.5` then `XA3`: a named one)
      program::count_parameter_words(text, counted);
      RC_ASSERT(program::scan_resolution(text, d) == counted);
    });
  }
}

TEST_CASE("an empty program is an input error, and nothing reaches the sink") {
  for (const char* text : {"", "\n\n  \n"}) {
    const auto t = make_translator<machines::sajo_12000p, machines::dmu_80p>(program::id_of<program::siemens::dialect>(), "empty.mpf");
    string_sink out;
    const auto run = stream_text(*t, text, program::id_of<program::siemens::dialect>(), "empty.mpf", program::id_of<program::heidenhain::dialect>(), out);
    REQUIRE(run.input.errors.size() == 1);
    CHECK(run.input.errors[0].message.find("empty program") != std::string::npos);
    CHECK(run.input.errors[0].where.line == 0);
    CHECK_FALSE(run.ok(*t));
    CHECK(out.text.empty());
  }
  const auto t = make_translator<machines::sajo_12000p, machines::dmu_80p>(program::id_of<program::siemens::dialect>(), "comment.mpf");
  string_sink out;
  const auto run = stream_text(*t, "; only a comment\n", program::id_of<program::siemens::dialect>(), "comment.mpf", program::id_of<program::heidenhain::dialect>(), out);
  CHECK(run.input.ok());
}

TEST_CASE("post refuses an NC program given as CL data, and nothing reaches the sink") {
  const auto post_text = [](const std::string& text) {
    const auto t = make_post<machines::dmu_80p>(program::id_of<program::apt::dialect>(), program::id_of<program::heidenhain::dialect>(), "p.cl");
    string_sink out;
    auto run = stream_text(*t, text, program::id_of<program::apt::dialect>(), "p.cl", program::id_of<program::heidenhain::dialect>(), out);
    CHECK(out.text.empty() == !run.ok(*t));
    return run.input;
  };
  // Recognised by its markers: named.
  const auto siemens = post_text("%_N_P_MPF\nN10 TRAORI\nN20 G1 X0 Y0 Z50 A-30 B10 F500\nN30 M30\n");
  REQUIRE(siemens.errors.size() == 1);
  CHECK(siemens.errors[0].message.find("it reads as an NC program in the siemens dialect") != std::string::npos);
  // No marker: no GOTO/, and the ISO reader finds fewer errors than the APT reader (4): one
  // error naming the dialect, not one per line.
  const auto iso = post_text("%\nO1000\nG0 X0 Y0 Z50.\nG1 X10. F500\nM30\n%\n");
  REQUIRE(iso.errors.size() == 1);
  CHECK(iso.errors[0].where.line == 0);  // about the whole file
  CHECK(iso.errors[0].message == "not APT CL data: it reads as an NC program in the iso dialect (no GOTO/, and its reader finds fewer "
                                 "errors); post reads CL data, translate and reverse read NC programs");
  // APT with a mistake and no GOTO/ is still APT: its own errors, at their lines.
  const auto apt = post_text("PARTNO P\nUNITS/MM\nFEDRAT/MMPM,500.0\nGOTO/0.0,0.0\nFINI\n");
  REQUIRE_FALSE(apt.ok());
  CHECK(apt.errors[0].where.line == 4);
  // CL data with a statement kin5 does not read still posts (with its warning).
  CHECK(post_text("PARTNO P\nUNITS/MM\nFEDRAT/MMPM,500.0\nGOTO/0.0,0.0,10.0,0.0,0.0,1.0\nFINI\n").ok());
}

TEST_CASE("M functions whose meaning is the machine maker's are refused across dialects, or mapped knowingly") {
  using M = machines::dmu_80p;
  const std::string text = "0 BEGIN PGM T MM\n1 TOOL CALL 3 Z S8000\n2 M128\n3 L X+0 Y+0 Z+50 B+10 C+0 F500 M3\n"
                           "4 M126\n5 L X+1 M8\n6 M129\n7 END PGM T MM\n";
  const auto run = [&](dialect out, const std::vector<std::string>& map) {
    auto options = test::options(feed_policy::tcp, out);
    for (const auto& m : map) REQUIRE(options.common.m_codes.add(m));
    const auto t = make_translator<M, M>(program::id_of<program::heidenhain::dialect>(), "m.h", options);
    string_sink written;
    const auto r = stream_text(*t, text, program::id_of<program::heidenhain::dialect>(), "m.h", out, written);
    REQUIRE(r.input.ok());
    return std::pair{t->result(), r.ok(*t) ? written.text : std::string()};
  };
  for (dialect out : {program::id_of<program::siemens::dialect>(), program::id_of<program::iso::dialect>()}) {
    const auto [refused, nothing] = run(out, {});
    REQUIRE(refused.errors.size() == 1);
    CHECK(refused.errors[0].where.line == 5);
    CHECK(refused.errors[0].where.column == 3);
    CHECK(refused.errors[0].construct == "M126");
    CHECK(refused.errors[0].option == "--m-map 126=");
    CHECK(nothing.empty());
    const auto [dropped, without] = run(out, {"126="});
    CHECK(dropped.ok());
    CHECK(without.find("M126") == std::string::npos);
    CHECK(without.find("M3") != std::string::npos);  // shared: carried
    CHECK(without.find("M8") != std::string::npos);
    const auto [renamed, with] = run(out, {"126=86"});
    CHECK(renamed.ok());
    CHECK(with.find("M86") != std::string::npos);
  }
  const auto [same, copied] = run(program::id_of<program::heidenhain::dialect>(), {});  // within one dialect: copied
  CHECK(same.ok());
  CHECK(copied.find("M126") != std::string::npos);

  // The shared table: mist (M7) has no TNC standard function; M7 between G-code dialects passes.
  CHECK_FALSE(shared_m_code(7, program::id_of<program::siemens::dialect>(), program::id_of<program::heidenhain::dialect>(), false));
  CHECK(shared_m_code(7, program::id_of<program::siemens::dialect>(), program::id_of<program::iso::dialect>(), false));
  CHECK_FALSE(shared_m_code(99, program::id_of<program::heidenhain::dialect>(), program::id_of<program::iso::dialect>(), false));  // cycle call vs subprogram return
  CHECK(shared_m_code(91, program::id_of<program::heidenhain::dialect>(), program::id_of<program::iso::dialect>(), true));
  CHECK_FALSE(shared_m_code(91, program::id_of<program::heidenhain::dialect>(), program::id_of<program::iso::dialect>(), false));
  m_map bad;
  CHECK_FALSE(bad.add("126"));
  CHECK_FALSE(bad.add("x=1"));
  CHECK_FALSE(bad.add("1=-2"));
}

TEST_CASE("spindle and coolant M functions are state words across dialects: Heidenhain M13, --m-map of M8") {
  using M = machines::dmu_80p;
  const std::string text = "0 BEGIN PGM T MM\n1 TOOL CALL 3 Z S8000\n2 M128\n3 L X+0 Y+0 Z+50 B+10 C+0 F500 M13\n"
                           "4 L X+1 M5 M9\n5 M129\n6 END PGM T MM\n";
  const auto run = [&](dialect out, const std::vector<std::string>& map) {
    auto options = test::options(feed_policy::tcp, out);
    for (const auto& m : map) REQUIRE(options.common.m_codes.add(m));
    const auto t = make_translator<M, M>(program::id_of<program::heidenhain::dialect>(), "m.h", options);
    string_sink written;
    const auto r = stream_text(*t, text, program::id_of<program::heidenhain::dialect>(), "m.h", out, written);
    REQUIRE(r.input.ok());
    return std::pair{t->result(), r.ok(*t) ? written.text : std::string()};
  };
  // M13 is spindle on clockwise with coolant on (a TNC's own function): M3 M8 in a G-code dialect.
  const auto [ok, iso] = run(program::id_of<program::iso::dialect>(), {});
  CHECK(ok.ok());
  CHECK(iso.find(" M3 M8\n") != std::string::npos);
  CHECK(iso.find("M13") == std::string::npos);
  CHECK(iso.find(" M5 M9\n") != std::string::npos);
  // --m-map names a state word by its M function: coolant on written as M50, coolant off dropped.
  const auto [mapped, siemens] = run(program::id_of<program::siemens::dialect>(), {"8=50", "9="});
  CHECK(mapped.ok());
  CHECK(siemens.find(" M3 M50\n") != std::string::npos);
  CHECK(siemens.find(" M5\n") != std::string::npos);
  CHECK(siemens.find("M9") == std::string::npos);
}

TEST_CASE("across dialects, a kept word whose effect a comment would lose is refused at its block") {
  using program::id_of;
  using program::read_result;
  using translate_detail::check_kept_words;
  using translate_detail::source_context;
  struct case_row {
    dialect from;
    std::string text, error;  // error empty: carried as a comment, harmless
  };
  const dialect iso = id_of<program::iso::dialect>();
  const dialect siemens = id_of<program::siemens::dialect>();
  const std::vector<case_row> rows{
      {iso, "G4 P1500\n", ""},  // a dwell is no kept word: state.dwell_s, translated (check_dwell)
      {iso, "G04 X1.5\n", ""},  // X of a G4 is its time, not a position
      {iso, "G43 H1\n", ""},  // read into the model: the writers translate or refuse it
      {siemens, "T=\"BALL\"\n", ""},  // read into the model (check_tool_name)
      {siemens, "D0\n", ""},  // read into the model as well (state.length_compensation): the writers translate it
      {iso, "G17 G40 G80 G90 G05.1 Q1\n", ""},
      {siemens, "G17 G40 G90 SOFT D1\n", ""},
      // Edge 2's length is not tool 1's own: H1 (TOOL CALL 1) would apply another length.
      {siemens, "D2\n",
       "t:1:1: error: D2: another cutting edge's length and radius than the first's (D1, the tool's own) of siemens "
       "is not translated into heidenhain yet (it would become a comment)"},
      {siemens, "N5 D12\n",
       "t:1:1: error: D12: another cutting edge's length and radius than the first's (D1, the tool's own) of "
       "siemens is not translated into heidenhain yet (it would become a comment)"},
  };
  for (const case_row& r : rows) {
    INFO(r.text);
    const read_result read = program::read(r.from, r.text, "t");
    REQUIRE(read.ok());
    translation out;
    source_context ctx;
    ctx.language = r.from;
    ctx.output = id_of<program::heidenhain::dialect>();
    ctx.out = &out;
    const bool ok = check_kept_words(read.parsed.blocks.at(0), ctx);
    CHECK(ok == r.error.empty());
    if (r.error.empty()) continue;
    REQUIRE(out.errors.size() == 1);
    CHECK(out.errors[0].to_string() == r.error);
    ctx.output = r.from;  // the same dialect writes it back as code
    CHECK(check_kept_words(read.parsed.blocks.at(0), ctx));
  }
  // TOOL CALL along X or Y: a tool axis the other dialects cannot say.
  const read_result h = program::heidenhain::read("TOOL CALL 5 Y S1000\n", "t");
  REQUIRE(h.ok());
  source_context ctx;
  ctx.language = id_of<program::heidenhain::dialect>();
  ctx.output = iso;
  CHECK_FALSE(check_kept_words(h.parsed.blocks.at(0), ctx));
}

TEST_CASE("across dialects, a tool called by name is refused where the target takes only numbers, unless mapped") {
  using program::id_of;
  using translate_detail::check_tool_name;
  using translate_detail::source_context;
  const dialect siemens = id_of<program::siemens::dialect>(), heidenhain = id_of<program::heidenhain::dialect>();
  const std::vector<dialect> numbers_only{id_of<program::iso::dialect>(), id_of<program::linuxcnc::dialect>(),
                                          id_of<program::haas::dialect>(), id_of<program::apt::dialect>()};
  const std::vector<std::pair<dialect, std::string>> sources{{siemens, "N10 T=\"BALL_D8\" M6\n"},
                                                             {heidenhain, "TOOL CALL \"BALL_D8\" Z S8000\n"}};
  tool_map map;
  REQUIRE(map.add("BALL_D8=7"));
  for (const auto& [from, text] : sources) {
    INFO(text);
    const program::read_result r = program::read(from, text, "t");
    REQUIRE(r.ok());
    const program::block& b = r.parsed.blocks.at(0);
    REQUIRE(b.tool_name == "BALL_D8");
    for (dialect to : {siemens, heidenhain}) {  // names go in as themselves
      source_context ctx;
      ctx.language = from, ctx.output = to;
      CHECK(check_tool_name(b, ctx));
    }
    for (dialect to : numbers_only) {
      translation out;
      source_context ctx;
      ctx.language = from, ctx.output = to, ctx.out = &out;
      CHECK_FALSE(check_tool_name(b, ctx));
      REQUIRE(out.errors.size() == 1);
      CHECK(out.errors[0].to_string() == "t:1:1: error: a tool called by name (\"BALL_D8\") in " +
                                             std::string(program::name(from)) + " has no number in " +
                                             std::string(program::name(to)) + "; --tool-map BALL_D8=N gives its number there");
      // Mapped, it is tool 7 from the source on: nothing left to refuse.
      std::optional<program::block> storage;
      const program::block& numbered = numbered_tools(b, map, storage);
      CHECK(numbered.tool == 7);
      CHECK_FALSE(numbered.tool_name);
    }
  }
  // A name the map does not give, or no map: the block as it is.
  std::optional<program::block> storage;
  program::block other;
  other.tool_name = "EM_D10";
  CHECK(&numbered_tools(other, map, storage) == &other);
  CHECK(&numbered_tools(other, tool_map{}, storage) == &other);
  // Entries: NAME=N, N whole, each name once; a name may hold a comma.
  tool_map bad;
  CHECK_FALSE(bad.add("BALL"));
  CHECK_FALSE(bad.add("=5"));
  CHECK_FALSE(bad.add("BALL=-1"));
  CHECK_FALSE(bad.add("BALL=1.5"));
  CHECK_FALSE(bad.add("BALL=123456789"));
  CHECK(bad.add("D10,ROUGH=12"));
  CHECK(bad.number_of("D10,ROUGH") == 12);
  CHECK_FALSE(bad.add("D10,ROUGH=13"));
}

TEST_CASE("across dialects, a dwell the target controller cannot take is refused at its block") {
  using program::id_of;
  using translate_detail::check_dwell;
  using translate_detail::source_context;
  struct case_row {
    dialect from, to;
    std::string text, error;  // error empty: written
  };
  const dialect iso = id_of<program::iso::dialect>(), linuxcnc = id_of<program::linuxcnc::dialect>();
  const dialect heidenhain = id_of<program::heidenhain::dialect>(), siemens = id_of<program::siemens::dialect>();
  const std::vector<case_row> rows{
      {iso, heidenhain, "G4 X3600.\n", ""},
      {iso, heidenhain, "G4 X3600.001\n",
       "t:1:1: error: a dwell of 3600.001 s is not one the heidenhain controller takes (0 to 3600 s in steps of 0.001 s)"},
      {linuxcnc, iso, "G4 P0.0005\n",
       "t:1:1: error: a dwell of 0.0005 s is not one the iso controller takes (0 to 9999.999 s in steps of 0.001 s)"},
      {linuxcnc, heidenhain, "G4 P0.0015\n",
       "t:1:1: error: a dwell of 0.0015 s is not one the heidenhain controller takes (0 to 3600 s in steps of 0.001 s)"},
      {linuxcnc, siemens, "G4 P0.0015\n", ""},
      {linuxcnc, id_of<program::haas::dialect>(), "G4 P0.0015\n",
       "t:1:1: error: a dwell of 0.0015 s is not one the haas controller takes (0 to 9999.999 s in steps of 0.001 s)"},
      {id_of<program::haas::dialect>(), heidenhain, "G04 P3600001\n",
       "t:1:1: error: a dwell of 3600.001 s is not one the heidenhain controller takes (0 to 3600 s in steps of 0.001 s)"},
      {siemens, iso, "G4 F12000\n",
       "t:1:1: error: a dwell of 12000 s is not one the iso controller takes (0 to 9999.999 s in steps of 0.001 s)"},
  };
  for (const case_row& r : rows) {
    INFO(r.text << " into " << program::name(r.to));
    const program::read_result read = program::read(r.from, r.text, "t");
    REQUIRE(read.ok());
    translation out;
    source_context ctx;
    ctx.language = r.from;
    ctx.output = r.to;
    ctx.out = &out;
    CHECK(check_dwell(read.parsed.blocks.at(0), ctx) == r.error.empty());
    if (r.error.empty()) continue;
    REQUIRE(out.errors.size() == 1);
    CHECK(out.errors[0].to_string() == r.error);
  }
}
